//! What the PROFIdrive channel's ids and error numbers mean, in gsdc's
//! words after the manuals (MICROMASTER 440 OI Tables 3-19 and 3-20, the
//! MICROMASTER 4 PROFIBUS board, the MASTERDRIVES Compendium, SINAMICS
//! G120; docs/wire-format.md gives the pages): `gsdc decode` and the
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
