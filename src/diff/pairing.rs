//! Pairs the items of two lists by what identifies them, in linear time.

use std::collections::VecDeque;
use std::hash::Hash;

use foldhash::{HashMap, HashMapExt};

/// Two lists' items paired: those in both, those only in the old list,
/// those only in the new one, each in its list's order.
pub struct Pairing<'a, T> {
    pub both: Vec<(&'a T, &'a T)>,
    /// Pairs found by a second key (see [`Pairing::then`]): the first key
    /// changed between the files.
    pub rekeyed: Vec<(&'a T, &'a T)>,
    pub gone: Vec<&'a T>,
    pub added: Vec<&'a T>,
}

/// Pairs `old` and `new` by `key`. Items of one key pair in order (the
/// first with the first), so that duplicates pair as far as they go.
pub fn pair<'a, T, K: Eq + Hash>(
    old: &'a [T],
    new: &'a [T],
    key: impl Fn(&'a T) -> K,
) -> Pairing<'a, T> {
    let (both, gone, added) = by_key(old.iter().collect(), new.iter().collect(), key);
    Pairing {
        both,
        rekeyed: Vec::new(),
        gone,
        added,
    }
}

impl<'a, T> Pairing<'a, T> {
    /// Pairs what is left by a second key (an element's ID after its ident
    /// number, a parameter's name after its place): the pairs found go to
    /// `rekeyed`.
    pub fn then<K: Eq + Hash>(mut self, key: impl Fn(&'a T) -> Option<K>) -> Self {
        let keyed = |items: Vec<&'a T>| -> (Vec<&'a T>, Vec<&'a T>) {
            items.into_iter().partition(|item| key(item).is_some())
        };
        let (old_keyed, old_rest) = keyed(std::mem::take(&mut self.gone));
        let (new_keyed, new_rest) = keyed(std::mem::take(&mut self.added));
        let (both, gone, added) = by_key(old_keyed, new_keyed, key);
        self.rekeyed.extend(both);
        self.gone = merge_in_order(gone, old_rest);
        self.added = merge_in_order(added, new_rest);
        self
    }
}

type Split<'a, T> = (Vec<(&'a T, &'a T)>, Vec<&'a T>, Vec<&'a T>);

fn by_key<'a, T, K: Eq + Hash>(
    old: Vec<&'a T>,
    new: Vec<&'a T>,
    key: impl Fn(&'a T) -> K,
) -> Split<'a, T> {
    let mut waiting: HashMap<K, VecDeque<usize>> = HashMap::with_capacity(new.len());
    for (i, item) in new.iter().enumerate() {
        waiting.entry(key(item)).or_default().push_back(i);
    }
    let mut taken = vec![false; new.len()];
    let mut both = Vec::new();
    let mut gone = Vec::new();
    for item in old {
        match waiting.get_mut(&key(item)).and_then(VecDeque::pop_front) {
            Some(i) => {
                taken[i] = true;
                both.push((item, new[i]));
            }
            None => gone.push(item),
        }
    }
    let added = new
        .into_iter()
        .zip(taken)
        .filter_map(|(item, taken)| (!taken).then_some(item))
        .collect();
    (both, gone, added)
}

/// Two lists of references into one slice, as one in the slice's order.
fn merge_in_order<'a, T>(mut a: Vec<&'a T>, b: Vec<&'a T>) -> Vec<&'a T> {
    a.extend(b);
    a.sort_by_key(|item| *item as *const T as usize);
    a
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pairs_by_key_then_by_a_second_key() {
        let old = [(1, "a"), (2, "b"), (3, "c"), (3, "d")];
        let new = [(3, "c"), (1, "a"), (9, "b"), (4, "e")];
        let p = pair(&old, &new, |x| x.0).then(|x| Some(x.1));
        let both: Vec<_> = p.both.iter().map(|(a, b)| (a.1, b.1)).collect();
        assert_eq!(both, [("a", "a"), ("c", "c")]);
        let rekeyed: Vec<_> = p.rekeyed.iter().map(|(a, b)| (a.0, b.0)).collect();
        assert_eq!(rekeyed, [(2, 9)]);
        assert_eq!(p.gone, [&(3, "d")]);
        assert_eq!(p.added, [&(4, "e")]);
    }
}
