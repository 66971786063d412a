//! Each layout's [`Card`]: its constants under the names every description
//! shares.

use crate::card::{Card, Diagnosis, DpModule, PrmValues, Profibus};
use crate::gsdc_support::PrmError;
use crate::pkw::PkwKind;

/// The card of the description named `name`, if the firmware was built
/// for it.
pub fn card(name: &str) -> Option<&'static Card> {
    CARDS.iter().find(|c| c.name == name)
}

/// Every card the firmware is built for.
pub const CARDS: &[Card] = &[md810dp::CARD];

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
        profibus: Some(&PROFIBUS),
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
