//! A layout's sentences, language-neutral: text and references to other
//! items of the layout, which each language writes its own way (a Rust
//! intra-doc link, a C name), and the few values every layout spells.

use crate::ir::Ident;
use serde::{Deserialize, Serialize};

/// Where a name lives. Rust gives each part of a layout a module of its
/// own; C has one namespace, so a part's names carry its name after the
/// layout's prefix.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub(crate) enum Scope {
    /// The layout's own names.
    Root,
    /// A part both languages name alike: Rust's module, C's infix
    /// (`control_word`, `pzd_out`, `diagnosis`).
    Part(Ident),
    /// The gateway's part: a module in Rust, the root in C, where its
    /// names were first published.
    Gateway,
    /// The gateway's diagnosis: in the gateway's module in Rust, under the
    /// infix `diag` in C.
    GatewayDiagnosis,
}

impl Scope {
    /// The part of a group of words, fields or mappings.
    pub(crate) fn part(name: &str) -> Self {
        Scope::Part(Ident::of(&name.split('_').collect::<Vec<_>>()))
    }

    /// The Rust module of the scope; `None` at the root.
    pub(crate) fn module(&self) -> Option<String> {
        match self {
            Scope::Root => None,
            Scope::Part(name) => Some(name.snake()),
            Scope::Gateway | Scope::GatewayDiagnosis => Some("gateway".into()),
        }
    }

    /// What C writes between the prefix and a name of the scope.
    pub(crate) fn infix(&self) -> Option<String> {
        match self {
            Scope::Root | Scope::Gateway => None,
            Scope::Part(name) => Some(name.snake()),
            Scope::GatewayDiagnosis => Some("diag".into()),
        }
    }
}

/// Another item of the layout, named in a sentence.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub(crate) enum Ref {
    /// A constant: Rust's `const`, C's macro.
    Const(Scope, Ident),
    /// Every name of a part: Rust's module, C's names of its infix.
    Part(Scope),
    /// A set of values: Rust's enum, C's macros of the set.
    Values(Scope, Ident),
    /// An item of the PKW channel's codec, which the support code holds.
    Pkw(PkwItem),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub(crate) enum PkwItem {
    Request,
    RequestDecode,
    Response,
    ResponseEncode,
}

#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub(crate) enum Part {
    Text(String),
    Ref(Ref),
}

/// A doc comment: one paragraph of text and references, and where it
/// stands, which is where a Rust link starts from.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub(crate) struct Doc {
    pub at: Scope,
    pub parts: Vec<Part>,
}

impl Doc {
    /// An empty sentence standing in `at`, to be built with
    /// [`Doc::text`] and [`Doc::link`].
    pub(crate) fn at(at: Scope) -> Self {
        Doc {
            at,
            parts: Vec::new(),
        }
    }

    /// A sentence without references.
    pub(crate) fn plain(text: impl Into<String>) -> Self {
        Doc::at(Scope::Root).text(text)
    }

    pub(crate) fn text(mut self, text: impl Into<String>) -> Self {
        self.parts.push(Part::Text(text.into()));
        self
    }

    pub(crate) fn link(mut self, to: Ref) -> Self {
        self.parts.push(Part::Ref(to));
        self
    }

    /// The text with each reference written by `name`.
    pub(crate) fn render(&self, name: impl Fn(&Ref) -> String) -> String {
        self.parts
            .iter()
            .map(|part| match part {
                Part::Text(text) => text.clone(),
                Part::Ref(to) => name(to),
            })
            .collect()
    }
}

/// A number or a text as the layouts write it: a parameter address or an
/// ident number in hex, with its digits, anything else in decimal.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub(crate) enum Val {
    Dec(u64),
    /// The number and its digits (2, 4 or 8).
    Hex(u64, usize),
    Text(String),
}

impl Val {
    pub(crate) fn hex_u8(value: u8) -> Self {
        Val::Hex(value.into(), 2)
    }

    pub(crate) fn hex_u16(value: u16) -> Self {
        Val::Hex(value.into(), 4)
    }

    pub(crate) fn hex_u32(value: u32) -> Self {
        Val::Hex(value.into(), 8)
    }
}
