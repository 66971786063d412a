//! The standard PPO types of PROFIdrive and the config bytes a PPO module
//! carries in Chk_Cfg.

use crate::ir::profibus::MAX_WORDS_PER_IDENTIFIER;
use crate::ir::telegram::PKW_WORDS;
use crate::ir::Layout;

/// Config identifier bits (IEC 61158 / EN 50170): bit 7 consistency over
/// the whole length, bit 6 words, bits 5-4 direction (11 = in and out),
/// bits 3-0 length - 1.
const CONSISTENT_WORDS_IN_OUT: u8 = 0b1111_0000;

/// PPO1 `0xF3,0xF1`: the PKW as 4 consistent words in and out, then the PZD
/// as one consistent block in and out. Lowering keeps `pzd_words` within
/// 1..=16.
pub(crate) fn config_bytes(layout: Layout) -> Vec<u8> {
    let pkw = layout.pkw.then(|| identifier(PKW_WORDS));
    pkw.into_iter()
        .chain(std::iter::once(identifier(layout.pzd_words)))
        .collect()
}

fn identifier(words: u8) -> u8 {
    debug_assert!((1..=MAX_WORDS_PER_IDENTIFIER).contains(&words));
    CONSISTENT_WORDS_IN_OUT | (words - 1)
}

/// The standard PPO types: (PKW, PZD words). PPO5's PZD count may differ per
/// device (MD810 has 12), so the description gives it.
pub(crate) fn ppo_layout(ppo: u8, ppo5_pzd_words: u8) -> Option<Layout> {
    let (pkw, pzd_words) = match ppo {
        1 => (true, 2),
        2 => (true, 6),
        3 => (false, 2),
        4 => (false, 6),
        5 => (true, ppo5_pzd_words),
        _ => return None,
    };
    Some(Layout::new(pkw, pzd_words))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn config(ppo: u8, ppo5: u8) -> Vec<u8> {
        config_bytes(ppo_layout(ppo, ppo5).unwrap())
    }

    #[test]
    fn ppo_config_bytes_match_the_profidrive_table() {
        assert_eq!(config(1, 12), [0xF3, 0xF1]);
        assert_eq!(config(2, 12), [0xF3, 0xF5]);
        assert_eq!(config(3, 12), [0xF1]);
        assert_eq!(config(4, 12), [0xF5]);
        assert_eq!(config(5, 12), [0xF3, 0xFB]);
        assert_eq!(config(5, 10), [0xF3, 0xF9]);
    }

    #[test]
    fn ppo_lengths_in_bytes() {
        let bytes = |ppo| ppo_layout(ppo, 12).unwrap().bytes();
        assert_eq!(
            [bytes(1), bytes(2), bytes(3), bytes(4), bytes(5)],
            [12, 20, 4, 12, 32]
        );
        assert!(ppo_layout(6, 12).is_none());
    }
}
