//! Facts of the fieldbus specifications that more than one part of gsdc
//! needs (the lowering that keeps a description within them, the rules
//! that check a file against them, the emitters that write to them), each
//! in one place: FIELDBUS-NOTES names the sources. The IR, the readers and
//! the emitters depend on this module; it depends on none of them.

mod baud;
mod gsdml_version;

pub use baud::Baud;
pub use gsdml_version::Version as GsdmlVersion;
pub use gsdml_version::{
    Introduced, ADAPTS_REAL_IDENTIFICATION, CHECK_MAU_TYPE_DIFFERENCE, PROFIENERGY, WEB_SERVER,
};

/// The bytes a PROFIBUS-DP telegram carries at most: a slave's input, its
/// output, its parameter telegram, its diagnosis (IEC 61158-6-3).
pub const DP_MAX_TELEGRAM: usize = 244;

/// The user parameter bytes a Set_Prm telegram carries at most: the
/// telegram less its 7 standard bytes (GSD Max_User_Prm_Data_Len 0..237).
pub const DP_MAX_USER_PRM: usize = DP_MAX_TELEGRAM - 7;

/// The characters of a GSD name or text: a module, a parameter, a value
/// text, a diagnosis text (GSD specification V5.1, FIELDBUS-NOTES §3).
pub const GSD_NAME_LEN: usize = 32;

/// The columns of a line of a GSD gsdc writes (DESIGN.md, Outputs); vendor
/// files may be wider.
pub const GSD_LINE_WIDTH: usize = 80;

/// gsdc's GSD writes each value after its key padded to this many columns.
pub const GSD_KEY_WIDTH: usize = 28;

/// The DPV1 keywords came with GSD revision 3, Ident_Maintenance_supp with
/// revision 5 (comments of Siemens' own GSD files, SI028158, SI018133).
pub const DPV1_GSD_REVISION: u8 = 3;
pub const IM_GSD_REVISION: u8 = 5;

/// The bytes of a channel's block in a DP slave's diagnosis: the module,
/// the channel, the error type in bits 0 to 4 of the third (VIPA's IM 353
/// manual, "Channel-related diagnostic").
pub const DP_CHANNEL_DIAG_BYTES: u8 = 3;

/// The characters that reorder text on screen (Unicode's Bidi_Control):
/// a name with one could read differently from what a compiler or a
/// terminal sees.
pub fn is_bidi_control(c: char) -> bool {
    matches!(
        c,
        '\u{061C}' | '\u{200E}' | '\u{200F}' | '\u{202A}'..='\u{202E}' | '\u{2066}'..='\u{2069}'
    )
}

/// A device access point's `WebServer` as the PI schema's pattern allows
/// it, `https?://(:[0-9]+)?(/[a-zA-Z0-9\-._~:?#@%!$&'()*+,;=]+)*/?`: the
/// scheme and port of the device's web server and a path, without a host
/// (the engineering tool puts the device's address there; SEW's MOVI-C:
/// `http://:80/`).
pub fn is_gsdml_web_server(url: &str) -> bool {
    let Some(rest) = url
        .strip_prefix("https://")
        .or_else(|| url.strip_prefix("http://"))
    else {
        return false;
    };
    let path = match rest.strip_prefix(':') {
        Some(port) => {
            let digits = port.bytes().take_while(u8::is_ascii_digit).count();
            if digits == 0 {
                return false;
            }
            &port[digits..]
        }
        None => rest,
    };
    let Some(segments) = path.strip_prefix('/') else {
        return path.is_empty();
    };
    let path_char = |c: char| c.is_ascii_alphanumeric() || "-._~:?#@%!$&'()*+,;=".contains(c);
    let segments: Vec<&str> = segments.split('/').collect();
    // A trailing `/` leaves one empty segment at the end; no other may be.
    let (last, before) = segments.split_last().expect("split gives one at least");
    before
        .iter()
        .all(|s| !s.is_empty() && s.chars().all(path_char))
        && last.chars().all(path_char)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The limits here that are also GSD keywords' are the keyword
    /// schema's, which the loader and the checker take them from.
    #[test]
    fn the_limits_agree_with_the_gsd_keyword_schema() {
        let max = |keyword| crate::gsd::keyword_range(keyword).1 as usize;
        assert_eq!(DP_MAX_USER_PRM, max("Max_User_Prm_Data_Len"));
        assert_eq!(DP_MAX_TELEGRAM, max("Max_Input_Len"));
        assert_eq!(DP_MAX_TELEGRAM, max("Max_Output_Len"));
        assert_eq!(GSD_NAME_LEN, crate::gsd::keyword_max_len("Unit_Diag_Bit"));
    }

    /// Unicode 15's Bidi_Control property: 12 characters.
    #[test]
    fn the_bidi_controls_are_unicodes_twelve() {
        let all: Vec<char> = (0..=0x10FFFF)
            .filter_map(char::from_u32)
            .filter(|&c| is_bidi_control(c))
            .collect();
        assert_eq!(all.len(), 12);
        assert!(all.contains(&'\u{061C}'));
        assert!(!is_bidi_control('\u{2028}'));
    }

    /// The schema's pattern: scheme, an optional port, a path without a
    /// host; MOVI-C's and Leuze's values are among them.
    #[test]
    fn a_web_server_is_the_schemas_pattern() {
        for url in [
            "http://:80/",
            "http://",
            "https://:8443",
            "http://:80/index.html",
            "http://:80/a/b/",
        ] {
            assert!(is_gsdml_web_server(url), "{url}");
        }
        for url in [
            "ftp://:21/",
            "http://a/b/",
            "http:/",
            "http://:/",
            "http://host:80/",
            "http://:80//x",
            "http://:80/a b",
            "HTTP://",
        ] {
            assert!(!is_gsdml_web_server(url), "{url}");
        }
    }
}
