//! `[profinet.pzd_names]`: what the GSDML's data items call the PZD words
//! of the modules of PZD words, where not gsdc's `PZD1`, `PZD2`...

use super::super::checks::Checker;
use crate::description as raw;
use crate::diag::Diagnostic;
use crate::ir::{Direction, Telegram, Text};
use toml::Spanned;

/// The names of the PZD words each way, from the first the telegram does
/// not name already (its control or status word): empty for gsdc's.
#[derive(Debug, Default)]
pub struct PzdNames {
    output: Vec<Text>,
    input: Vec<Text>,
}

impl PzdNames {
    /// The name of PZD word `n` (from 1) one way, where the description
    /// gives one.
    pub fn of(&self, telegram: &Telegram, direction: Direction, n: u8) -> Option<&Text> {
        let names = match direction {
            Direction::Out => &self.output,
            Direction::In => &self.input,
        };
        let first_named = 1 + u8::from(telegram.word(direction).is_some());
        names.get(usize::from(n.checked_sub(first_named)?))
    }
}

/// The names, checked: one per PZD word of the telegram's most, after the
/// control or status word where the telegram names it (E193). None when
/// a list is wrong.
pub fn lower(
    cx: &mut Checker,
    given: Option<&Spanned<raw::PzdNames>>,
    telegram: &Telegram,
) -> Option<PzdNames> {
    let Some(given) = given else {
        return Some(PzdNames::default());
    };
    let given = given.get_ref();
    let output = names(cx, given.output.as_ref(), telegram, Direction::Out);
    let input = names(cx, given.input.as_ref(), telegram, Direction::In);
    Some(PzdNames {
        output: output?,
        input: input?,
    })
}

fn names(
    cx: &mut Checker,
    given: Option<&Spanned<Vec<Spanned<raw::Text>>>>,
    telegram: &Telegram,
    direction: Direction,
) -> Option<Vec<Text>> {
    let Some(given) = given else {
        return Some(Vec::new());
    };
    let (key, word, way) = match direction {
        Direction::Out => ("output", "control word", "the master sends"),
        Direction::In => ("input", "status word", "the drive sends"),
    };
    let named = telegram.word(direction).is_some();
    let wanted = usize::from(telegram.pzd_words) - usize::from(named);
    if given.get_ref().len() != wanted {
        let after = if named {
            format!(", after the {word} [telegram] names")
        } else {
            String::new()
        };
        cx.push(
            Diagnostic::error(
                "E193",
                format!("{} PZD names for {wanted} PZD words", given.get_ref().len()),
            )
            .at(given.span())
            .label(format!("one per PZD word{after}"))
            .help(format!(
                "give {wanted} names, one for each PZD word {way} in order{after}"
            )),
        );
        return None;
    }
    let what = format!("profinet.pzd_names.{key}");
    Some(
        given
            .get_ref()
            .iter()
            .map(|name| cx.text(name, None, &what))
            .collect(),
    )
}
