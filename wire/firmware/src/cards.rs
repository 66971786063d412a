//! Each layout's [`Card`]: its constants under the names every description
//! shares.

use crate::card::{
    Card, Diagnosis, DpModule, PnModule, PnRecord, PnSubmodule, PrmValues, Profibus, Profinet,
};
use crate::gsdc_support::PrmError;
use crate::pkw::PkwKind;

/// The card of the description named `name`, if the firmware was built
/// for it.
pub fn card(name: &str) -> Option<&'static Card> {
    CARDS.iter().find(|c| c.name == name)
}

/// Every card the firmware is built for.
pub const CARDS: &[Card] = &[md810dp::CARD, mv810_pnet02::CARD, profidrive::CARD];

/// PROVISIONAL, until the layouts carry their device tables: the PROFINET
/// access point as gsdc numbers it today (its own submodule in subslot 1 with
/// the DAP's ident; the interface and each port with their subslot as
/// ident), from the layout's constants.
macro_rules! pn_dap {
    ($layout:path, ports: [$($port:expr),*]) => {{
        use $layout as l;
        &[
            PnSubmodule { subslot: 1, ident: l::DAP_IDENT, api: 0, input_len: 0, output_len: 0 },
            PnSubmodule {
                subslot: l::INTERFACE_SUBSLOT,
                ident: l::INTERFACE_SUBSLOT as u32,
                api: 0,
                input_len: 0,
                output_len: 0,
            },
            $(PnSubmodule {
                subslot: l::FIRST_PORT_SUBSLOT + $port,
                ident: (l::FIRST_PORT_SUBSLOT + $port) as u32,
                api: 0,
                input_len: 0,
                output_len: 0,
            }),*
        ]
    }};
}

/// PROVISIONAL (as `pn_dap`): a module with one submodule in subslot 1
/// carrying `pkw` and `pzd` words each way, its ident the module's. The
/// GSDML ID is typed here: no layout has it yet.
macro_rules! pn_module {
    ($id:literal, $ident:expr, slots: $slots:expr, pkw: $pkw:literal, pzd: $pzd:literal, records: $records:expr) => {
        PnModule {
            id: $id,
            ident: $ident,
            slots: $slots,
            submodules: &[PnSubmodule {
                subslot: 1,
                ident: $ident,
                api: 0,
                input_len: (if $pkw {
                    crate::gsdc_support::PKW_BYTES
                } else {
                    0
                } + 2 * $pzd) as u16,
                output_len: (if $pkw {
                    crate::gsdc_support::PKW_BYTES
                } else {
                    0
                } + 2 * $pzd) as u16,
            }],
            pkw: $pkw,
            pzd_words: $pzd,
            records: $records,
        }
    };
}

/// A record of subslot 1 decoded by the layout's `decode_record` of
/// `$mappings`'s module.
macro_rules! pn_record {
    ($module:ident) => {
        PnRecord {
            subslot: 1,
            index: $module::RECORD_INDEX,
            mappings: &$module::MAPPINGS,
            decode: |bytes| {
                Ok(PrmValues::EMPTY.with(&$module::MAPPINGS, &$module::decode_record(bytes)?))
            },
        }
    };
}

mod md810dp {
    use super::*;
    use crate::layouts::md810dp::*;

    pub const CARD: Card = Card {
        name: "md810dp",
        fingerprint: FINGERPRINT,
        pkw: Some(PkwKind::PkeIndPwe),
        control_word: false,
        status_word: false,
        pzd_out: &pzd_out::MAPPINGS,
        pzd_in: &pzd_in::MAPPINGS,
        status_of: None,
        profibus: Some(&PROFIBUS),
        profinet: Some(&PROFINET),
    };

    const RECORDS: &[PnRecord] = &[
        pn_record!(pzd_out),
        pn_record!(pzd_in),
        pn_record!(dpv1_index),
    ];
    const SLOT: &[u16] = &[MODULE_SLOT];

    const PROFINET: Profinet = Profinet {
        vendor_id: PROFINET_VENDOR_ID,
        device_id: PROFINET_DEVICE_ID,
        dap_ident: DAP_IDENT,
        dap_submodules: pn_dap!(crate::layouts::md810dp, ports: [0, 1]),
        modules: &[
            pn_module!("IDM_PKW_2", PKW_PZD2_IDENT, slots: SLOT, pkw: true, pzd: 2, records: RECORDS),
            pn_module!("IDM_PKW_6", PKW_PZD6_IDENT, slots: SLOT, pkw: true, pzd: 6, records: RECORDS),
            pn_module!("IDM_PKW_12", PKW_PZD12_IDENT, slots: SLOT, pkw: true, pzd: 12, records: RECORDS),
            pn_module!("IDM_PZD_2", PZD2_IDENT, slots: SLOT, pkw: false, pzd: 2, records: RECORDS),
            pn_module!("IDM_PZD_6", PZD6_IDENT, slots: SLOT, pkw: false, pzd: 6, records: RECORDS),
            pn_module!("IDM_PZD_12", PZD12_IDENT, slots: SLOT, pkw: false, pzd: 12, records: RECORDS),
        ],
    };

    const PROFIBUS: Profibus = Profibus {
        ident_number: PROFIBUS_IDENT_NUMBER,
        modules: &[
            DpModule {
                name: "PPO1: 4 PKW + 2 PZD",
                config: &PPO1_CONFIG,
                pkw: true,
                pzd_words: 2,
            },
            DpModule {
                name: "PPO2: 4 PKW + 6 PZD",
                config: &PPO2_CONFIG,
                pkw: true,
                pzd_words: 6,
            },
            DpModule {
                name: "PPO3: 2 PZD",
                config: &PPO3_CONFIG,
                pkw: false,
                pzd_words: 2,
            },
            DpModule {
                name: "PPO4: 6 PZD",
                config: &PPO4_CONFIG,
                pkw: false,
                pzd_words: 6,
            },
            DpModule {
                name: "PPO5: 4 PKW + 12 PZD",
                config: &PPO5_CONFIG,
                pkw: true,
                pzd_words: 12,
            },
        ],
        user_prm_len: USER_PRM_LEN,
        decode_user_prm,
        diagnosis: Some(Diagnosis {
            len: diagnosis::LEN,
            empty: &diagnosis::EMPTY,
            code: diagnosis::BITS_8_15,
        }),
    };

    fn decode_user_prm(bytes: &[u8]) -> Result<PrmValues, PrmError> {
        let prm = crate::layouts::md810dp::decode_user_prm(bytes)?;
        Ok(PrmValues::EMPTY
            .with(&pzd_out::MAPPINGS, &prm.pzd_out)
            .with(&pzd_in::MAPPINGS, &prm.pzd_in)
            .with(&dpv1_index::MAPPINGS, &prm.dpv1_index))
    }
}

mod mv810_pnet02 {
    use super::*;
    use crate::layouts::mv810_pnet02::*;

    pub const CARD: Card = Card {
        name: "mv810-pnet02",
        fingerprint: FINGERPRINT,
        pkw: Some(PkwKind::StationCommand),
        control_word: true,
        status_word: true,
        // MV810's mappings hold what a PZD word means (1: set frequency ...),
        // not a parameter's address, and its drive model holds none of those
        // quantities: its PZD2 to PZD12 carry 0.
        pzd_out: &[],
        pzd_in: &[],
        status_of: Some(status_of),
        profibus: None,
        profinet: Some(&PROFINET),
    };

    /// The drive answering its control word (section 3's bits, by the
    /// layout's names): it runs forward or reverse while asked to and not
    /// asked to stop, and reports stop otherwise; it is always ready. That
    /// it reacts at once is this model's own: the manual gives the bits,
    /// not the drive's timing.
    fn status_of(control: u16) -> u16 {
        use control_word as c;
        use status_word as s;
        let stopping = [c::DECELERATE_TO_STOP, c::COAST_TO_STOP, c::EMERGENCY_STOP]
            .iter()
            .any(|bit| bit.is_set(control));
        let forward = c::FORWARD_RUNNING.is_set(control) && !stopping;
        let reverse = c::REVERSE_RUNNING.is_set(control) && !stopping && !forward;
        let status = s::READY_STATUS.with(0, 1);
        let status = s::FORWARD_RUNNING.with(status, forward.into());
        let status = s::REVERSE_RUNNING.with(status, reverse.into());
        s::STOP.with(status, (!forward && !reverse).into())
    }

    const SLOT: &[u16] = &[MODULE_SLOT];
    /// Standard message 1 fixes P43.01 (settings); the user-defined modules
    /// also map PZD2 and up, one word each way per word the module carries
    /// after PZD1.
    const SETTINGS: &[PnRecord] = &[pn_record!(settings)];
    const MAPPED: &[PnRecord] = &[
        pn_record!(pzd_out),
        pn_record!(pzd_in),
        pn_record!(settings),
    ];

    const PROFINET: Profinet = Profinet {
        vendor_id: PROFINET_VENDOR_ID,
        device_id: PROFINET_DEVICE_ID,
        dap_ident: DAP_IDENT,
        dap_submodules: pn_dap!(crate::layouts::mv810_pnet02, ports: [0, 1]),
        modules: &[
            pn_module!("IDM_STD_TEL_1", TELEGRAM1_IDENT, slots: SLOT, pkw: false, pzd: 2, records: SETTINGS),
            pn_module!("IDM_PKW_1", PKW_PZD1_IDENT, slots: SLOT, pkw: true, pzd: 1, records: SETTINGS),
            pn_module!("IDM_PKW_2", PKW_PZD2_IDENT, slots: SLOT, pkw: true, pzd: 2, records: MAPPED),
            pn_module!("IDM_PKW_3", PKW_PZD3_IDENT, slots: SLOT, pkw: true, pzd: 3, records: MAPPED),
            pn_module!("IDM_PKW_4", PKW_PZD4_IDENT, slots: SLOT, pkw: true, pzd: 4, records: MAPPED),
            pn_module!("IDM_PKW_5", PKW_PZD5_IDENT, slots: SLOT, pkw: true, pzd: 5, records: MAPPED),
            pn_module!("IDM_PKW_6", PKW_PZD6_IDENT, slots: SLOT, pkw: true, pzd: 6, records: MAPPED),
            pn_module!("IDM_PKW_7", PKW_PZD7_IDENT, slots: SLOT, pkw: true, pzd: 7, records: MAPPED),
            pn_module!("IDM_PKW_8", PKW_PZD8_IDENT, slots: SLOT, pkw: true, pzd: 8, records: MAPPED),
            pn_module!("IDM_PKW_9", PKW_PZD9_IDENT, slots: SLOT, pkw: true, pzd: 9, records: MAPPED),
            pn_module!("IDM_PKW_10", PKW_PZD10_IDENT, slots: SLOT, pkw: true, pzd: 10, records: MAPPED),
            pn_module!("IDM_PKW_11", PKW_PZD11_IDENT, slots: SLOT, pkw: true, pzd: 11, records: MAPPED),
            pn_module!("IDM_PKW_12", PKW_PZD12_IDENT, slots: SLOT, pkw: true, pzd: 12, records: MAPPED),
        ],
    };
}

mod profidrive {
    use super::*;
    use crate::layouts::profidrive::*;

    pub const CARD: Card = Card {
        name: "profidrive",
        fingerprint: FINGERPRINT,
        pkw: Some(PkwKind::Profidrive),
        // PROFIdrive's STW1 and ZSW1: the fixture's drive model has no state
        // machine of the profile, so they carry nothing here.
        control_word: false,
        status_word: false,
        pzd_out: &[],
        pzd_in: &[],
        status_of: None,
        profibus: None,
        profinet: Some(&PROFINET),
    };

    const SLOT: &[u16] = &[MODULE_SLOT];

    const PROFINET: Profinet = Profinet {
        vendor_id: PROFINET_VENDOR_ID,
        device_id: PROFINET_DEVICE_ID,
        dap_ident: DAP_IDENT,
        dap_submodules: pn_dap!(crate::layouts::profidrive, ports: [0, 1]),
        modules: &[
            PnModule {
                id: "IDM_STD_TEL_1",
                ident: TELEGRAM1_IDENT,
                slots: SLOT,
                submodules: &[
                    PnSubmodule {
                        subslot: TELEGRAM1_ACCESS_POINT_SUBSLOT,
                        ident: TELEGRAM1_ACCESS_POINT_IDENT,
                        api: TELEGRAM1_API,
                        input_len: 0,
                        output_len: 0,
                    },
                    PnSubmodule {
                        subslot: TELEGRAM1_DATA_SUBSLOT,
                        ident: TELEGRAM1_IDENT,
                        api: TELEGRAM1_API,
                        input_len: Telegram1In::LEN as u16,
                        output_len: Telegram1Out::LEN as u16,
                    },
                ],
                pkw: false,
                pzd_words: 2,
                records: &[],
            },
            pn_module!("IDM_PZD_1", PZD1_IDENT, slots: SLOT, pkw: false, pzd: 1, records: &[pn_record!(settings)]),
        ],
    };
}
