//! PROFIsafe's two description CRCs (`F_ParamDescCRC`,
//! `F_IO_StructureDescCRC`), which gsdc cannot compute (PI's algorithm is
//! for its members): a description states the values it was given and
//! `of`, gsdc's fingerprint of what they were given for, so a module
//! edited since never ships with stale CRCs. The same for a GSDML safety
//! module and a GSD's PROFIsafe module.

use super::checks::Checker;
use crate::description::safety::DescriptionCrcs;
use crate::diag::Diagnostic;
use crate::i18n::Phrase;
use toml::Spanned;

/// Which file carries the CRCs, and so who computes them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum CrcFile {
    /// PI's GSDML checker reports them.
    Gsdml,
    /// A GSD's: gsdc knows no public tool that computes them.
    Gsd,
}

impl CrcFile {
    /// What a placeholder value is not.
    fn not_yet(self) -> &'static str {
        match self {
            CrcFile::Gsdml => {
                "the GSDML's F_ParamDescCRC and F_IO_StructureDescCRC are not PI's checker's"
            }
            CrcFile::Gsd => {
                "the GSD's F_ParamDescCRC and F_IO_StructureDescCRC are not computed for the module"
            }
        }
    }

    /// How the user gets the values, as the help says it.
    fn source(self) -> &'static str {
        match self {
            CrcFile::Gsdml => "run PI's GSDML checker on the built file, then state the CRCs it reports",
            CrcFile::Gsd => "have the two CRCs computed for the built module by a tool that has PI's algorithm, then state them",
        }
    }

    /// Why a placeholder is one, in every generated file.
    fn reason(self) -> Phrase {
        match self {
            CrcFile::Gsdml => crate::i18n::files::NOT_COMPUTED_BY_PI_CHECKER,
            CrcFile::Gsd => crate::i18n::files::NOT_COMPUTED_FOR_THE_MODULE,
        }
    }
}

/// The stated CRCs, when they were given for what the module now is
/// (`now`, its fingerprint): E128 when the fingerprint they were given for
/// (`of`) is another or missing; W109 while they are placeholders.
pub(crate) fn pinned(
    cx: &mut Checker,
    given: &Spanned<DescriptionCrcs>,
    now: &str,
    (what, file): (&str, CrcFile),
) -> Option<()> {
    let crcs = given.get_ref();
    if crcs.placeholder {
        let value = format!(
            "F_ParamDescCRC {}, F_IO_StructureDescCRC {}",
            crcs.f_param_desc.get_ref(),
            crcs.f_io_structure_desc.get_ref()
        );
        cx.placeholder(
            Diagnostic::warning(
                "W109",
                format!("{what} are placeholders: {}", file.not_yet()),
            )
            .at(given.span())
            .label("placeholder")
            .help(format!(
                "{} with of = \"{now}\" and without placeholder",
                file.source()
            )),
            (what, value),
            file.reason(),
        );
        return Some(());
    }
    let stated = crcs.of.as_ref();
    if stated.is_some_and(|of| *of.get_ref() == now) {
        return Some(());
    }
    let was = stated.map_or_else(
        || "for no stated fingerprint (`of`)".to_string(),
        |of| format!("for \"{}\"", of.get_ref()),
    );
    cx.push(
        Diagnostic::error(
            "E128",
            format!("{what} were given {was}, but the F-parameters and IO data are now \"{now}\""),
        )
        .at(stated.map_or_else(|| given.span(), Spanned::span))
        .label("stale or unpinned CRCs")
        .help(format!("gsdc cannot compute PROFIsafe's description CRCs: build with `placeholder = true`, {} with of = \"{now}\"", file.source())),
    );
    None
}
