//! The module a telegram belongs to: a PPO type, a PROFINET module or a
//! gateway's block of words, found by the name the device files show, and
//! the names of its words.

use crate::diag::Diagnostic;
use crate::ir::gateway::{self, Gateway};
use crate::ir::profibus::DpModule;
use crate::ir::profinet::{self, ModuleKind};
use crate::ir::{Direction, Ir, Layout, PkwKind};

/// A module of either bus, as the description's IR has it.
#[derive(Debug, Clone, Copy)]
pub enum Module<'a> {
    /// A GSD module with a telegram: a PPO type or a vendor's module.
    Ppo(&'a DpModule, Layout),
    Profinet(&'a profinet::Module),
    /// A gateway's module: words one way, of the nodes of the second bus.
    Gateway(&'a Gateway, &'a gateway::Module),
}

impl Module<'_> {
    /// The PPO type (`PPO1`) or the name the GSDML or GSD shows (`PKW + 12
    /// PZD`, `INPUT 16 words`).
    pub fn name(self) -> String {
        match self {
            Module::Ppo(m, _) => m.ppo.map_or_else(|| m.name.clone(), |n| format!("PPO{n}")),
            Module::Profinet(m) => m.name.text.en.clone(),
            Module::Gateway(_, m) => m.name.clone(),
        }
    }

    /// Whether `name` names the module, whatever its case and blanks: the
    /// PPO type or the GSD's module name (`PPO1: 4 PKW + 2 PZD`), the GSDML's.
    fn is_called(self, name: &str) -> bool {
        let wanted = squeeze(name);
        let gsd_name = match self {
            Module::Ppo(m, _) => Some(&m.name),
            Module::Profinet(_) | Module::Gateway(..) => None,
        };
        squeeze(&self.name()) == wanted || gsd_name.is_some_and(|n| squeeze(n) == wanted)
    }

    /// The layout of a PPO type or PROFINET module, the same each way; a
    /// gateway's module has words one way only.
    pub fn layout(self) -> Option<Layout> {
        match self {
            Module::Ppo(_, layout) => Some(layout),
            Module::Profinet(m) => Some(m.layout),
            Module::Gateway(..) => None,
        }
    }

    /// Bytes of its telegram (each way, or the one way it goes).
    pub fn bytes(self) -> usize {
        match self {
            Module::Ppo(_, layout) => layout.bytes().into(),
            Module::Profinet(m) => m.layout.bytes().into(),
            Module::Gateway(_, m) => 2 * usize::from(m.words),
        }
    }

    /// The direction a gateway's module goes; the others go both ways.
    fn only_direction(self) -> Option<Direction> {
        match self {
            Module::Gateway(_, m) => Some(m.direction),
            Module::Ppo(..) | Module::Profinet(_) => None,
        }
    }

    /// Whether its PZD words carry the description's mappings; the
    /// standard telegrams have fixed meanings instead, and a gateway's words
    /// are its nodes'.
    pub fn is_mapped(self) -> bool {
        match self {
            Module::Ppo(..) => true,
            Module::Profinet(m) => m.kind == ModuleKind::Pzd,
            Module::Gateway(..) => false,
        }
    }

    /// Whether PZD1 is the description's control or status word; in
    /// PROFIdrive's standard telegrams 1 and 2 it is the profile's STW1 or
    /// ZSW1.
    pub fn has_vendor_words(self) -> bool {
        match self {
            Module::Ppo(..) => true,
            Module::Profinet(m) => !m.is_profidrive(),
            Module::Gateway(..) => false,
        }
    }

    /// Whether it is a PROFIdrive card's standard telegram 1 or 2, whose
    /// PZD1 is the profile's STW1 or ZSW1.
    pub fn is_profidrive_telegram(self) -> bool {
        matches!(self, Module::Profinet(m) if m.is_profidrive())
    }

    /// The name of each word in `direction`, in telegram order.
    pub fn word_names(self, ir: &Ir, direction: Direction) -> Vec<String> {
        match self {
            Module::Profinet(m) => {
                let items = match direction {
                    Direction::Out => &m.output,
                    Direction::In => &m.input,
                };
                items.iter().flat_map(item_word_names).collect()
            }
            Module::Ppo(_, layout) => ppo_word_names(ir, layout, direction),
            Module::Gateway(_, m) => (1..=m.words).map(word_name).collect(),
        }
    }

    /// The 32-bit items in `direction`: the word each starts at (from 0,
    /// the PKW channel's counted) and its name; none but in standard
    /// telegram 2.
    pub fn double_words(self, direction: Direction) -> Vec<(usize, String)> {
        let Module::Profinet(m) = self else {
            return Vec::new();
        };
        m.placed_items(direction)
            .filter(|(_, item)| item.double_word)
            .map(|(at, item)| (usize::from(at), item.text.text.en.clone()))
            .collect()
    }

    /// What the module holds, for a help line: "PPO1 is 12 bytes each way:
    /// the PKW channel (8 bytes) and 2 PZD word(s)".
    pub fn summary(self) -> String {
        let Some(layout) = self.layout() else {
            let way = match self.only_direction() {
                Some(Direction::In) => "the master's input, the words the nodes send",
                _ => "the master's output, the words the nodes receive",
            };
            return format!("{} is {} bytes of {way}", self.name(), self.bytes());
        };
        let pkw = if layout.pkw {
            format!("the PKW channel ({} bytes) and ", 2 * layout.pkw_words())
        } else {
            String::new()
        };
        format!(
            "{} is {} bytes each way: {pkw}{} PZD word(s)",
            self.name(),
            layout.bytes(),
            layout.pzd_words
        )
    }
}

/// The name of each word of a data item: a 32-bit item's two words, high
/// word first (standard telegram 2's NSOLL_B and NIST_B).
fn item_word_names(item: &crate::ir::profinet::DataItem) -> Vec<String> {
    let name = &item.text.text.en;
    match item.double_word {
        false => vec![name.clone()],
        true => vec![format!("{name}, high word"), format!("{name}, low word")],
    }
}

/// Every module of the description: the PPO types, then the PROFINET
/// modules, then a gateway's, in the order of the device files.
fn modules(ir: &Ir) -> Vec<Module<'_>> {
    let ppos = ir
        .profibus
        .iter()
        .flat_map(|p| &p.modules)
        .filter_map(|m| Some(Module::Ppo(m, m.layout?)));
    let profinet = ir
        .profinet
        .iter()
        .flat_map(|p| &p.modules)
        .map(Module::Profinet);
    let gateway = ir
        .gateway
        .iter()
        .flat_map(|g| g.modules.iter().map(move |m| Module::Gateway(g, m)));
    ppos.chain(profinet).chain(gateway).collect()
}

/// The module called `name` that goes in `direction`, ignoring case and
/// blanks (`ppo1`, `pkw+12pzd`; see `Module::is_called`), or E413 with the
/// names there are. The diagnostic's span is the whole of `name`.
pub fn find_module<'a>(
    ir: &'a Ir,
    name: &str,
    direction: Direction,
) -> Result<Module<'a>, Diagnostic> {
    let all = modules(ir);
    let Some(module) = all.iter().find(|m| m.is_called(name)) else {
        let names: Vec<String> = all.iter().map(|m| m.name()).collect();
        let help = if names.is_empty() {
            "the description has no PROFIBUS or PROFINET modules".to_string()
        } else {
            format!("the modules are: {}", names.join(", "))
        };
        return Err(
            Diagnostic::error("E413", format!("the description has no module `{name}`"))
                .at(0..name.len())
                .label("unknown module")
                .help(help),
        );
    };
    match module.only_direction() {
        Some(only) if only != direction => {
            let (wanted, has) = match direction {
                Direction::In => ("input", "an output module"),
                Direction::Out => ("output", "an input module"),
            };
            let others: Vec<String> = all
                .iter()
                .filter(|m| m.only_direction() == Some(direction))
                .map(|m| m.name())
                .collect();
            Err(Diagnostic::error(
                "E413",
                format!("the description has no {wanted} module `{name}`"),
            )
            .at(0..name.len())
            .label(has)
            .help(format!(
                "the {wanted} modules (--direction {}) are: {}",
                match direction {
                    Direction::In => "in",
                    Direction::Out => "out",
                },
                others.join(", ")
            )))
        }
        _ => Ok(*module),
    }
}

/// Lower case without blanks: how module names are compared.
fn squeeze(name: &str) -> String {
    name.chars()
        .filter(|c| !c.is_whitespace())
        .flat_map(char::to_lowercase)
        .collect()
}

/// A PPO type's words: the PKW channel, then PZD1..PZDn, PZD1 named after
/// the control or status word when the telegram has one. The IR carries
/// these names for PROFINET modules only (`profinet::DataItem`); these are
/// the same names, so both buses show a telegram alike.
fn ppo_word_names(ir: &Ir, layout: Layout, direction: Direction) -> Vec<String> {
    let pkw = if layout.pkw {
        pkw_word_names(ir.telegram.pkw)
    } else {
        &[]
    };
    let word = ir.telegram.word(direction);
    let pzd = (1..=layout.pzd_words).map(|n| match word {
        Some(word) if n == 1 => word.name.en.clone(),
        _ => format!("PZD{n}"),
    });
    pkw.iter().map(|name| name.to_string()).chain(pzd).collect()
}

/// The PKW channel's words, as the GSDML names them.
fn pkw_word_names(kind: PkwKind) -> &'static [&'static str] {
    match kind {
        PkwKind::PkeIndPwe => &["PKE", "IND", "PWE high", "PWE low"],
        PkwKind::StationCommandAddressValue => &["Station", "Command", "Address", "Value"],
        PkwKind::Profidrive => &["PKE", "IND", "PWE1", "PWE2"],
        PkwKind::None => &[],
    }
}

/// A gateway module's word `n`, from 1: `word 3`.
pub(super) fn word_name(n: u8) -> String {
    format!("word {n}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::decode::tests::{md810, mv810};

    #[test]
    fn names_match_whatever_the_case_and_blanks() {
        let ir = mv810();
        for name in ["PKW + 12 PZD", "pkw+12pzd", " Pkw + 12  pzd "] {
            let module = find_module(&ir, name, Direction::In).unwrap();
            assert_eq!(module.name(), "PKW + 12 PZD");
            assert_eq!(module.bytes(), 32);
        }
        let ir = md810();
        assert_eq!(
            find_module(&ir, "ppo5", Direction::In).unwrap().name(),
            "PPO5"
        );
        let gsd_name = find_module(&ir, "PPO5: 4 PKW + 12 PZD", Direction::Out).unwrap();
        assert_eq!(gsd_name.bytes(), 32);
        assert_eq!(
            find_module(&ir, "6 pzd", Direction::Out).unwrap().name(),
            "6 PZD"
        );
    }

    #[test]
    fn an_unknown_name_lists_the_modules() {
        let ir = md810();
        let d = find_module(&ir, "PPO7", Direction::Out).unwrap_err();
        assert_eq!((d.code, d.span), ("E413", Some(0..4)));
        let help = d.help.unwrap();
        assert!(
            help.starts_with("the modules are: PPO1, PPO2, PPO3, PPO4, PPO5, PKW + 2 PZD,"),
            "{help}"
        );
        assert!(help.ends_with(", 12 PZD"), "{help}");
    }

    /// PPO and PROFINET modules of the same layout name their words alike:
    /// the PPO names are built here, the PROFINET ones by lowering.
    #[test]
    fn ppo_words_are_named_as_the_profinet_module_of_the_same_layout() {
        for ir in [md810(), mv810()] {
            let all = modules(&ir);
            let pn = all.iter().find(|m| m.name() == "PKW + 2 PZD").unwrap();
            let layout = pn.layout().unwrap();
            let ppo = ppo_word_names(&ir, layout, Direction::In);
            assert_eq!(ppo, pn.word_names(&ir, Direction::In));
            let ppo = ppo_word_names(&ir, layout, Direction::Out);
            assert_eq!(ppo, pn.word_names(&ir, Direction::Out));
        }
        let ir = md810();
        let names = find_module(&ir, "PPO1", Direction::Out)
            .unwrap()
            .word_names(&ir, Direction::Out);
        assert_eq!(names, ["PKE", "IND", "PWE high", "PWE low", "PZD1", "PZD2"]);
    }

    /// The PROFIdrive channel's words are the profile's PKE, IND, PWE1,
    /// PWE2, on a PROFINET module (as the GSDML names them) and a PPO alike.
    #[test]
    fn profidrive_words_are_the_profiles_on_both_buses() {
        let text = include_str!("../../tests/fixtures/valid/profidrive.toml")
            .replace("module_pkw = \"without\"", "module_pkw = \"both\"");
        let ir = crate::load("profidrive.toml", &text).0.unwrap();
        let pn = find_module(&ir, "PKW + 1 PZD", Direction::Out).unwrap();
        let names = ["PKE", "IND", "PWE1", "PWE2", "PZD1"];
        assert_eq!(pn.word_names(&ir, Direction::Out), names);
        assert_eq!(pn.word_names(&ir, Direction::In), names);
        let ppo1 = find_module(&ir, "PPO1", Direction::In).unwrap();
        assert_eq!(
            ppo1.word_names(&ir, Direction::In),
            ["PKE", "IND", "PWE1", "PWE2", "PZD1", "PZD2"]
        );
    }
}
