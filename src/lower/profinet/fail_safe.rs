//! `[profinet.fail_safe_values]`: the values each module's settings record
//! ends with, one for each of the module's output PZD items, named by kind
//! of module.

use crate::description as raw;
use crate::diag::Diagnostic;
use crate::ir::profinet::{DataItem, ModuleKind, TextRef};
use crate::ir::{Layout, Text};
use crate::lower::checks::Checker;
use toml::Spanned;

/// Standard telegram 1's output items: two words (PROFIdrive's STW1 and
/// NSOLL_A, or a vendor's).
const STANDARD_TELEGRAM_1_ITEMS: usize = 2;
/// Standard telegram 2's output items: STW1, NSOLL_B (32 bits), STW2.
const STANDARD_TELEGRAM_2_ITEMS: usize = 3;

/// A list of names as the description gives it.
type GivenNames = Spanned<Vec<Spanned<raw::Text>>>;

/// Each kind of module's names of its fail-safe values, in telegram order.
pub struct FailSafeNames {
    user_defined: Vec<Text>,
    telegram_1: Vec<Text>,
    telegram_2: Vec<Text>,
}

/// A module's fail-safe values before the record places them: one per
/// output PZD item, named, of the item's width.
pub struct FailSafeItem {
    pub text: TextRef,
    pub double_word: bool,
}

impl FailSafeNames {
    /// The values a module of `kind` ends its settings record with: one per
    /// output item after the PKW channel's words.
    pub fn items(
        &self,
        kind: ModuleKind,
        layout: Layout,
        output: &[DataItem],
    ) -> Vec<FailSafeItem> {
        let (names, tag) = match kind {
            ModuleKind::Pzd => (&self.user_defined, "FAIL_SAFE"),
            ModuleKind::StandardTelegram1 => (&self.telegram_1, "FAIL_SAFE_TELEGRAM_1"),
            ModuleKind::StandardTelegram2 => (&self.telegram_2, "FAIL_SAFE_TELEGRAM_2"),
        };
        let pzd = &output[usize::from(layout.pkw_words())..];
        pzd.iter()
            .zip(names)
            .enumerate()
            .map(|(i, (item, name))| FailSafeItem {
                text: TextRef::new(format!("IDT_{tag}_{}", i + 1), name.clone()),
                double_word: item.double_word,
            })
            .collect()
    }
}

/// The names `[profinet.fail_safe_values]` gives, checked: as many as each
/// kind of module has output items (E185; `user_defined` as many as the
/// longest of `pzd_lengths` as written, whose own errors are said there), a
/// list for each standard telegram offered and none for another (E004,
/// E002), and settings the master sets, whose record carries them (E186).
/// None when the table is absent or wrong.
pub fn names(
    cx: &mut Checker,
    p: &raw::Profinet,
    kinds: &[(ModuleKind, Layout)],
    master_sets_settings: bool,
) -> Option<FailSafeNames> {
    let given = p.fail_safe_values.as_ref()?;
    let values = given.get_ref();
    if !master_sets_settings {
        cx.push(
            Diagnostic::error("E186", "fail-safe values without a settings record to carry them")
                .at(given.span())
                .label("each module's settings record ends with them")
                .help("the settings record carries the [[settings]] the master sets: add them (set_at = \"master\"), or remove [profinet.fail_safe_values]"),
        );
        return None;
    }
    let longest = p
        .pzd_lengths
        .get_ref()
        .iter()
        .map(|n| usize::from(*n.get_ref()));
    let longest = longest.max().unwrap_or(0);
    let offered = |kind| kinds.iter().any(|(k, _)| *k == kind);
    let user_defined = list(
        cx,
        &values.user_defined,
        longest,
        "the longest module's PZD words",
    );
    let telegram_1 = telegram(
        cx,
        (&values.standard_telegram_1, given.span()),
        offered(ModuleKind::StandardTelegram1),
        ("standard_telegram_1", STANDARD_TELEGRAM_1_ITEMS),
    );
    let telegram_2 = telegram(
        cx,
        (&values.standard_telegram_2, given.span()),
        offered(ModuleKind::StandardTelegram2),
        ("standard_telegram_2", STANDARD_TELEGRAM_2_ITEMS),
    );
    Some(FailSafeNames {
        user_defined: user_defined?,
        telegram_1: telegram_1?,
        telegram_2: telegram_2?,
    })
}

/// A standard telegram's names: required when it is offered, refused when
/// not.
fn telegram(
    cx: &mut Checker,
    (names, table): (&Option<GivenNames>, std::ops::Range<usize>),
    offered: bool,
    (key, items): (&str, usize),
) -> Option<Vec<Text>> {
    match (names, offered) {
        (Some(names), true) => list(cx, names, items, "the telegram's output items"),
        (None, false) => Some(Vec::new()),
        (Some(names), false) => {
            cx.push(
                Diagnostic::error(
                    "E002",
                    format!("fail-safe values of {key}, which is not offered"),
                )
                .at(names.span())
                .label("no such module")
                .help(format!(
                    "remove `{key}` here, or offer the telegram: [profinet] {key} = true"
                )),
            );
            None
        }
        (None, true) => {
            cx.push(
                Diagnostic::error("E004", format!("missing field `{key}`"))
                    .at(table)
                    .label(format!("{key}'s record ends with its fail-safe values too"))
                    .help(format!("name the telegram's {items} output items' values in `{key} = [...]`, as the manual names them")),
            );
            None
        }
    }
}

/// One name per item (E185), each a text.
fn list(cx: &mut Checker, names: &GivenNames, items: usize, what: &str) -> Option<Vec<Text>> {
    let given = names.get_ref();
    if given.len() != items {
        cx.push(
            Diagnostic::error(
                "E185",
                format!("{} fail-safe values for {items} output items", given.len()),
            )
            .at(names.span())
            .label(format!("one per item: {what}"))
            .help(format!(
                "name {items} values, one for each output item in telegram order"
            )),
        );
        return None;
    }
    Some(
        given
            .iter()
            .map(|n| cx.text(n, None, "fail-safe value name"))
            .collect(),
    )
}
