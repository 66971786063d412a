//! The gateway's modules: a block of words for each size and direction,
//! and Max_Module.

use super::super::checks::Checker;
use super::words_of;
use crate::description::gateway as raw;
use crate::diag::Diagnostic;
use crate::i18n::files;
use crate::ir::gateway::{Fewest, Module};
use crate::ir::profibus::MAX_WORDS_PER_IDENTIFIER;
use crate::ir::{Direction, Ident};
use std::collections::BTreeSet;
use toml::Spanned;

/// The modules, input first, each size ascending, Max_Module, and how each
/// total within the limits is made of as few of them as it can be.
pub(super) fn modules(
    cx: &mut Checker,
    m: &raw::Modules,
    limits: &[(Direction, u16)],
) -> (Vec<Module>, u8, Fewest) {
    let sizes = module_sizes(cx, &m.words);
    let fewest: Result<Vec<usize>, u16> = limits
        .iter()
        .map(|&(_, max_len)| fewest_modules(&sizes, max_len / 2))
        .collect();
    let most = match fewest {
        Ok(needed) => needed.iter().sum(),
        // No valid size at all was refused where each was written (E101).
        Err(_) if sizes.is_empty() => 0,
        Err(words) => {
            cx.push(
                Diagnostic::error("E147", format!("no set of these modules carries {}", words_of(words.into())))
                    .at(m.words.span())
                    .label("sizes that leave a total out")
                    .help("the master plugs modules until they equal the nodes' words, which may be any number up to the limit: offer 1 word, the smallest size"),
            );
            0
        }
    };
    let consistent = *m.consistent.get_ref();
    let modules: Vec<Module> = [Direction::In, Direction::Out]
        .into_iter()
        .flat_map(|direction| sizes.iter().map(move |&words| (direction, words)))
        .zip(1..=u8::MAX)
        .map(|((direction, words), reference)| {
            let (way, unit) = way_and_unit(direction, words);
            Module {
                reference,
                name: module_name(direction, words),
                direction,
                words,
                consistent,
                config: config_byte(direction, words, consistent),
                ident: Ident::of(&[way, &words.to_string(), unit]),
            }
        })
        .collect();
    layout_decisions(cx, &modules, most);
    let last_of = |direction| {
        let max_len = limits
            .iter()
            .find(|(d, _)| *d == direction)
            .map_or(0, |l| l.1);
        fewest_by_total(&sizes, usize::from(max_len / 2))
            .into_iter()
            .map(|f| f.map(|(_, size)| size).filter(|&size| size > 0))
            .collect()
    };
    let fewest = Fewest {
        input: last_of(Direction::In),
        output: last_of(Direction::Out),
    };
    (modules, u8::try_from(most).unwrap_or(u8::MAX), fewest)
}

/// The config identifiers and Max_Module are gsdc's rules where the
/// manual's module list is lost: listed in every header (the layouts carry
/// each number).
fn layout_decisions(cx: &mut Checker, modules: &[Module], most: usize) {
    if modules.is_empty() {
        return;
    }
    let bytes: Vec<String> = modules
        .iter()
        .map(|m| format!("{} 0x{:02X}", m.name, m.config))
        .collect();
    cx.layout(
        "profibus config identifiers",
        format!(
            "0x40 | 0x10 (input) or 0x20 (output) | (words - 1), 0x80 when consistent: {}",
            bytes.join("; ")
        ),
        files::GATEWAY_CONFIG_IDENTIFIERS_REASON,
    );
    cx.layout(
        "profibus Max_Module",
        most,
        files::GATEWAY_MAX_MODULE_REASON,
    );
}

/// The sizes, ascending, each 1..=16 words (one identifier byte) and once.
/// A word block's name in the GSD: `INPUT 1 word`, `OUTPUT 16 words`.
pub(crate) fn module_name(direction: Direction, words: u8) -> String {
    let (way, unit) = way_and_unit(direction, words);
    format!("{} {words} {unit}", way.to_ascii_uppercase())
}

fn way_and_unit(direction: Direction, words: u8) -> (&'static str, &'static str) {
    let way = match direction {
        Direction::In => "input",
        Direction::Out => "output",
    };
    (way, if words == 1 { "word" } else { "words" })
}

fn module_sizes(cx: &mut Checker, words: &Spanned<Vec<Spanned<i64>>>) -> Vec<u8> {
    if words.get_ref().is_empty() {
        cx.push(
            Diagnostic::error("E101", "no module size")
                .at(words.span())
                .label("empty")
                .help("offer at least one size, e.g. words = [1, 2, 4, 8, 16]"),
        );
    }
    let mut seen = BTreeSet::new();
    for size in words.get_ref() {
        let max = i64::from(MAX_WORDS_PER_IDENTIFIER);
        if let Some(value) = cx.spanned_in_range::<u8, _>(size, 1, max, "a module's words") {
            if !seen.insert(value) {
                cx.duplicate(format!("module size {value}"), size.span());
            }
        }
    }
    seen.into_iter().collect()
}

/// The most modules of `sizes` any total of 0..=`words` words needs when
/// made of as few as it can be; or the first total no set of them makes.
fn fewest_modules(sizes: &[u8], words: u16) -> Result<usize, u16> {
    fewest_by_total(sizes, usize::from(words))
        .iter()
        .enumerate()
        .try_fold(0, |most, (total, fewest)| match fewest {
            Some((n, _)) => Ok(most.max(*n)),
            None => Err(total as u16),
        })
}

/// For each total of 0..=`words` words: the fewest modules of `sizes` (words
/// each) that make it, and the largest size the last of them can be
/// (`(0, 0)` for no words); `None` for a total no set of them makes.
/// Lowering takes Max_Module from it, the datasheet the modules of its
/// example.
fn fewest_by_total(sizes: &[u8], words: usize) -> Vec<Option<(usize, u8)>> {
    let mut fewest: Vec<Option<(usize, u8)>> = vec![None; words + 1];
    fewest[0] = Some((0, 0));
    for total in 1..=words {
        fewest[total] = sizes
            .iter()
            .filter_map(|&size| {
                let (before, _) = fewest[total.checked_sub(usize::from(size))?]?;
                Some((before + 1, size))
            })
            .min_by_key(|&(n, size)| (n, std::cmp::Reverse(size)));
    }
    fewest
}

/// Config identifier bits (IEC 61158 / EN 50170): bit 7 consistency over
/// the whole length, bit 6 words, bits 5-4 direction (01 input, 10
/// output), bits 3-0 length - 1.
fn config_byte(direction: Direction, words: u8, consistent: bool) -> u8 {
    debug_assert!((1..=MAX_WORDS_PER_IDENTIFIER).contains(&words));
    let consistency = if consistent { 0x80 } else { 0 };
    let way = match direction {
        Direction::In => 0x10,
        Direction::Out => 0x20,
    };
    consistency | 0x40 | way | (words - 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn module_counts_are_the_fewest_for_the_worst_total() {
        // 122 words of powers of two: 111 = 6 x 16 + 8 + 4 + 2 + 1 needs 10.
        assert_eq!(fewest_modules(&[1, 2, 4, 8, 16], 122), Ok(10));
        // Every size: 7 x 16 and one more for the rest.
        let all: Vec<u8> = (1..=16).collect();
        assert_eq!(fewest_modules(&all, 122), Ok(8));
        assert_eq!(fewest_modules(&[2, 4], 8), Err(1));
        assert_eq!(fewest_modules(&[1], 0), Ok(0));
    }

    #[test]
    fn sizes_that_leave_a_total_out_make_none_of_it() {
        let fewest = fewest_by_total(&[2, 4], 8);
        assert_eq!(fewest[0], Some((0, 0)));
        assert_eq!(fewest[1], None);
        assert_eq!(fewest[6], Some((2, 4)));
        assert_eq!(fewest[8], Some((2, 4)));
    }

    #[test]
    fn config_bytes_say_words_direction_and_length() {
        assert_eq!(config_byte(Direction::In, 1, false), 0x50);
        assert_eq!(config_byte(Direction::In, 16, false), 0x5F);
        assert_eq!(config_byte(Direction::Out, 8, false), 0x67);
        assert_eq!(config_byte(Direction::Out, 16, true), 0xEF);
    }
}
