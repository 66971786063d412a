//! What the PROFIdrive channel's ids and error numbers mean, in gsdc's
//! words after the manuals (research/profidrive.md §1.2, §1.3, §1.5:
//! MICROMASTER 440 OI Tables 3-19 and 3-20, the MICROMASTER 4 PROFIBUS
//! board, the MASTERDRIVES Compendium, SINAMICS G120): `gsdc decode` and the
//! datasheet say them; the codec (`pkw_profidrive`) gives the numbers.

use super::pkw_profidrive::PkwErrorNumber;

/// English and Chinese (gsdc's translation).
pub(crate) type Meaning = (&'static str, &'static str);

/// The meaning of each request id of the profile, by id (0 to 9).
pub(crate) const REQUESTS: [Meaning; 10] = [
    ("no request", "无请求"),
    ("request the parameter value", "读参数值"),
    ("change the parameter value (word)", "修改参数值（单字）"),
    (
        "change the parameter value (double word)",
        "修改参数值（双字）",
    ),
    ("request a description element", "读参数描述元素"),
    ("change a description element", "修改参数描述元素"),
    ("request the parameter value (array)", "读参数值（数组）"),
    (
        "change the parameter value (array, word)",
        "修改参数值（数组，单字）",
    ),
    (
        "change the parameter value (array, double word)",
        "修改参数值（数组，双字）",
    ),
    ("request the number of array elements", "读数组元素个数"),
];

/// The meaning of each response id of the profile, by id (0 to 8).
pub(crate) const RESPONSES: [Meaning; 9] = [
    ("no response", "无应答"),
    ("the parameter value (word)", "传送参数值（单字）"),
    ("the parameter value (double word)", "传送参数值（双字）"),
    ("the description element", "传送描述元素"),
    (
        "the parameter value (array, word)",
        "传送参数值（数组，单字）",
    ),
    (
        "the parameter value (array, double word)",
        "传送参数值（数组，双字）",
    ),
    ("the number of array elements", "传送数组元素个数"),
    ("the request cannot be executed", "请求无法执行"),
    (
        "no master control: the PKW interface may not change parameters",
        "PKW 接口无主控权，不能修改参数",
    ),
];

/// The error numbers the Siemens, Danfoss and TR encoTRive manuals agree
/// on, as the codec names them.
pub(crate) const PROFILE_ERRORS: [(PkwErrorNumber, Meaning); 11] = [
    (
        PkwErrorNumber::ILLEGAL_PNU,
        ("impermissible parameter number (PNU)", "非法参数号（PNU）"),
    ),
    (
        PkwErrorNumber::NOT_CHANGEABLE,
        ("the parameter value cannot be changed", "参数值不可修改"),
    ),
    (
        PkwErrorNumber::LIMIT_EXCEEDED,
        ("low or high limit exceeded", "超出下限或上限"),
    ),
    (
        PkwErrorNumber::BAD_SUBINDEX,
        ("faulty subindex", "子索引错误"),
    ),
    (PkwErrorNumber::NO_ARRAY, ("no array", "参数不是数组")),
    (
        PkwErrorNumber::WRONG_TYPE,
        ("incorrect data type", "数据类型错误"),
    ),
    (
        PkwErrorNumber::SETTING_NOT_ALLOWED,
        (
            "setting not allowed (only resetting)",
            "不允许设置（只能复位）",
        ),
    ),
    (
        PkwErrorNumber::DESCRIPTION_NOT_CHANGEABLE,
        (
            "the description element cannot be changed",
            "描述元素不可修改",
        ),
    ),
    (
        PkwErrorNumber::NO_MASTER_CONTROL,
        ("no master control", "无主控权"),
    ),
    (
        PkwErrorNumber::KEY_WORD_MISSING,
        ("key word missing", "缺少关键字"),
    ),
    (
        PkwErrorNumber::OPERATING_STATE,
        (
            "the request cannot be processed in the operating state",
            "当前运行状态下无法处理请求",
        ),
    ),
];

/// Numbers some manuals give beyond those, with the manuals that give them:
/// a drive may mean something else by them.
const VENDOR_ERRORS: [(u16, &str); 19] = [
    (9, "description data not available (SINAMICS G120X, TR encoTRive, SINAMICS DCP; not every manual's)"),
    (15, "no text array available (MASTERDRIVES, SINAMICS G120X; not every manual's)"),
    (20, "illegal value (MASTERDRIVES, SINAMICS CU240B-2 and G120; not every manual's)"),
    (21, "response too long (MASTERDRIVES; not every manual's)"),
    (22, "non-admissible parameter address (MASTERDRIVES; not every manual's)"),
    (23, "non-admissible format (MASTERDRIVES; not every manual's)"),
    (24, "inconsistent number of values (MASTERDRIVES; not every manual's)"),
    (101, "parameter number currently deactivated (MICROMASTER 4, MASTERDRIVES, SINAMICS G120: device-specific)"),
    (102, "channel not wide enough (MICROMASTER 4, MASTERDRIVES, SINAMICS G120: device-specific)"),
    (103, "incorrect number of PKWs (MASTERDRIVES: device-specific)"),
    (104, "illegal parameter value (MICROMASTER 4, MASTERDRIVES, SINAMICS G120: device-specific)"),
    (105, "the parameter is indexed (MASTERDRIVES: device-specific)"),
    (106, "request not implemented (MICROMASTER 4, MASTERDRIVES, SINAMICS G120: device-specific)"),
    (107, "no write access with the controller enabled (SINAMICS CU240B-2 and G120C: device-specific)"),
    (134, "write access only for commissioning (SINAMICS G120: device-specific)"),
    (135, "know-how protection active (SINAMICS G120: device-specific)"),
    (200, "modified minimum not reached (MICROMASTER 4, SINAMICS CU240B-2 and G120: device-specific)"),
    (201, "modified maximum exceeded (MICROMASTER 4, SINAMICS CU240B-2 and G120: device-specific)"),
    (204, "the access authorization does not cover changing parameters (MICROMASTER 4, SINAMICS CU240B-2 and G120: device-specific)"),
];

/// A number none of the manuals gives.
const OWN_ERROR: &str = "not a number any of the manuals gives: the drive's own";

/// What `gsdc decode` says of an error number: the profile's meaning, or
/// what the manuals that give it mean, or that it is the drive's own.
pub(crate) fn error_text(number: PkwErrorNumber) -> &'static str {
    if let Some((_, (en, _))) = PROFILE_ERRORS.iter().find(|(n, _)| *n == number) {
        return en;
    }
    VENDOR_ERRORS
        .iter()
        .find(|(n, _)| *n == number.0)
        .map_or(OWN_ERROR, |(_, text)| text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_number_has_one_meaning() {
        let mut numbers: Vec<u16> = PROFILE_ERRORS
            .iter()
            .map(|(n, _)| n.0)
            .chain(VENDOR_ERRORS.iter().map(|(n, _)| *n))
            .collect();
        let count = numbers.len();
        numbers.sort_unstable();
        numbers.dedup();
        assert_eq!(numbers.len(), count);
    }

    #[test]
    fn error_texts_say_whose_a_number_is() {
        assert_eq!(error_text(PkwErrorNumber(17)), PROFILE_ERRORS[10].1 .0);
        assert_eq!(
            error_text(PkwErrorNumber(0)),
            "impermissible parameter number (PNU)"
        );
        assert!(error_text(PkwErrorNumber(106)).starts_with("request not implemented ("));
        assert_eq!(error_text(PkwErrorNumber(50)), OWN_ERROR);
    }
}
