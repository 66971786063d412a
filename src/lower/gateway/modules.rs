//! The gateway's modules: a block of words for each size and direction,
//! and Max_Module.

use super::super::checks::Checker;
use super::words_of;
use crate::description::gateway as raw;
use crate::diag::Diagnostic;
use crate::ir::gateway::{config_byte, fewest_by_total, Module};
use crate::ir::profibus::MAX_WORDS_PER_IDENTIFIER;
use crate::ir::{Direction, Ident};
use std::collections::BTreeSet;
use toml::Spanned;

/// The modules, input first, each size ascending, and Max_Module.
pub(super) fn modules(
    cx: &mut Checker,
    m: &raw::Modules,
    limits: &[(Direction, u16)],
) -> (Vec<Module>, u8) {
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
    let modules = [Direction::In, Direction::Out]
        .into_iter()
        .flat_map(|direction| sizes.iter().map(move |&words| (direction, words)))
        .zip(1..=u8::MAX)
        .map(|((direction, words), reference)| {
            let way = match direction {
                Direction::In => "input",
                Direction::Out => "output",
            };
            let unit = if words == 1 { "word" } else { "words" };
            Module {
                reference,
                name: format!("{} {words} {unit}", way.to_ascii_uppercase()),
                direction,
                words,
                consistent,
                config: config_byte(direction, words, consistent),
                ident: Ident::of(&[way, &words.to_string(), unit]),
            }
        })
        .collect();
    (modules, u8::try_from(most).unwrap_or(u8::MAX))
}

/// The sizes, ascending, each 1..=16 words (one identifier byte) and once.
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
}
