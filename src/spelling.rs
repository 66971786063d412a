//! Suggestions for misspelt names: a description key, a GSD keyword, a
//! path under `[choices]`.

/// The most edits a suggestion may be away from what was written.
const MAX_EDITS: usize = 2;

/// The candidate at most two edits away from `word` (the nearest; the first
/// in `candidates` among equals), compared as given.
pub fn closest<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    candidates
        .into_iter()
        .filter_map(|c| edit_distance(word, c).map(|d| (d, c)))
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}

/// Levenshtein distance over characters, two rows; `None` as soon as it
/// must exceed [`MAX_EDITS`].
fn edit_distance(a: &str, b: &str) -> Option<usize> {
    // Most candidates differ in length by more than that: no allocation.
    if a.chars().count().abs_diff(b.chars().count()) > MAX_EDITS {
        return None;
    }
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    let mut cur = vec![0; b.len() + 1];
    for (i, &ca) in a.iter().enumerate() {
        cur[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let substitute = prev[j] + usize::from(ca != cb);
            cur[j + 1] = substitute.min(prev[j + 1] + 1).min(cur[j] + 1);
        }
        // A row never shrinks below its minimum further down.
        if cur.iter().min().is_some_and(|&m| m > MAX_EDITS) {
            return None;
        }
        std::mem::swap(&mut prev, &mut cur);
    }
    Some(prev[b.len()]).filter(|&d| d <= MAX_EDITS)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edit_distance_counts_edits_up_to_two() {
        assert_eq!(
            edit_distance("min_slave_interval", "min_slave_intervall"),
            Some(1)
        );
        assert_eq!(edit_distance("dns_name", "dns_nmae"), Some(2));
        assert_eq!(edit_distance("abc", "abc"), Some(0));
        assert_eq!(edit_distance("abc", "xyz"), None);
        assert_eq!(edit_distance("vendor_name", "model_name"), None);
        assert_eq!(edit_distance("", "abc"), None);
    }

    #[test]
    fn the_nearest_candidate_is_suggested() {
        let keys = ["baud_rates", "dpv1", "diagnosis"];
        assert_eq!(closest("baud_rate", keys), Some("baud_rates"));
        assert_eq!(closest("dvp1", keys), Some("dpv1"));
        assert_eq!(closest("station", keys), None);
    }
}
