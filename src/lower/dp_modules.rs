//! `[[profibus.modules]]`: modules in the vendor's own layout. Each
//! module's config bytes follow from what its identifiers carry (the
//! general or special format of IEC 61158-6-3, `crate::gsd::config`); its
//! telegram, for the layouts, the datasheet and the decoder, is the PKW
//! channel (or not) and as many PZD words each way, when its data is that.

use super::checks::{Checker, GSD_NAME_LEN};
use super::ppo::{config_bytes, ppo_layout};
use crate::description::dp as raw;
use crate::diag::Diagnostic;
use crate::gsd::config::{
    Direction, Identifier, Length, MAX_GENERAL_COUNT, MAX_SPECIAL_COUNT, MAX_VENDOR_BYTES,
};
use crate::ir::profibus::DpModule;
use crate::ir::telegram::PKW_WORDS;
use crate::ir::{Ident, Layout, PkwKind, Scope, Telegram};
use std::collections::BTreeSet;
use toml::Spanned;

/// The modules of `[[profibus.modules]]`, each with its config bytes.
pub(super) fn lower(
    cx: &mut Checker,
    modules: &Spanned<Vec<raw::DpModule>>,
    ppo5_pzd_words: u8,
    telegram: &Telegram,
) -> Vec<DpModule> {
    if modules.get_ref().is_empty() {
        cx.push(
            Diagnostic::error("E101", "profibus.modules is empty")
                .at(modules.span())
                .label("no module")
                .help("give each module the master may plug, with its name and data"),
        );
    }
    let mut idents = Scope::default();
    let (mut names, mut references) = (BTreeSet::new(), BTreeSet::new());
    let mut lowered = Vec::new();
    for m in modules.get_ref() {
        if !names.insert(m.name.get_ref().clone()) {
            cx.duplicate(format!("module \"{}\"", m.name.get_ref()), m.name.span());
        }
        if let Some(r) = &m.reference {
            if !references.insert(*r.get_ref()) {
                cx.duplicate(format!("module reference {}", r.get_ref()), r.span());
            }
        }
        if let Some(module) = module(cx, m, ppo5_pzd_words, telegram, &mut idents) {
            lowered.push(module);
        }
    }
    lowered
}

fn module(
    cx: &mut Checker,
    m: &raw::DpModule,
    ppo5_pzd_words: u8,
    telegram: &Telegram,
    idents: &mut Scope,
) -> Option<DpModule> {
    let name = cx.gsd_name(&m.name, GSD_NAME_LEN, "module name");
    let info = cx.optional_gsd_string(m.info.as_ref(), "Info_Text", "module info");
    let (ppo, config, layout) = match (&m.ppo, &m.data) {
        (Some(ppo), None) => {
            let (number, layout) = ppo_type(cx, ppo, ppo5_pzd_words)?;
            (Some(number), config_bytes(layout), Some(layout))
        }
        (None, Some(data)) if data.get_ref().is_empty() => {
            cx.push(
                Diagnostic::error(
                    "E117",
                    format!("module \"{}\" has no data", m.name.get_ref()),
                )
                .at(data.span())
                .label("no identifier")
                .help("a module carries one config identifier at least; `{}` is an empty place"),
            );
            return None;
        }
        (None, Some(data)) => {
            let ids: Vec<(Identifier, bool)> = data
                .get_ref()
                .iter()
                .map(|id| identifier(cx, id))
                .collect::<Option<_>>()?;
            let config: Vec<u8> = ids.iter().flat_map(|(id, _)| id.bytes()).collect();
            (None, config, layout(&ids))
        }
        _ => {
            cx.push(
                Diagnostic::error("E170", format!("module \"{}\" does not say its data once", m.name.get_ref()))
                    .at(m.name.span())
                    .label("give `ppo` or `data`")
                    .help("a module is a PPO type (`ppo = \"PPO1\"`) or a list of config identifiers (`data = [{ pkw = true }, { words = 2 }]`), not both"),
            );
            return None;
        }
    };
    let pkw = layout.is_some_and(|l| l.pkw)
        || m.data
            .as_ref()
            .is_some_and(|d| d.get_ref().iter().any(|i| i.get_ref().pkw));
    if pkw && telegram.pkw == PkwKind::None {
        cx.push(
            Diagnostic::error(
                "E121",
                format!("module \"{name}\" carries a PKW channel, but the telegram has none"),
            )
            .at(m.name.span())
            .label("has PKW")
            .help("set telegram.pkw to the channel's kind, or drop the module's PKW"),
        );
    }
    if let Some(l) = layout.filter(|l| l.pzd_words > telegram.pzd_words) {
        cx.push(
            Diagnostic::error(
                "E113",
                format!(
                    "module \"{name}\" has {} PZD words; the telegram has {}",
                    l.pzd_words, telegram.pzd_words
                ),
            )
            .at(m.name.span())
            .label("longer than the telegram")
            .help("raise telegram.pzd_words or shorten the module"),
        );
    }
    let io = crate::gsd::io_lengths(&config).unwrap_or_default();
    let ident = idents.unique(Ident::from_text(&format!("dp {name}"), "dp"), "module");
    Some(DpModule {
        ppo,
        name,
        reference: m.reference.as_ref().map(|r| *r.get_ref()),
        info,
        layout,
        config,
        input_len: u16::try_from(io.input).unwrap_or(u16::MAX),
        output_len: u16::try_from(io.output).unwrap_or(u16::MAX),
        ident,
        // `dp_safety::lower` gives a PROFIsafe module its block.
        safety: None,
    })
}

/// `PPO1`..`PPO5` and their layouts.
fn ppo_type(cx: &mut Checker, ppo: &Spanned<String>, ppo5_pzd_words: u8) -> Option<(u8, Layout)> {
    let found = (1..=5).find(|n| *ppo.get_ref() == format!("PPO{n}"));
    let Some(number) = found else {
        cx.push(
            Diagnostic::error("E104", format!("`{}` is not a PPO type", ppo.get_ref()))
                .at(ppo.span())
                .label("unknown PPO type")
                .help("PPO types are PPO1, PPO2, PPO3, PPO4 and PPO5; another layout is `data = [...]`"),
        );
        return None;
    };
    Some((number, ppo_layout(number, ppo5_pzd_words)?))
}

/// One identifier as the description writes it, and whether it is the PKW
/// channel; E171 for one that says more than one identifier can.
fn identifier(cx: &mut Checker, id: &Spanned<raw::Identifier>) -> Option<(Identifier, bool)> {
    let i = id.get_ref();
    let consistent = i.consistent.as_ref().is_none_or(|c| *c.get_ref());
    let both = [(&i.words, true), (&i.bytes, false)];
    let one_way = |out: bool| -> [(&Option<Spanned<u8>>, bool); 2] {
        match out {
            true => [(&i.words_out, true), (&i.bytes_out, false)],
            false => [(&i.words_in, true), (&i.bytes_in, false)],
        }
    };
    let (both, output, input) = (given(both), given(one_way(true)), given(one_way(false)));
    let wrong = |cx: &mut Checker, why: &str| {
        cx.push(
            Diagnostic::error("E171", format!("not a config identifier: {why}"))
                .at(id.span())
                .label("one identifier")
                .help("an identifier is `{ pkw = true }`, `{ words = n }` (or bytes) each way, `{ words_out = n }` or `{ words_in = n }` one way, both of those together or with `vendor = [...]` (the special format), or `{}`, an empty place"),
        );
        None
    };
    let one_way = !output.is_empty() || !input.is_empty();
    if both.len() > 1 || output.len() > 1 || input.len() > 1 || (!both.is_empty() && one_way) {
        return wrong(cx, "more than one length for one way");
    }
    if i.pkw {
        if !(both.is_empty()
            && output.is_empty()
            && input.is_empty()
            && i.vendor.is_none()
            && i.consistent.is_none())
        {
            return wrong(
                cx,
                "the PKW channel is 4 consistent words each way, nothing else",
            );
        }
        let data = Length {
            words: true,
            count: PKW_WORDS,
            consistent: true,
        };
        return Some((
            Identifier::General {
                direction: Direction::Both,
                data,
            },
            true,
        ));
    }
    let length = |cx: &mut Checker, (v, words): (&Spanned<u8>, bool), most: u8| -> Option<Length> {
        let count = cx.spanned_in_range(v, 1, i64::from(most), "the length of an identifier")?;
        Some(Length {
            words,
            count,
            consistent,
        })
    };
    let special = i.vendor.is_some() || (!output.is_empty() && !input.is_empty());
    if !special {
        let (direction, data) = match (both.first(), output.first(), input.first()) {
            (Some(&d), None, None) => (Direction::Both, d),
            (None, Some(&d), None) => (Direction::Output, d),
            (None, None, Some(&d)) => (Direction::Input, d),
            _ => {
                if i.consistent.is_some() {
                    return wrong(cx, "an empty place has no consistency");
                }
                return Some((
                    Identifier::Special {
                        output: None,
                        input: None,
                        vendor: Vec::new(),
                    },
                    false,
                ));
            }
        };
        let data = length(cx, data, MAX_GENERAL_COUNT)?;
        return Some((Identifier::General { direction, data }, false));
    }
    if !both.is_empty() {
        return wrong(
            cx,
            "the special format says each way on its own: words_out and words_in",
        );
    }
    let vendor: Vec<u8> = i
        .vendor
        .as_ref()
        .map(|v| v.get_ref().iter().map(|b| *b.get_ref()).collect())
        .unwrap_or_default();
    if vendor.len() > MAX_VENDOR_BYTES {
        return wrong(
            cx,
            "a special identifier carries at most 14 manufacturer bytes",
        );
    }
    let output = match output.first() {
        Some(&d) => Some(length(cx, d, MAX_SPECIAL_COUNT)?),
        None => None,
    };
    let input = match input.first() {
        Some(&d) => Some(length(cx, d, MAX_SPECIAL_COUNT)?),
        None => None,
    };
    Some((
        Identifier::Special {
            output,
            input,
            vendor,
        },
        false,
    ))
}

/// The lengths of a pair (words, bytes) that are given.
fn given(pair: [(&Option<Spanned<u8>>, bool); 2]) -> Vec<(&Spanned<u8>, bool)> {
    pair.into_iter()
        .filter_map(|(v, words)| Some((v.as_ref()?, words)))
        .collect()
}

/// The telegram of a module's identifiers: the PKW channel first or not,
/// then words whose sum is the same each way; `None` for data of another
/// shape (bytes, manufacturer bytes, a PKW channel after data, words one
/// way only).
fn layout(ids: &[(Identifier, bool)]) -> Option<Layout> {
    let empty = |id: &Identifier| matches!(id, Identifier::Special { output: None, input: None, vendor } if vendor.is_empty());
    let mut data = ids.iter().filter(|(id, _)| !empty(id)).peekable();
    let pkw = data.peek().is_some_and(|(_, pkw)| *pkw);
    if pkw {
        data.next();
    }
    let (mut out, mut inp) = (0u32, 0u32);
    for (id, is_pkw) in data {
        let Identifier::General { direction, data } = id else {
            return None;
        };
        if *is_pkw || !data.words {
            return None;
        }
        let count = u32::from(data.count);
        match direction {
            Direction::Both => {
                out += count;
                inp += count;
            }
            Direction::Output => out += count,
            Direction::Input => inp += count,
        }
    }
    let words = u8::try_from(out)
        .ok()
        .filter(|&w| out == inp && (1..=16).contains(&w))?;
    Some(Layout::new(pkw, words))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn general(direction: Direction, count: u8) -> Identifier {
        Identifier::General {
            direction,
            data: Length {
                words: true,
                count,
                consistent: true,
            },
        }
    }

    #[test]
    fn a_telegram_is_the_pkw_first_and_as_many_words_each_way() {
        let pkw = (general(Direction::Both, 4), true);
        let empty = (
            Identifier::Special {
                output: None,
                input: None,
                vendor: vec![],
            },
            false,
        );
        let out2 = (general(Direction::Output, 2), false);
        let in2 = (general(Direction::Input, 2), false);
        let in6 = (general(Direction::Input, 6), false);
        assert_eq!(
            layout(&[empty.clone(), out2.clone(), in2.clone()]),
            Some(Layout::new(false, 2))
        );
        assert_eq!(
            layout(&[pkw.clone(), out2.clone(), in2.clone()]),
            Some(Layout::new(true, 2))
        );
        assert_eq!(layout(&[out2.clone(), in6]), None);
        assert_eq!(layout(&[out2.clone(), pkw.clone(), in2]), None);
        assert_eq!(layout(&[pkw]), None);
    }
}
