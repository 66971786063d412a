//! What the PROFIdrive channel's ids and error numbers mean: `gsdc decode`
//! and the datasheet say them; the codec (`pkw_profidrive`) gives the
//! numbers, and gsdc's catalogue (`crate::i18n::codes`) the words.

use super::pkw_profidrive::PkwErrorNumber;
use crate::i18n::codes as c;
use crate::i18n::Phrase;

/// The meaning of each request id of the profile, by id (0 to 9).
pub(crate) const REQUESTS: [Phrase; 10] = [
    c::REQUEST_NONE,
    c::REQUEST_VALUE,
    c::CHANGE_VALUE_WORD,
    c::CHANGE_VALUE_DOUBLE_WORD,
    c::REQUEST_DESCRIPTION,
    c::CHANGE_DESCRIPTION,
    c::REQUEST_VALUE_ARRAY,
    c::CHANGE_VALUE_ARRAY_WORD,
    c::CHANGE_VALUE_ARRAY_DOUBLE_WORD,
    c::REQUEST_ARRAY_LENGTH,
];

/// The meaning of each response id of the profile, by id (0 to 8).
pub(crate) const RESPONSES: [Phrase; 9] = [
    c::RESPONSE_NONE,
    c::VALUE_WORD,
    c::VALUE_DOUBLE_WORD,
    c::DESCRIPTION_ELEMENT,
    c::VALUE_ARRAY_WORD,
    c::VALUE_ARRAY_DOUBLE_WORD,
    c::ARRAY_LENGTH,
    c::CANNOT_BE_EXECUTED,
    c::NO_MASTER_CONTROL_FOR_PKW,
];

/// The error numbers the Siemens, Danfoss and TR encoTRive manuals agree
/// on, as the codec names them.
pub(crate) const PROFILE_ERRORS: [(PkwErrorNumber, Phrase); 11] = [
    (PkwErrorNumber::ILLEGAL_PNU, c::ILLEGAL_PNU),
    (PkwErrorNumber::NOT_CHANGEABLE, c::NOT_CHANGEABLE),
    (PkwErrorNumber::LIMIT_EXCEEDED, c::LIMIT_EXCEEDED),
    (PkwErrorNumber::BAD_SUBINDEX, c::BAD_SUBINDEX),
    (PkwErrorNumber::NO_ARRAY, c::NO_ARRAY),
    (PkwErrorNumber::WRONG_TYPE, c::WRONG_TYPE),
    (PkwErrorNumber::SETTING_NOT_ALLOWED, c::SETTING_NOT_ALLOWED),
    (
        PkwErrorNumber::DESCRIPTION_NOT_CHANGEABLE,
        c::DESCRIPTION_NOT_CHANGEABLE,
    ),
    (PkwErrorNumber::NO_MASTER_CONTROL, c::NO_MASTER_CONTROL),
    (PkwErrorNumber::KEY_WORD_MISSING, c::KEY_WORD_MISSING),
    (PkwErrorNumber::OPERATING_STATE, c::OPERATING_STATE),
];
