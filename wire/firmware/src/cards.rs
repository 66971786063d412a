//! Each layout's [`Card`]: its constants under the names every description
//! shares.

use crate::card::Card;
use crate::cyclic::Shape;
use crate::gsdc_support::{PnModule, PKW_BYTES};

/// The card of the description named `name`, if the firmware was built
/// for it.
pub fn card(name: &str) -> Option<&'static Card> {
    CARDS.iter().find(|c| c.name == name)
}

/// Every card the firmware is built for.
pub const CARDS: &[Card] = &[
    #[cfg(layout = "md810dp")]
    md810dp::CARD,
    #[cfg(layout = "9kdp1")]
    powtran_9kdp1::CARD,
    #[cfg(layout = "profidrive")]
    profidrive::CARD,
    #[cfg(layout = "no_warnings")]
    no_warnings::CARD,
    #[cfg(layout = "md810-gateway")]
    md810_gateway::CARD,
    #[cfg(layout = "mv810-pnet02")]
    mv810_pnet02::CARD,
];

/// PROVISIONAL, until the device table says it (see
/// [`crate::card::Profinet::shape`]): a PROFINET module's telegram, the PKW
/// channel when `pkw`, then PZD words to its length.
#[allow(dead_code)] // Only the cards of layouts with [profinet] use it.
fn pn_shape(module: &PnModule, pkw: bool) -> Shape {
    let pkw_bytes = if pkw { PKW_BYTES } else { 0 };
    Shape {
        pkw,
        pzd_words: (module.data.output_len - pkw_bytes) / 2,
    }
}

#[cfg(layout = "md810dp")]
mod md810dp {
    use crate::card::{Card, Diagnosis, DpModule, PrmValues, Profibus, Profinet};
    use crate::layouts::md810dp::*;
    use crate::pkw::PkwKind;

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
        profinet: Some(Profinet {
            device: &PN_DEVICE,
            shape: pn_shape,
        }),
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
        gateway: None,
    };

    fn pn_shape(module: &crate::gsdc_support::PnModule) -> crate::cyclic::Shape {
        let pkw = [PKW_PZD2_IDENT, PKW_PZD6_IDENT, PKW_PZD12_IDENT].contains(&module.ident);
        super::pn_shape(module, pkw)
    }

    fn decode_user_prm(bytes: &[u8]) -> Result<PrmValues, PrmError> {
        let prm = crate::layouts::md810dp::decode_user_prm(bytes)?;
        Ok(PrmValues::EMPTY
            .with(&pzd_out::MAPPINGS, &prm.pzd_out)
            .with(&pzd_in::MAPPINGS, &prm.pzd_in)
            .with(&dpv1_index::MAPPINGS, &prm.dpv1_index))
    }
}

#[cfg(layout = "9kdp1")]
mod powtran_9kdp1 {
    use crate::card::{Card, Diagnosis, DpModule, PrmValues, Profibus};
    use crate::layouts::gsdc_9kdp1::*;

    pub const CARD: Card = Card {
        name: "9kdp1",
        fingerprint: FINGERPRINT,
        pkw: None,
        control_word: true,
        status_word: true,
        pzd_out: &pzd_out::MAPPINGS,
        pzd_in: &pzd_in::MAPPINGS,
        status_of: None,
        profibus: Some(&PROFIBUS),
        profinet: None,
    };

    const PROFIBUS: Profibus = Profibus {
        ident_number: PROFIBUS_IDENT_NUMBER,
        modules: &[
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
        ],
        user_prm_len: USER_PRM_LEN,
        decode_user_prm,
        diagnosis: Some(Diagnosis {
            len: diagnosis::LEN,
            empty: &diagnosis::EMPTY,
            code: diagnosis::BITS_8_15,
        }),
        gateway: None,
    };

    fn decode_user_prm(bytes: &[u8]) -> Result<PrmValues, PrmError> {
        let prm = crate::layouts::gsdc_9kdp1::decode_user_prm(bytes)?;
        Ok(PrmValues::EMPTY
            .with(&pzd_out::MAPPINGS, &prm.pzd_out)
            .with(&pzd_in::MAPPINGS, &prm.pzd_in))
    }
}

#[cfg(layout = "profidrive")]
mod profidrive {
    use crate::card::{Card, DpModule, PrmValues, Profibus, Profinet};
    use crate::layouts::profidrive::*;
    use crate::pkw::PkwKind;

    pub const CARD: Card = Card {
        name: "profidrive",
        fingerprint: FINGERPRINT,
        pkw: Some(PkwKind::Profidrive),
        control_word: false,
        status_word: false,
        pzd_out: &[],
        pzd_in: &[],
        status_of: None,
        profibus: Some(&PROFIBUS),
        profinet: Some(Profinet {
            device: &PN_DEVICE,
            shape: pn_shape,
        }),
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
                name: "PPO3: 2 PZD",
                config: &PPO3_CONFIG,
                pkw: false,
                pzd_words: 2,
            },
        ],
        user_prm_len: USER_PRM_LEN,
        decode_user_prm,
        diagnosis: None,
        gateway: None,
    };

    /// The fixture's PROFINET modules carry no PKW channel.
    fn pn_shape(module: &crate::gsdc_support::PnModule) -> crate::cyclic::Shape {
        super::pn_shape(module, false)
    }

    fn decode_user_prm(bytes: &[u8]) -> Result<PrmValues, PrmError> {
        let prm = crate::layouts::profidrive::decode_user_prm(bytes)?;
        Ok(PrmValues::EMPTY.with(&settings::MAPPINGS, &prm.settings))
    }
}

#[cfg(layout = "no_warnings")]
mod no_warnings {
    use crate::card::{Card, DpModule, PrmValues, Profibus, Profinet};
    use crate::layouts::no_warnings::*;
    use crate::pkw::PkwKind;

    pub const CARD: Card = Card {
        name: "no_warnings",
        fingerprint: FINGERPRINT,
        pkw: Some(PkwKind::PkeIndPwe),
        control_word: false,
        status_word: false,
        pzd_out: &pzd_out::MAPPINGS,
        pzd_in: &[],
        status_of: None,
        profibus: Some(&PROFIBUS),
        profinet: Some(Profinet {
            device: &PN_DEVICE,
            shape: pn_shape,
        }),
    };

    fn pn_shape(module: &crate::gsdc_support::PnModule) -> crate::cyclic::Shape {
        let pkw = [PKW_PZD2_IDENT, PKW_PZD6_IDENT].contains(&module.ident);
        super::pn_shape(module, pkw)
    }

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
        ],
        user_prm_len: USER_PRM_LEN,
        decode_user_prm,
        diagnosis: None,
        gateway: None,
    };

    fn decode_user_prm(bytes: &[u8]) -> Result<PrmValues, PrmError> {
        let prm = crate::layouts::no_warnings::decode_user_prm(bytes)?;
        Ok(PrmValues::EMPTY.with(&pzd_out::MAPPINGS, &prm.pzd_out))
    }
}

#[cfg(layout = "md810-gateway")]
mod md810_gateway {
    use crate::card::{
        Card, DiagBytes, DpModule, Gateway, NodeData, NodeEvent, NodeSetup, PrmValues, Profibus,
    };
    use crate::layouts::md810_gateway::gateway::{
        CanopenNetworkFaultCode, Diagnosis as NodeDiagnosis, NodeConfig, ParameterErrorCode,
        FIRST_NODE, NODES,
    };
    use crate::layouts::md810_gateway::*;

    pub const CARD: Card = Card {
        name: "md810-gateway",
        fingerprint: FINGERPRINT,
        pkw: None,
        control_word: false,
        status_word: false,
        pzd_out: &[],
        pzd_in: &[],
        status_of: None,
        profibus: Some(&PROFIBUS),
        profinet: None,
    };

    const PROFIBUS: Profibus = Profibus {
        ident_number: PROFIBUS_IDENT_NUMBER,
        modules: &[
            DpModule {
                name: "INPUT 1 word",
                config: &[gateway::INPUT_1_WORD_CONFIG],
                pkw: false,
                pzd_words: 1,
            },
            DpModule {
                name: "INPUT 2 words",
                config: &[gateway::INPUT_2_WORDS_CONFIG],
                pkw: false,
                pzd_words: 2,
            },
            DpModule {
                name: "INPUT 4 words",
                config: &[gateway::INPUT_4_WORDS_CONFIG],
                pkw: false,
                pzd_words: 4,
            },
            DpModule {
                name: "INPUT 8 words",
                config: &[gateway::INPUT_8_WORDS_CONFIG],
                pkw: false,
                pzd_words: 8,
            },
            DpModule {
                name: "INPUT 16 words",
                config: &[gateway::INPUT_16_WORDS_CONFIG],
                pkw: false,
                pzd_words: 16,
            },
            DpModule {
                name: "OUTPUT 1 word",
                config: &[gateway::OUTPUT_1_WORD_CONFIG],
                pkw: false,
                pzd_words: 1,
            },
            DpModule {
                name: "OUTPUT 2 words",
                config: &[gateway::OUTPUT_2_WORDS_CONFIG],
                pkw: false,
                pzd_words: 2,
            },
            DpModule {
                name: "OUTPUT 4 words",
                config: &[gateway::OUTPUT_4_WORDS_CONFIG],
                pkw: false,
                pzd_words: 4,
            },
            DpModule {
                name: "OUTPUT 8 words",
                config: &[gateway::OUTPUT_8_WORDS_CONFIG],
                pkw: false,
                pzd_words: 8,
            },
            DpModule {
                name: "OUTPUT 16 words",
                config: &[gateway::OUTPUT_16_WORDS_CONFIG],
                pkw: false,
                pzd_words: 16,
            },
        ],
        user_prm_len: USER_PRM_LEN,
        decode_user_prm,
        diagnosis: None,
        gateway: Some(Gateway {
            nodes,
            config_totals,
            diagnosis,
        }),
    };

    const NODE_COUNT_NAME: &str = "Number of CANopen slaves";
    const INPUT_WORDS_NAMES: [&str; NODES] = [
        "Slave 1 TPDO words",
        "Slave 2 TPDO words",
        "Slave 3 TPDO words",
        "Slave 4 TPDO words",
        "Slave 5 TPDO words",
        "Slave 6 TPDO words",
        "Slave 7 TPDO words",
        "Slave 8 TPDO words",
        "Slave 9 TPDO words",
        "Slave 10 TPDO words",
        "Slave 11 TPDO words",
        "Slave 12 TPDO words",
        "Slave 13 TPDO words",
        "Slave 14 TPDO words",
        "Slave 15 TPDO words",
        "Slave 16 TPDO words",
        "Slave 17 TPDO words",
        "Slave 18 TPDO words",
        "Slave 19 TPDO words",
        "Slave 20 TPDO words",
        "Slave 21 TPDO words",
        "Slave 22 TPDO words",
        "Slave 23 TPDO words",
        "Slave 24 TPDO words",
        "Slave 25 TPDO words",
        "Slave 26 TPDO words",
        "Slave 27 TPDO words",
        "Slave 28 TPDO words",
        "Slave 29 TPDO words",
        "Slave 30 TPDO words",
    ];
    const OUTPUT_WORDS_NAMES: [&str; NODES] = [
        "Slave 1 RPDO words",
        "Slave 2 RPDO words",
        "Slave 3 RPDO words",
        "Slave 4 RPDO words",
        "Slave 5 RPDO words",
        "Slave 6 RPDO words",
        "Slave 7 RPDO words",
        "Slave 8 RPDO words",
        "Slave 9 RPDO words",
        "Slave 10 RPDO words",
        "Slave 11 RPDO words",
        "Slave 12 RPDO words",
        "Slave 13 RPDO words",
        "Slave 14 RPDO words",
        "Slave 15 RPDO words",
        "Slave 16 RPDO words",
        "Slave 17 RPDO words",
        "Slave 18 RPDO words",
        "Slave 19 RPDO words",
        "Slave 20 RPDO words",
        "Slave 21 RPDO words",
        "Slave 22 RPDO words",
        "Slave 23 RPDO words",
        "Slave 24 RPDO words",
        "Slave 25 RPDO words",
        "Slave 26 RPDO words",
        "Slave 27 RPDO words",
        "Slave 28 RPDO words",
        "Slave 29 RPDO words",
        "Slave 30 RPDO words",
    ];

    fn decode_user_prm(bytes: &[u8]) -> Result<PrmValues, PrmError> {
        let config = crate::layouts::md810_gateway::decode_user_prm(bytes)?.nodes;
        let mut values = PrmValues::EMPTY.with_value(NODE_COUNT_NAME, config.node_count.into());
        for i in 0..NODES {
            values = values
                .with_value(INPUT_WORDS_NAMES[i], config.input_words[i].into())
                .with_value(OUTPUT_WORDS_NAMES[i], config.output_words[i].into());
        }
        Ok(values)
    }

    fn nodes(bytes: &[u8]) -> Result<NodeSetup, PrmError> {
        let config = NodeConfig::decode(bytes)?;
        // The totals the layout refuses are a parameter fault too.
        let totals = config.totals().map_err(|_| PrmError::NotAllowed {
            offset: 0,
            value: config.node_count.into(),
        })?;
        let mut in_use = [NodeData {
            node: 0,
            input_offset: 0,
            input_words: 0,
            output_offset: 0,
            output_words: 0,
        }; NODES];
        let count = usize::from(config.node_count);
        for (i, data) in in_use.iter_mut().enumerate().take(count) {
            let node = FIRST_NODE + i as u8;
            *data = NodeData {
                node,
                input_offset: config.input_offset(node).unwrap_or(0),
                input_words: config.input_words[i],
                output_offset: config.output_offset(node).unwrap_or(0),
                output_words: config.output_words[i],
            };
        }
        Ok(NodeSetup::new(
            totals.input_len(),
            totals.output_len(),
            &in_use[..count],
        ))
    }

    fn config_totals(config: &[u8]) -> Option<(usize, usize)> {
        let totals = gateway::config_totals(config).ok()?;
        Some((totals.input_len(), totals.output_len()))
    }

    fn diagnosis(event: NodeEvent) -> Option<DiagBytes> {
        let NodeEvent { kind, node, code } = event;
        let diagnosis = match kind {
            1 => NodeDiagnosis::ParameterError {
                node,
                code: ParameterErrorCode::from_value(code)?,
            },
            3 => NodeDiagnosis::CanopenNetworkFault {
                node,
                code: CanopenNetworkFaultCode::from_value(code)?,
            },
            4 => NodeDiagnosis::DriveReportsFault { node, code },
            _ => return None,
        };
        let block = diagnosis.encode();
        // The layout's decode checks the node against its node numbers.
        NodeDiagnosis::decode(block.as_bytes()).ok()?;
        Some(DiagBytes::new(block.as_bytes()))
    }
}

#[cfg(layout = "mv810-pnet02")]
mod mv810_pnet02 {
    use crate::card::{Card, Profinet};
    use crate::layouts::mv810_pnet02::*;
    use crate::pkw::PkwKind;

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
        profinet: Some(Profinet {
            device: &PN_DEVICE,
            shape: pn_shape,
        }),
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

    /// Every module but standard message 1 starts with the PKW channel.
    fn pn_shape(module: &crate::gsdc_support::PnModule) -> crate::cyclic::Shape {
        super::pn_shape(module, module.ident != TELEGRAM1_IDENT)
    }
}
