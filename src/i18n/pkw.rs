//! What the PKW channels' codes mean, as the datasheet and `gsdc decode`
//! say it (decode in English): PROFIdrive's request and response ids and
//! error numbers, in gsdc's words after the manuals (MICROMASTER 440 OI
//! Tables 3-19 and 3-20, the MICROMASTER 4 PROFIBUS board, the MASTERDRIVES
//! Compendium, SINAMICS G120; docs/wire-format.md gives the pages; the
//! German in Siemens' German terms: Auftragskennung, Antwortkennung,
//! Bedienhoheit), and the error codes of MD810's channel, which are
//! Modbus's.

use super::phrases;

phrases! {
    REQUEST_NONE = { en: "no request", zh: "无请求", de: "kein Auftrag" };
    REQUEST_VALUE = { en: "request the parameter value", zh: "读参数值", de: "Parameterwert anfordern" };
    CHANGE_VALUE_WORD = {
        en: "change the parameter value (word)",
        zh: "修改参数值（单字）",
        de: "Parameterwert ändern (Wort)",
    };
    CHANGE_VALUE_DOUBLE_WORD = {
        en: "change the parameter value (double word)",
        zh: "修改参数值（双字）",
        de: "Parameterwert ändern (Doppelwort)",
    };
    REQUEST_DESCRIPTION = {
        en: "request a description element",
        zh: "读参数描述元素",
        de: "Beschreibungselement anfordern",
    };
    CHANGE_DESCRIPTION = {
        en: "change a description element",
        zh: "修改参数描述元素",
        de: "Beschreibungselement ändern",
    };
    REQUEST_VALUE_ARRAY = {
        en: "request the parameter value (array)",
        zh: "读参数值（数组）",
        de: "Parameterwert anfordern (Array)",
    };
    CHANGE_VALUE_ARRAY_WORD = {
        en: "change the parameter value (array, word)",
        zh: "修改参数值（数组，单字）",
        de: "Parameterwert ändern (Array, Wort)",
    };
    CHANGE_VALUE_ARRAY_DOUBLE_WORD = {
        en: "change the parameter value (array, double word)",
        zh: "修改参数值（数组，双字）",
        de: "Parameterwert ändern (Array, Doppelwort)",
    };
    REQUEST_ARRAY_LENGTH = {
        en: "request the number of array elements",
        zh: "读数组元素个数",
        de: "Anzahl der Arrayelemente anfordern",
    };

    RESPONSE_NONE = { en: "no response", zh: "无应答", de: "keine Antwort" };
    VALUE_WORD = { en: "the parameter value (word)", zh: "传送参数值（单字）", de: "Parameterwert übertragen (Wort)" };
    VALUE_DOUBLE_WORD = {
        en: "the parameter value (double word)",
        zh: "传送参数值（双字）",
        de: "Parameterwert übertragen (Doppelwort)",
    };
    DESCRIPTION_ELEMENT = {
        en: "the description element",
        zh: "传送描述元素",
        de: "Beschreibungselement übertragen",
    };
    VALUE_ARRAY_WORD = {
        en: "the parameter value (array, word)",
        zh: "传送参数值（数组，单字）",
        de: "Parameterwert übertragen (Array, Wort)",
    };
    VALUE_ARRAY_DOUBLE_WORD = {
        en: "the parameter value (array, double word)",
        zh: "传送参数值（数组，双字）",
        de: "Parameterwert übertragen (Array, Doppelwort)",
    };
    ARRAY_LENGTH = {
        en: "the number of array elements",
        zh: "传送数组元素个数",
        de: "Anzahl der Arrayelemente übertragen",
    };
    CANNOT_BE_EXECUTED = {
        en: "the request cannot be executed",
        zh: "请求无法执行",
        de: "Auftrag nicht ausführbar",
    };
    NO_MASTER_CONTROL_FOR_PKW = {
        en: "no master control: the PKW interface may not change parameters",
        zh: "PKW 接口无主控权，不能修改参数",
        de: "keine Bedienhoheit: die PKW-Schnittstelle darf keine Parameter ändern",
    };

    ILLEGAL_PNU = {
        en: "impermissible parameter number (PNU)",
        zh: "非法参数号（PNU）",
        de: "unzulässige Parameternummer (PNU)",
    };
    NOT_CHANGEABLE = {
        en: "the parameter value cannot be changed",
        zh: "参数值不可修改",
        de: "Parameterwert nicht änderbar",
    };
    LIMIT_EXCEEDED = {
        en: "low or high limit exceeded",
        zh: "超出下限或上限",
        de: "untere oder obere Wertgrenze überschritten",
    };
    BAD_SUBINDEX = { en: "faulty subindex", zh: "子索引错误", de: "fehlerhafter Subindex" };
    NO_ARRAY = { en: "no array", zh: "参数不是数组", de: "kein Array" };
    WRONG_TYPE = { en: "incorrect data type", zh: "数据类型错误", de: "falscher Datentyp" };
    SETTING_NOT_ALLOWED = {
        en: "setting not allowed (only resetting)",
        zh: "不允许设置（只能复位）",
        de: "Setzen nicht erlaubt (nur Rücksetzen)",
    };
    DESCRIPTION_NOT_CHANGEABLE = {
        en: "the description element cannot be changed",
        zh: "描述元素不可修改",
        de: "Beschreibungselement nicht änderbar",
    };
    NO_MASTER_CONTROL = { en: "no master control", zh: "无主控权", de: "keine Bedienhoheit" };
    KEY_WORD_MISSING = { en: "key word missing", zh: "缺少关键字", de: "Schlüsselwort fehlt" };
    OPERATING_STATE = {
        en: "the request cannot be processed in the operating state",
        zh: "当前运行状态下无法处理请求",
        de: "Auftrag wegen Betriebszustand nicht ausführbar",
    };

    /// MD810's error codes (manual 1.4.1: Modbus's).
    ILLEGAL_COMMAND = { en: "illegal command", zh: "非法命令", de: "unzulässiger Befehl" };
    ILLEGAL_ADDRESS = { en: "illegal address", zh: "非法地址", de: "unzulässige Adresse" };
    ILLEGAL_DATA = { en: "illegal data", zh: "非法数据", de: "unzulässige Daten" };
    OTHER_ERROR = { en: "other error", zh: "其它错误", de: "sonstiger Fehler" };
}
