//! The modules a master plugs for cyclic data, both buses in one list: the
//! GSD's PPO types, then the GSDML's modules. Every output that lists
//! telegrams (the layouts, the datasheet, the decoder) reads this list, so
//! they cannot disagree on which modules there are or in what order.

use super::profinet;
use super::{Ident, Ir, Layout};

/// The bus a module is plugged on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bus {
    Profibus,
    Profinet,
}

/// How the master names the module when it plugs it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModuleId<'a> {
    /// A PPO type: the config identifier bytes Chk_Cfg carries.
    Config(&'a [u8]),
    /// A PROFINET module: its ModuleIdentNumber.
    IdentNumber(u32),
}

/// A PPO type or a PROFINET module: one telegram each way.
#[derive(Debug, Clone, Copy)]
pub struct CyclicModule<'a> {
    pub bus: Bus,
    /// In English, as its device file names it: the GSD's `Module`, the
    /// GSDML's module name.
    pub name: &'a str,
    /// The device file that offers it.
    pub file_name: &'a str,
    /// Its name in generated code: `ppo1`, `pkw_pzd12`.
    pub ident: &'a Ident,
    pub layout: Layout,
    pub id: ModuleId<'a>,
    /// The GSDML's module, with its words and records.
    pub profinet: Option<&'a profinet::Module>,
}

impl CyclicModule<'_> {
    /// PROFIdrive's standard telegram 1, in the profile's API: PZD1 and
    /// PZD2 are the profile's words, not the description's.
    pub fn is_profidrive(&self) -> bool {
        self.profinet.is_some_and(profinet::Module::is_profidrive)
    }
}

impl Ir {
    /// Each module of the GSD with a telegram (a PPO type, a vendor's
    /// module of PKW and PZD words), then each module of the GSDML.
    pub fn cyclic_modules(&self) -> impl Iterator<Item = CyclicModule<'_>> {
        let ppos = self.profibus.iter().flat_map(|p| {
            p.modules.iter().filter_map(move |m| {
                Some(CyclicModule {
                    bus: Bus::Profibus,
                    name: &m.name,
                    file_name: &p.file_name,
                    ident: &m.ident,
                    layout: m.layout?,
                    id: ModuleId::Config(&m.config),
                    profinet: None,
                })
            })
        });
        let modules = self.profinet.iter().flat_map(|p| {
            p.modules.iter().map(move |m| CyclicModule {
                bus: Bus::Profinet,
                name: &m.name.text.en,
                file_name: &p.file_name,
                ident: &m.ident,
                layout: m.layout,
                id: ModuleId::IdentNumber(m.ident_number),
                profinet: Some(m),
            })
        });
        ppos.chain(modules)
    }
}
