//! The PROFIBUS baud rates.

/// The PROFIBUS baud rates, as the `<baud>_supp` and `MaxTsdr_<baud>` family
/// of keywords spells them.
/// Descriptions key their MaxTsdr values by the same spelling.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Deserialize)]
#[non_exhaustive]
pub enum Baud {
    #[serde(rename = "9.6")]
    B9k6,
    #[serde(rename = "19.2")]
    B19k2,
    #[serde(rename = "31.25")]
    B31k25,
    #[serde(rename = "45.45")]
    B45k45,
    #[serde(rename = "93.75")]
    B93k75,
    #[serde(rename = "187.5")]
    B187k5,
    #[serde(rename = "500")]
    B500k,
    #[serde(rename = "1.5M")]
    B1M5,
    #[serde(rename = "3M")]
    B3M,
    #[serde(rename = "6M")]
    B6M,
    #[serde(rename = "12M")]
    B12M,
}

impl Baud {
    pub const ALL: [Baud; 11] = [
        Baud::B9k6,
        Baud::B19k2,
        Baud::B31k25,
        Baud::B45k45,
        Baud::B93k75,
        Baud::B187k5,
        Baud::B500k,
        Baud::B1M5,
        Baud::B3M,
        Baud::B6M,
        Baud::B12M,
    ];

    /// The spelling inside keywords: `9.6`, `1.5M`, `12M`.
    pub fn as_str(self) -> &'static str {
        match self {
            Baud::B9k6 => "9.6",
            Baud::B19k2 => "19.2",
            Baud::B31k25 => "31.25",
            Baud::B45k45 => "45.45",
            Baud::B93k75 => "93.75",
            Baud::B187k5 => "187.5",
            Baud::B500k => "500",
            Baud::B1M5 => "1.5M",
            Baud::B3M => "3M",
            Baud::B6M => "6M",
            Baud::B12M => "12M",
        }
    }

    pub fn bits_per_second(self) -> u32 {
        match self {
            Baud::B9k6 => 9_600,
            Baud::B19k2 => 19_200,
            Baud::B31k25 => 31_250,
            Baud::B45k45 => 45_450,
            Baud::B93k75 => 93_750,
            Baud::B187k5 => 187_500,
            Baud::B500k => 500_000,
            Baud::B1M5 => 1_500_000,
            Baud::B3M => 3_000_000,
            Baud::B6M => 6_000_000,
            Baud::B12M => 12_000_000,
        }
    }

    /// Case-insensitive: `1.5m` is `1.5M`.
    pub fn parse(s: &str) -> Option<Baud> {
        Baud::ALL
            .into_iter()
            .find(|b| b.as_str().eq_ignore_ascii_case(s))
    }
}
