//! Identifiers for generated code, decided once by lowering.
//!
//! An [`Ident`] is a list of lower-case ASCII words; each target language
//! spells it in its own case (`PkwPzd12`, `PKW_PZD12`, `pkw_pzd12`).
//! Lowering makes every identifier unique within its scope in every
//! spelling at once, so an emitter only formats and never renames.

use std::collections::BTreeSet;

/// An identifier as words: lower-case ASCII letters and digits, never
/// empty, the first word never starting with a digit.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Ident(Vec<String>);

impl Ident {
    /// Words of fixed names (`["pkw", "pzd12"]`), as lowering writes them.
    /// The caller keeps to the rules above; tested where it is used.
    pub(crate) fn of(words: &[&str]) -> Self {
        Ident(words.iter().map(|w| w.to_ascii_lowercase()).collect())
    }

    /// The identifier a text spells: its runs of ASCII letters and digits,
    /// leaving out what is in parentheses (units and remarks, as in
    /// `Output frequency (0.01 Hz)`). `fallback` stands in front when the
    /// text has no such word or starts with a digit: `1st speed` with
    /// fallback `value` is `Value1stSpeed`.
    pub(crate) fn from_text(text: &str, fallback: &str) -> Self {
        let mut words = text_words(text);
        if words
            .first()
            .is_none_or(|w| w.starts_with(|c: char| c.is_ascii_digit()))
        {
            words.insert(0, fallback.to_ascii_lowercase());
        }
        let ident = Ident(words);
        // `Self` is the one keyword a capitalised word can spell.
        if ident.camel() == "Self" {
            return Ident::of(&["self", fallback]);
        }
        ident
    }

    /// This identifier with `tag` (a bit or value number, a counter) as a
    /// word of its own at the end.
    pub(crate) fn tagged(&self, tag: impl std::fmt::Display) -> Self {
        let mut words = self.0.clone();
        words.push(tag.to_string().to_ascii_lowercase());
        Ident(words)
    }

    pub fn words(&self) -> &[String] {
        &self.0
    }

    /// `ForwardRunning`: Rust types and enum variants.
    pub fn camel(&self) -> String {
        let mut camel = String::with_capacity(self.0.iter().map(String::len).sum());
        for word in &self.0 {
            // Words are ASCII and never empty: one byte is one letter.
            let (head, tail) = word.split_at(1);
            camel.push(char::from(head.as_bytes()[0].to_ascii_uppercase()));
            camel.push_str(tail);
        }
        camel
    }

    /// `FORWARD_RUNNING`: constants, C macros and enumerators.
    pub fn upper_snake(&self) -> String {
        self.0.join("_").to_ascii_uppercase()
    }

    /// `forward_running`: Rust modules and fields, C functions.
    pub fn snake(&self) -> String {
        self.0.join("_")
    }
}

/// An identifier travels (into a template, through a filter) as its
/// `snake_case` spelling, from which every other spelling follows.
impl serde::Serialize for Ident {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(&self.snake())
    }
}

impl<'de> serde::Deserialize<'de> for Ident {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let snake = String::deserialize(deserializer)?;
        Ok(Ident(snake.split('_').map(str::to_string).collect()))
    }
}

fn text_words(text: &str) -> Vec<String> {
    let mut depth = 0usize;
    let outside: String = text
        .chars()
        .map(|c| {
            match c {
                '(' => depth += 1,
                ')' => depth = depth.saturating_sub(1),
                _ if depth == 0 && c.is_ascii_alphanumeric() => return c.to_ascii_lowercase(),
                _ => {}
            }
            ' '
        })
        .collect();
    outside.split_whitespace().map(str::to_string).collect()
}

/// The identifiers given in one scope, in every spelling.
#[derive(Default)]
pub(crate) struct Scope {
    camel: BTreeSet<String>,
    snake: BTreeSet<String>,
}

impl Scope {
    /// `ident` if it is new in every spelling; else `ident` tagged with
    /// `tag`, then with a counter too, until it is.
    pub(crate) fn unique(&mut self, ident: Ident, tag: impl std::fmt::Display) -> Ident {
        let tag = tag.to_string();
        let mut candidate = ident.clone();
        let mut n = 1;
        // Each spelling made once per candidate: a large file's diagnosis
        // names thousands of constants.
        loop {
            let (camel, snake) = (candidate.camel(), candidate.snake());
            if !self.camel.contains(&camel) && !self.snake.contains(&snake) {
                self.camel.insert(camel);
                self.snake.insert(snake);
                return candidate;
            }
            candidate = match n {
                1 => ident.tagged(&tag),
                _ => ident.tagged(&tag).tagged(n),
            };
            n += 1;
        }
    }

    /// Takes `ident` for a name the scope's owner writes itself.
    pub(crate) fn reserve(&mut self, ident: &Ident) {
        self.camel.insert(ident.camel());
        self.snake.insert(ident.snake());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camel(text: &str, fallback: &str) -> String {
        Ident::from_text(text, fallback).camel()
    }

    #[test]
    fn names_from_manual_texts() {
        assert_eq!(camel("Forward running", "v"), "ForwardRunning");
        assert_eq!(camel("PID feedback", "v"), "PidFeedback");
        assert_eq!(camel("Output frequency (0.01 Hz)", "v"), "OutputFrequency");
        assert_eq!(camel("DI1 to DI4 state", "v"), "Di1ToDi4State");
        assert_eq!(
            camel("Encoder/PG card abnormal", "v"),
            "EncoderPgCardAbnormal"
        );
        assert_eq!(camel("1st speed", "value"), "Value1stSpeed");
        assert_eq!(camel("正转运行", "value"), "Value");
        assert_eq!(camel("self", "value"), "SelfValue");
        let motor = Ident::from_text("Motor number", "bit");
        assert_eq!(motor.upper_snake(), "MOTOR_NUMBER");
        assert_eq!(motor.snake(), "motor_number");
        assert_eq!(
            Ident::from_text("5 V supply", "bit").upper_snake(),
            "BIT_5_V_SUPPLY"
        );
    }

    #[test]
    fn names_are_unique_in_their_scope_in_every_spelling() {
        let mut scope = Scope::default();
        let stop = Ident::of(&["stop"]);
        assert_eq!(
            scope.unique(Ident::of(&["bit", "field"]), 3).camel(),
            "BitField"
        );
        assert_eq!(
            scope.unique(Ident::of(&["bitfield"]), 3).camel(),
            "Bitfield"
        );
        // `BitField` and `bit_field` taken: the snake-case spelling tells them apart.
        assert_eq!(
            scope.unique(Ident::of(&["bit", "field"]), 3).camel(),
            "BitField3"
        );
        assert_eq!(scope.unique(stop.clone(), 3).camel(), "Stop");
        assert_eq!(scope.unique(stop.clone(), 3).upper_snake(), "STOP_3");
        assert_eq!(scope.unique(stop, 3).upper_snake(), "STOP_3_2");
        // `a1b` and `a 1b` are one camel-case name, so the second is tagged.
        let mut scope = Scope::default();
        assert_eq!(scope.unique(Ident::of(&["a1b"]), 7).camel(), "A1b");
        assert_eq!(scope.unique(Ident::of(&["a", "1b"]), 7).camel(), "A1b7");
    }
}
