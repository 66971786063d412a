//! No import circles in src/: for every two sibling modules (children of
//! one parent), at most one uses the other, directly or through other
//! siblings. A module may use its parent's items and its parent its
//! children's; what counts is every `crate::`, `super::` and `self::` path
//! outside comments and unit tests, resolved to the module it names.

use crate::support;
use std::collections::{BTreeMap, BTreeSet};

type Module = Vec<String>;

/// Every module of src/ by its path (`["gsd", "model"]`), with its text.
fn modules() -> BTreeMap<Module, String> {
    let root = support::checkout("src");
    let mut found = BTreeMap::new();
    let mut dirs = vec![root.clone()];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                dirs.push(path);
                continue;
            }
            if path.extension().is_none_or(|e| e != "rs") {
                continue;
            }
            let relative = path.strip_prefix(&root).unwrap().with_extension("");
            let mut module: Module = relative
                .iter()
                .map(|p| p.to_string_lossy().into_owned())
                .collect();
            if matches!(
                module.last().map(String::as_str),
                Some("mod" | "lib" | "main")
            ) {
                module.pop();
            }
            found.insert(
                module,
                without_comments_and_tests(&std::fs::read_to_string(&path).unwrap()),
            );
        }
    }
    found
}

fn without_comments_and_tests(text: &str) -> String {
    let code = text.split("#[cfg(test)]\nmod tests").next().unwrap();
    code.lines()
        .map(|line| line.split("//").next().unwrap())
        .collect::<Vec<_>>()
        .join("\n")
}

/// The paths a module's text names: `crate::a::b`, `super::c`, and those
/// inside `use crate::x::{a, b::c}` groups.
fn paths(text: &str) -> Vec<String> {
    let mut found = Vec::new();
    let words: Vec<char> = text.chars().collect();
    let starts = ["crate::", "super::", "self::"];
    let mut i = 0;
    while i < words.len() {
        let rest: String = words[i..words.len().min(i + 7)].iter().collect();
        let boundary = i == 0 || !(words[i - 1].is_alphanumeric() || words[i - 1] == '_');
        if boundary && starts.iter().any(|s| rest.starts_with(s)) {
            let end = (i..words.len())
                .find(|&j| !(words[j].is_alphanumeric() || words[j] == '_' || words[j] == ':'))
                .unwrap_or(words.len());
            let path: String = words[i..end].iter().collect();
            let path = path.trim_end_matches(':').to_string();
            if words.get(end) == Some(&'{') {
                let close = (end..words.len()).find(|&j| words[j] == '}').unwrap_or(end);
                let group: String = words[end + 1..close].iter().collect();
                for item in group.split(',') {
                    let first = item.trim().split("::").next().unwrap_or("").trim();
                    if !first.is_empty() && first != "self" {
                        found.push(format!("{path}::{first}"));
                    }
                }
            }
            found.push(path);
            i = end;
        } else {
            i += 1;
        }
    }
    found
}

/// The module a path from `from` names: the longest module its words reach.
fn resolve(modules: &BTreeMap<Module, String>, from: &Module, path: &str) -> Option<Module> {
    let mut words = path.split("::").peekable();
    let mut full: Module = match *words.peek()? {
        "crate" => Vec::new(),
        _ => from.clone(),
    };
    for word in words {
        match word {
            "crate" | "self" => {}
            "super" => {
                full.pop();
            }
            other => full.push(other.to_string()),
        }
    }
    (0..=full.len())
        .rev()
        .map(|n| full[..n].to_vec())
        .find(|m| modules.contains_key(m))
}

/// `a` uses `b`, lifted to the children of their nearest common parent;
/// none between a module and its ancestor.
fn sibling_edge(a: &Module, b: &Module) -> Option<(Module, Module)> {
    let common = a.iter().zip(b).take_while(|(x, y)| x == y).count();
    (common < a.len() && common < b.len()).then(|| (a[..=common].to_vec(), b[..=common].to_vec()))
}

/// The modules `from` reaches through `edges`.
fn reached(edges: &BTreeMap<Module, BTreeSet<Module>>, from: &Module) -> BTreeSet<Module> {
    let mut seen = BTreeSet::new();
    let mut todo = vec![from.clone()];
    while let Some(m) = todo.pop() {
        for next in edges.get(&m).into_iter().flatten() {
            if seen.insert(next.clone()) {
                todo.push(next.clone());
            }
        }
    }
    seen
}

fn sibling_edges(modules: &BTreeMap<Module, String>) -> BTreeMap<Module, BTreeSet<Module>> {
    let mut edges: BTreeMap<Module, BTreeSet<Module>> = BTreeMap::new();
    for (module, text) in modules {
        for path in paths(text) {
            let Some(target) = resolve(modules, module, &path) else {
                continue;
            };
            if let Some((a, b)) = sibling_edge(module, &target) {
                edges.entry(a).or_default().insert(b);
            }
        }
    }
    edges
}

#[test]
fn no_two_sibling_modules_use_each_other() {
    let modules = modules();
    assert!(modules.contains_key(&vec!["gsd".to_string(), "model".to_string()]));
    let edges = sibling_edges(&modules);
    assert!(
        edges.values().map(BTreeSet::len).sum::<usize>() > 50,
        "{edges:?}"
    );
    let circles: Vec<String> = edges
        .keys()
        .filter(|m| reached(&edges, m).contains(*m))
        .map(|m| m.join("::"))
        .collect();
    assert!(
        circles.is_empty(),
        "modules in an import circle: {circles:?}"
    );
}

/// The check sees a circle where there is one.
#[test]
fn a_circle_between_siblings_is_found() {
    let mut modules = BTreeMap::new();
    let m = |path: &str| -> Module { path.split("::").map(str::to_string).collect() };
    modules.insert(Vec::new(), String::new());
    modules.insert(m("a"), "use crate::b::{x, y::z};".to_string());
    modules.insert(m("b"), "fn f() { super::a::g() }".to_string());
    modules.insert(m("b::y"), "use super::super::a; // crate::c".to_string());
    let edges = sibling_edges(&modules);
    assert!(reached(&edges, &m("a")).contains(&m("a")));
    assert_eq!(edges[&m("a")], BTreeSet::from([m("b")]));
    let without = without_comments_and_tests(
        "use crate::c; // crate::d\n#[cfg(test)]\nmod tests { use crate::e; }",
    );
    assert_eq!(paths(&without), ["crate::c"]);
}
