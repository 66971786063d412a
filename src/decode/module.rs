//! The module a telegram belongs to: a PPO type or a PROFINET module, found
//! by the name the device files show, and the names of its words.

use crate::diag::Diagnostic;
use crate::ir::profibus::PpoModule;
use crate::ir::profinet::{self, ModuleKind};
use crate::ir::{Direction, Ir, Layout, PkwKind};

/// A module of either bus, as the description's IR has it.
#[derive(Debug, Clone, Copy)]
pub enum Module<'a> {
    Ppo(&'a PpoModule),
    Profinet(&'a profinet::Module),
}

impl Module<'_> {
    /// The PPO type (`PPO1`) or the name the GSDML shows (`PKW + 12 PZD`).
    pub fn name(self) -> String {
        match self {
            Module::Ppo(m) => format!("PPO{}", m.ppo),
            Module::Profinet(m) => m.name.text.en.clone(),
        }
    }

    /// Whether `name` names the module, whatever its case and blanks: the
    /// PPO type or the GSD's module name (`PPO1: 4 PKW + 2 PZD`), the GSDML's.
    fn is_called(self, name: &str) -> bool {
        let wanted = squeeze(name);
        let gsd_name = match self {
            Module::Ppo(m) => Some(&m.name),
            Module::Profinet(_) => None,
        };
        squeeze(&self.name()) == wanted || gsd_name.is_some_and(|n| squeeze(n) == wanted)
    }

    pub fn layout(self) -> Layout {
        match self {
            Module::Ppo(m) => m.layout,
            Module::Profinet(m) => m.layout,
        }
    }

    /// Whether its PZD words carry the description's mappings; standard
    /// telegram 1 has fixed meanings instead.
    pub fn is_mapped(self) -> bool {
        match self {
            Module::Ppo(_) => true,
            Module::Profinet(m) => m.kind == ModuleKind::Pzd,
        }
    }

    /// Whether PZD1 is the description's control or status word; in
    /// PROFIdrive's standard telegram 1 it is the profile's STW1 or ZSW1.
    pub fn has_vendor_words(self) -> bool {
        match self {
            Module::Ppo(_) => true,
            Module::Profinet(m) => !m.is_profidrive(),
        }
    }

    /// The name of each word in `direction`, in telegram order.
    pub fn word_names(self, ir: &Ir, direction: Direction) -> Vec<String> {
        match self {
            Module::Profinet(m) => {
                let items = match direction {
                    Direction::Out => &m.output,
                    Direction::In => &m.input,
                };
                items.iter().map(|item| item.text.text.en.clone()).collect()
            }
            Module::Ppo(m) => ppo_word_names(ir, m.layout, direction),
        }
    }

    /// What the module holds, for a help line: "12 bytes each way: the PKW
    /// channel (8 bytes) and 2 PZD words".
    pub fn summary(self) -> String {
        let layout = self.layout();
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

/// Every module of the description: the PPO types, then the PROFINET
/// modules, in the order of the device files.
fn modules(ir: &Ir) -> Vec<Module<'_>> {
    let ppos = ir.profibus.iter().flat_map(|p| &p.modules).map(Module::Ppo);
    let profinet = ir
        .profinet
        .iter()
        .flat_map(|p| &p.modules)
        .map(Module::Profinet);
    ppos.chain(profinet).collect()
}

/// The module called `name`, ignoring case and blanks (`ppo1`,
/// `pkw+12pzd`; see `Module::is_called`), or E413 with the names there are. The diagnostic's span
/// is the whole of `name`.
pub fn find_module<'a>(ir: &'a Ir, name: &str) -> Result<Module<'a>, Diagnostic> {
    let all = modules(ir);
    if let Some(module) = all.iter().find(|m| m.is_called(name)) {
        return Ok(*module);
    }
    let names: Vec<String> = all.iter().map(|m| m.name()).collect();
    let help = if names.is_empty() {
        "the description has no PROFIBUS or PROFINET modules".to_string()
    } else {
        format!("the modules are: {}", names.join(", "))
    };
    Err(
        Diagnostic::error("E413", format!("the description has no module `{name}`"))
            .at(0..name.len())
            .label("unknown module")
            .help(help),
    )
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
        PkwKind::None => &[],
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::decode::tests::{md810, mv810};

    #[test]
    fn names_match_whatever_the_case_and_blanks() {
        let ir = mv810();
        for name in ["PKW + 12 PZD", "pkw+12pzd", " Pkw + 12  pzd "] {
            let module = find_module(&ir, name).unwrap();
            assert_eq!(module.name(), "PKW + 12 PZD");
            assert_eq!(module.layout().bytes(), 32);
        }
        let ir = md810();
        assert_eq!(find_module(&ir, "ppo5").unwrap().name(), "PPO5");
        let gsd_name = find_module(&ir, "PPO5: 4 PKW + 12 PZD").unwrap();
        assert_eq!(gsd_name.layout().bytes(), 32);
        assert_eq!(find_module(&ir, "6 pzd").unwrap().name(), "6 PZD");
    }

    #[test]
    fn an_unknown_name_lists_the_modules() {
        let ir = md810();
        let d = find_module(&ir, "PPO7").unwrap_err();
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
            let ppo = ppo_word_names(&ir, pn.layout(), Direction::In);
            assert_eq!(ppo, pn.word_names(&ir, Direction::In));
            let ppo = ppo_word_names(&ir, pn.layout(), Direction::Out);
            assert_eq!(ppo, pn.word_names(&ir, Direction::Out));
        }
        let ir = md810();
        let names = find_module(&ir, "PPO1")
            .unwrap()
            .word_names(&ir, Direction::Out);
        assert_eq!(names, ["PKE", "IND", "PWE high", "PWE low", "PZD1", "PZD2"]);
    }
}
