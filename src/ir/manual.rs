//! What the manual gives besides the telegram: the set-up it tells the user
//! to do on the drive and the card, and its worked examples of telegrams,
//! each with the manual's section.

use super::{Direction, Text};

/// A group of set-up steps: one table of the manual, or one of the ways it
/// describes.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct SetupGroup {
    /// The manual's section: `1.2`, `4`, `V-2-1`.
    pub section: String,
    pub title: Option<Text>,
    pub info: Option<Text>,
    pub steps: Vec<SetupStep>,
    pub note: Option<Text>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct SetupStep {
    pub target: SetupTarget,
    /// The manual's name of what is set.
    pub name: Option<Text>,
    /// The value to set, as the manual prints it.
    pub value: Option<Text>,
    /// The factory default the manual gives.
    pub default: Option<String>,
    pub meaning: Option<Text>,
    /// Settings and what each means, as the manual tables them.
    pub values: Vec<(Text, Text)>,
}

/// What a set-up step sets.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum SetupTarget {
    /// A drive parameter's address.
    Parameter(u16),
    /// A run of drive parameters, first and last address.
    Parameters(u16, u16),
    /// Something that is not a drive parameter: a DIP switch, an LED, an
    /// entry of the master's configuration.
    Item(Text),
    /// Nothing named: the step is what the manual says.
    None,
}

/// A telegram the manual prints, byte by byte, checked against the
/// description's telegrams when the description was loaded.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub struct Example {
    /// The manual's section: `1.4.2`.
    pub section: String,
    /// The module the telegram is of, as the description's files name it
    /// (a PPO type, a PROFINET module); `None`: the PKW words of every
    /// module that has them.
    pub module: Option<String>,
    pub direction: Direction,
    pub part: ExamplePart,
    /// The bytes as the manual prints them.
    pub printed: String,
    /// The bytes, word by word as printed.
    pub words: Vec<ExampleWord>,
    pub meaning: Text,
    /// The caption of the manual's figure that shows it.
    pub figure: Option<Text>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum ExamplePart {
    /// The module's whole telegram.
    Telegram,
    /// The module's PKW words, its first 8 bytes.
    Pkw,
}

/// A group of bytes as the manual prints it.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum ExampleWord {
    Bytes(Vec<u8>),
    /// A 16-bit word the manual names instead of printing (`errCode`), and
    /// the values it stands for.
    Named {
        name: String,
        values: Vec<u16>,
    },
}

impl Example {
    /// Every telegram the example stands for: one, or one per value of its
    /// named words (each combination, in the order of the values).
    pub fn instances(&self) -> Vec<Vec<u8>> {
        let mut telegrams = vec![Vec::new()];
        for word in &self.words {
            telegrams = match word {
                ExampleWord::Bytes(bytes) => telegrams
                    .into_iter()
                    .map(|mut t| {
                        t.extend_from_slice(bytes);
                        t
                    })
                    .collect(),
                ExampleWord::Named { values, .. } => telegrams
                    .iter()
                    .flat_map(|t| {
                        values.iter().map(move |v| {
                            let mut t = t.clone();
                            t.extend_from_slice(&v.to_be_bytes());
                            t
                        })
                    })
                    .collect(),
            };
        }
        telegrams
    }

    /// The bytes the example holds: a named word counts two.
    pub fn len(&self) -> usize {
        self.words
            .iter()
            .map(|w| match w {
                ExampleWord::Bytes(bytes) => bytes.len(),
                ExampleWord::Named { .. } => 2,
            })
            .sum()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_named_word_gives_one_telegram_per_value() {
        let example = Example {
            section: "1.4.2".into(),
            module: None,
            direction: Direction::In,
            part: ExamplePart::Pkw,
            printed: "70F0 errCode".into(),
            words: vec![
                ExampleWord::Bytes(vec![0x70, 0xF0]),
                ExampleWord::Named {
                    name: "errCode".into(),
                    values: vec![1, 0x0203],
                },
            ],
            meaning: Text::english("failed"),
            figure: None,
        };
        assert_eq!(example.len(), 4);
        assert_eq!(
            example.instances(),
            [vec![0x70, 0xF0, 0, 1], vec![0x70, 0xF0, 2, 3]]
        );
    }
}
