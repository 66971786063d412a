//! GSDML schema versions and the file naming convention
//! `GSDML-V<x.yy>-<Vendor>-<Family>-<yyyymmdd>[-hhmmss].xml`.

pub use crate::spec::GsdmlVersion as Version;

/// The schema version of `xsi:schemaLocation`, read from the file name of
/// its schema: `... ..\xsd\GSDML-DeviceProfile-V2.32.xsd`.
pub fn from_schema_location(location: &str) -> Option<Version> {
    let schema = location.split_whitespace().last()?;
    let file = schema.rsplit(['/', '\\']).next()?.to_ascii_lowercase();
    let version = file
        .strip_prefix("gsdml-deviceprofile-")?
        .strip_suffix(".xsd")?;
    Version::parse(version)
}

/// The parts of a conventional GSDML file name.
#[derive(Debug, PartialEq, Eq)]
#[non_exhaustive]
pub struct FileName<'n> {
    pub version: Version,
    pub vendor_and_family: &'n str,
    pub date: &'n str,
    pub time: Option<&'n str>,
}

/// What a Windows file name cannot hold, and so neither the vendor nor the
/// family of a GSDML file name.
pub const WINDOWS_FORBIDDEN: [char; 9] = ['<', '>', ':', '"', '/', '\\', '|', '?', '*'];

/// Splits a file name by the convention; the error says what is wrong.
pub fn parse_file_name(name: &str) -> Result<FileName<'_>, &'static str> {
    let rest = name
        .strip_prefix("GSDML-")
        .ok_or("it does not start with \"GSDML-\"")?;
    let stem = rest
        .len()
        .checked_sub(4)
        .filter(|&n| rest[n..].eq_ignore_ascii_case(".xml"))
        .map(|n| &rest[..n])
        .ok_or("it does not end with \".xml\"")?;
    let (version, rest) = stem
        .split_once('-')
        .ok_or("it has no version, vendor, family and date")?;
    let version = version
        .strip_prefix('V')
        .and_then(Version::parse)
        .ok_or("the version is not written V<x.yy>")?;
    let (rest, last) = rest.rsplit_once('-').ok_or("it has no release date")?;
    let (vendor_and_family, date, time) = match rest.rsplit_once('-') {
        Some((before, date)) if is_date(date) && is_time(last) => (before, date, Some(last)),
        _ if is_date(last) => (rest, last, None),
        _ => {
            return Err("it does not end with a release date yyyymmdd and an optional time hhmmss")
        }
    };
    let (vendor, family) = vendor_and_family
        .split_once('-')
        .ok_or("it lacks the vendor or the device family")?;
    if vendor.is_empty() || family.is_empty() {
        return Err("it lacks the vendor or the device family");
    }
    if vendor_and_family.contains(WINDOWS_FORBIDDEN) {
        return Err("the vendor or family contains a character Windows forbids in file names");
    }
    Ok(FileName {
        version,
        vendor_and_family,
        date,
        time,
    })
}

fn digits(text: &str, count: usize) -> Option<Vec<u32>> {
    (text.len() == count && text.bytes().all(|b| b.is_ascii_digit()))
        .then(|| text.bytes().map(|b| u32::from(b - b'0')).collect())
}

fn is_date(text: &str) -> bool {
    let Some(d) = digits(text, 8) else {
        return false;
    };
    let year = d[0] * 1000 + d[1] * 100 + d[2] * 10 + d[3];
    let (month, day) = (d[4] * 10 + d[5], d[6] * 10 + d[7]);
    let leap = year % 4 == 0 && (year % 100 != 0 || year % 400 == 0);
    let days = match month {
        1 | 3 | 5 | 7 | 8 | 10 | 12 => 31,
        4 | 6 | 9 | 11 => 30,
        2 if leap => 29,
        2 => 28,
        _ => return false,
    };
    (1..=days).contains(&day)
}

/// `hhmmss`; the GSDML specification lets `hh` run up to 24.
fn is_time(text: &str) -> bool {
    digits(text, 6)
        .is_some_and(|d| d[0] * 10 + d[1] <= 24 && d[2] * 10 + d[3] <= 59 && d[4] * 10 + d[5] <= 59)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn versions_order_as_decimal_fractions() {
        let v = |s| Version::parse(s).unwrap();
        assert!(v("V2.25") < v("V2.3") && v("V2.3") < v("V2.31") && v("V2.35") < v("V2.4"));
        assert_eq!(v("V2.4"), v("V2.40"));
        assert_eq!(v("2.4").to_string(), "V2.4");
        assert_eq!(v("V2.25").to_string(), "V2.25");
        assert_eq!(Version::parse("V2.321"), None);
        assert_eq!(Version::parse("V2"), None);
    }

    #[test]
    fn schema_location_gives_version() {
        let loc = "http://www.profibus.com/GSDML/2003/11/DeviceProfile ..\\XSD\\GSDML-DeviceProfile-v2.34.xsd";
        assert_eq!(from_schema_location(loc), Version::parse("V2.34"));
        assert_eq!(from_schema_location("ns GSDML-DeviceProfile.xsd"), None);
    }

    #[test]
    fn file_names_split_with_dashes_in_family_and_time() {
        let f =
            parse_file_name("GSDML-V2.34-SEW-MOVI-C-Decentralized-Electronics-20200731-071447.xml")
                .unwrap();
        assert_eq!(f.version, Version::new(2, 34));
        assert_eq!(f.vendor_and_family, "SEW-MOVI-C-Decentralized-Electronics");
        assert_eq!((f.date, f.time), ("20200731", Some("071447")));
        let f = parse_file_name("GSDML-V2.4-RT-Labs-P-Net-Sample-App-20210507.xml").unwrap();
        assert_eq!((f.date, f.time), ("20210507", None));
        assert!(parse_file_name("GSDML-V2.4-Vendor-20210507.xml").is_err());
        assert!(parse_file_name("GSDML-V2.4-A-B-20210230.xml").is_err());
        assert!(parse_file_name("device.xml").is_err());
    }
}
