//! GSDML schema versions.

use std::fmt;

/// A GSDML schema version. The minor part is a decimal fraction: V2.4 is
/// V2.40 and comes after V2.35 and before V2.41; V2.3 is V2.30.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Version {
    major: u8,
    hundredths: u8,
}

impl Version {
    /// The newest schema gsdc knows (`shared/reference/gsdml-xsd-v2.44`).
    pub const LATEST: Version = Version::new(2, 44);

    pub const fn new(major: u8, hundredths: u8) -> Self {
        Version { major, hundredths }
    }

    /// `V2.32`, `v2.4` or `2.25`.
    pub fn parse(text: &str) -> Option<Self> {
        let text = text.strip_prefix(['V', 'v']).unwrap_or(text);
        let (major, minor) = text.split_once('.')?;
        let all_digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
        if !all_digits(major) || !all_digits(minor) || minor.len() > 2 {
            return None;
        }
        let minor_value: u8 = minor.parse().ok()?;
        let hundredths = if minor.len() == 1 {
            minor_value * 10
        } else {
            minor_value
        };
        Some(Version::new(major.parse().ok()?, hundredths))
    }
}

impl Version {
    /// The version without its V, as a description writes it: `2.32`.
    pub fn number(self) -> String {
        self.to_string()[1..].to_string()
    }
}

impl fmt::Display for Version {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let Version { major, hundredths } = *self;
        if hundredths % 10 == 0 {
            write!(f, "V{major}.{}", hundredths / 10)
        } else {
            write!(f, "V{major}.{hundredths:02}")
        }
    }
}

/// A GSDML attribute or element gsdc writes only in files of the version
/// that a file at hand first shows it in, and later: no schema older than
/// V2.44 is at hand to say when it came, and gsdc writes nothing a version
/// lacks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Introduced {
    /// The attribute or element, as GSDML names it.
    pub name: &'static str,
    pub version: Version,
    /// The file that shows it in that version.
    pub shown_by: &'static str,
}

/// SEW's MOVI-C file, the first at hand of GSDML V2.34.
const MOVI_C: &str = "SEW's GSDML-V2.34-SEW-MOVI-C-Decentralized-Electronics-20200731-071447.xml";

/// Each port's `CheckMAUTypeDifferenceSupported`.
pub const CHECK_MAU_TYPE_DIFFERENCE: Introduced = Introduced {
    name: "CheckMAUTypeDifferenceSupported",
    version: Version::new(2, 33),
    shown_by: "Hilscher's GSDML-V2.33-HILSCHER-NETX_51-RE_PNS-20170216.xml",
};

/// The device access point's `AdaptsRealIdentification`.
pub const ADAPTS_REAL_IDENTIFICATION: Introduced = Introduced {
    name: "AdaptsRealIdentification",
    version: Version::new(2, 34),
    shown_by: MOVI_C,
};

/// The `PROFIenergy` element of a submodule, and with it the device access
/// point's `PROFIenergyASE_Supported` and the `EnergySaving` application
/// class, which MOVI-C's access points declare with it.
pub const PROFIENERGY: Introduced = Introduced {
    name: "PROFIenergy",
    version: Version::new(2, 34),
    shown_by: MOVI_C,
};

/// The device access point's `WebServer`.
pub const WEB_SERVER: Introduced = Introduced {
    name: "WebServer",
    version: Version::new(2, 34),
    shown_by: MOVI_C,
};
