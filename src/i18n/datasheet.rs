//! gsdc's words on the datasheet (`gsdc doc`): headings, table heads and
//! captions, sentences and the words of diagrams, by section. German in the
//! terms of Siemens' German drive manuals (Prozessdaten, Parameterkanal,
//! Steuerwort, Zustandswort, Parametriertelegramm, Parameterdatensatz).

use super::phrases;
use std::fmt::Display;

phrases! {
    // -----------------------------------------------------------------------
    // Shared by the sections

    title(vendor: &str, model: &str) = {
        en: "{vendor} {model}: fieldbus interface",
        zh: "{vendor} {model}：现场总线接口",
        de: "{vendor} {model}: Feldbusschnittstelle",
    };
    table_label(n: usize) = { en: "Table {n}.", zh: "表 {n}", de: "Tabelle {n}:" };
    figure_label(n: usize) = { en: "Figure {n}.", zh: "图 {n}", de: "Bild {n}:" };
    /// `a, b`: between the items of a list.
    LIST_SEPARATOR = { en: ", ", zh: "、", de: same };
    /// `a, b and c`: before the last item.
    LIST_LAST_SEPARATOR = { en: " and ", zh: "、", de: " und " };
    range(min: impl Display, max: impl Display) = {
        en: "{min} to {max}",
        zh: "{min}～{max}",
        de: "{min} bis {max}",
    };
    address_range(min: u16, max: u16) = {
        en: "{min} to {max} (0x{min:04X} to 0x{max:04X})",
        zh: "{min}～{max}（0x{min:04X}～0x{max:04X}）",
        de: "{min} bis {max} (0x{min:04X} bis 0x{max:04X})",
    };
    one_of_choices(count: usize, caption: &str) = {
        en: "one of {count} choices ({caption})",
        zh: "{count} 个选项之一（{caption}）",
        de: "einer von {count} Auswahlwerten ({caption})",
    };
    choices_of(name: &str) = {
        en: "choices of {name}",
        zh: "{name}的选项",
        de: "Auswahlwerte von {name}",
    };
    PLACEHOLDER_NOT_ASSIGNED = {
        en: "placeholder, not assigned by PI",
        zh: "占位值，非 PI 分配",
        de: "Platzhalter, nicht von PI vergeben",
    };
    PLACEHOLDER = { en: "placeholder", zh: "占位值", de: "Platzhalter" };
    OWN_CHOICE = {
        en: "the description's own choice",
        zh: "描述文件自行确定",
        de: "eigene Wahl der Beschreibung",
    };
    GSDC_NUMBERING = { en: "gsdc's numbering", zh: "gsdc 编号", de: "Nummerierung von gsdc" };
    REQUIRED_OF_FIRMWARE = {
        en: "required of the firmware",
        zh: "固件须支持",
        de: "von der Firmware gefordert",
    };
    GSDC_DEFAULT = { en: "gsdc's default", zh: "gsdc 默认值", de: "Vorgabe von gsdc" };
    bit(n: impl Display) = { en: "bit {n}", zh: "Bit{n}", de: "Bit {n}" };
    bits(first: impl Display, last: impl Display) = {
        en: "bits {first}-{last}",
        zh: "Bit{first}-Bit{last}",
        de: "Bit {first}-{last}",
    };
    byte(n: impl Display) = { en: "byte {n}", zh: "字节 {n}", de: "Byte {n}" };
    bytes(first: impl Display, last: impl Display) = {
        en: "bytes {first}-{last}",
        zh: "字节 {first}-{last}",
        de: "Byte {first}-{last}",
    };
    bytes_count(n: impl Display) = { en: "{n} bytes", zh: "{n} 字节", de: "{n} Byte" };
    ONE_BYTE = { en: "1 byte", zh: "1 字节", de: "1 Byte" };
    /// Where a Bit or BitArea is: `byte 0, bits 4-6`.
    byte_bits(byte: &str, bits: &str) = { en: "{byte}, {bits}", zh: "{byte}，{bits}", de: same };
    MEANING = { en: "Meaning", zh: "含义", de: "Bedeutung" };
    VALUE = { en: "Value", zh: "值", de: "Wert" };
    NAME = { en: "Name", zh: "名称", de: same };
    BYTES = { en: "Bytes", zh: "字节", de: "Byte" };
    HEX = { en: "Hex", zh: "十六进制", de: same };
    WORD = { en: "Word", zh: "字", de: "Wort" };
    MODULE = { en: "Module", zh: "模块", de: "Modul" };
    DIAGNOSIS = { en: "Diagnosis", zh: "诊断", de: "Diagnose" };
    CHANNEL_DIAGNOSIS = { en: "PROFINET channel diagnosis", zh: "PROFINET 通道诊断", de: "PROFINET-Kanaldiagnose" };
    CHANNEL_DIAGNOSIS_INTRO = {
        en: "The error types the card reports as channel diagnosis, and what the engineering tool shows for each; a profile's error types (0x9000 and up) are in the profile's API.",
        zh: "扩展卡以通道诊断报告的错误类型，以及工程工具为每种错误显示的内容；行规的错误类型（0x9000 及以上）属于该行规的 API。",
        de: "Die Fehlertypen, die die Karte als Kanaldiagnose meldet, und was das Engineering-Tool zu jedem anzeigt; die Fehlertypen eines Profils (ab 0x9000) liegen in der API des Profils.",
    };
    ERROR_TYPE = { en: "Error type", zh: "错误类型", de: "Fehlertyp" };
    DP_CHANNEL_DIAGNOSIS = { en: "PROFIBUS channel diagnosis", zh: "PROFIBUS 通道诊断", de: "PROFIBUS-Kanaldiagnose" };
    F_PARAMETERS_INTRO = {
        en: "When a PROFIsafe module is plugged, its F-parameters follow User_Prm_Data: the F-host sends them, and the card's PROFIsafe layer checks them. The GSD states the module's two description CRCs with them.",
        zh: "插入 PROFIsafe 模块时，其 F 参数紧随 User_Prm_Data 之后：由 F 主站发送，由扩展卡的 PROFIsafe 层检查。GSD 随之给出该模块的两个描述 CRC。",
        de: "Ist ein PROFIsafe-Modul gesteckt, folgen seine F-Parameter auf User_Prm_Data: Der F-Host sendet sie, die PROFIsafe-Schicht der Karte prüft sie. Die GSD nennt mit ihnen die beiden Beschreibungs-CRCs des Moduls.",
    };
    DP_DIAGNOSIS_TYPES = { en: "PROFIBUS diagnosis types", zh: "PROFIBUS 诊断类型", de: "PROFIBUS-Diagnosetypen" };
    DP_DIAGNOSIS_TYPES_INTRO = {
        en: "The texts the engineering tool shows for a device-related diagnosis of each type the GSD names (UnitDiagType), bits counted from the first byte after the header.",
        zh: "工程工具为 GSD 所列各类型（UnitDiagType）的设备相关诊断显示的文本，位从头字节后的第一个字节起计数。",
        de: "Die Texte, die das Engineering-Tool zu einer gerätebezogenen Diagnose jedes Typs zeigt, den die GSD nennt (UnitDiagType); Bits gezählt ab dem ersten Byte nach dem Header.",
    };
    DP_CHANNEL_DIAGNOSIS_INTRO = {
        en: "The error types the card reports in a channel's diagnosis (bits 0 to 4 of its third byte), and the text the engineering tool shows for each.",
        zh: "扩展卡在通道诊断中报告的错误类型（其第三个字节的位 0 至 4），以及工程工具为每种错误显示的文本。",
        de: "Die Fehlertypen, die die Karte in der Diagnose eines Kanals meldet (Bits 0 bis 4 ihres dritten Bytes), und der Text, den das Engineering-Tool zu jedem anzeigt.",
    };
    EXTENDED_DIAGNOSIS = {
        en: "PROFINET extended channel diagnosis",
        zh: "PROFINET 扩展通道诊断",
        de: "Erweiterte PROFINET-Kanaldiagnose",
    };
    EXTENDED_DIAGNOSIS_INTRO = {
        en: "The extended error types the card reports with a channel diagnosis's error type, and the data items of the 4-byte add value it sends with each.",
        zh: "扩展卡随通道诊断错误类型报告的扩展错误类型，以及随每种错误发送的 4 字节附加值的数据项。",
        de: "Die erweiterten Fehlertypen, die die Karte mit dem Fehlertyp einer Kanaldiagnose meldet, und die Datenelemente des 4-Byte-Zusatzwerts, den sie mit jedem sendet.",
    };
    EXTENDED_ERROR_TYPE = { en: "Extended error type", zh: "扩展错误类型", de: "Erweiterter Fehlertyp" };
    ADD_VALUE = { en: "Add value", zh: "附加值", de: "Zusatzwert" };
    API = { all: "API" };
    HELP = { en: "Help", zh: "帮助", de: "Hilfe" };
    DIAGNOSIS_BYTE_BY_BYTE = {
        en: "The diagnosis, byte by byte",
        zh: "诊断数据各字节",
        de: "Die Diagnose, Byte für Byte",
    };
    BYTE = { en: "Byte", zh: "字节", de: same };
    CONTENT = { en: "Content", zh: "内容", de: "Inhalt" };
    ITEM = { en: "Item", zh: "项目", de: "Eintrag" };
    TYPE = { en: "Type", zh: "类型", de: "Typ" };
    /// `lengths`: the block's length in hex, or its lengths by type.
    diagnosis_header(lengths: &str) = {
        en: "header: the block's length, {lengths}",
        zh: "块头：块长度 {lengths}",
        de: "Kopfbyte: die Länge des Blocks, {lengths}",
    };

    // -----------------------------------------------------------------------
    // The card, its files and its bus parameters; the checklist

    /// `Name: text`.
    COLON = { en: ": ", zh: "：", de: same };
    PARAMETER = { en: "Parameter", zh: "参数", de: same };
    GENERATED_BY = { en: "Generated by ", zh: "本页由 ", de: "Erzeugt von " };
    FROM_THE_DESCRIPTION = {
        en: " from the description ",
        zh: " 根据设备描述 ",
        de: " aus der Beschreibung ",
    };
    OPEN_FINGERPRINT = { en: " (fingerprint ", zh: "（指纹 ", de: " (Fingerabdruck " };
    CHANGE_THE_DESCRIPTION = {
        en: "). Change the description, not this page.",
        zh: "）生成。请修改设备描述，不要修改本页。",
        de: "). Ändern Sie die Beschreibung, nicht diese Seite.",
    };
    IDENTITY_AND_FILES = { en: "Identity and files", zh: "标识与文件", de: "Identität und Dateien" };
    VENDOR = { en: "Vendor", zh: "厂商", de: "Hersteller" };
    FAMILY = { en: "Family", zh: "系列", de: "Familie" };
    MODEL = { en: "Model", zh: "型号", de: "Modell" };
    REVISION = { en: "Revision", zh: "版本", de: same };
    HARDWARE_RELEASE = { en: "Hardware release", zh: "硬件版本", de: "Hardware-Ausgabestand" };
    SOFTWARE_RELEASE = { en: "Software release", zh: "软件版本", de: "Software-Ausgabestand" };
    ORDER_NUMBER = { en: "Order number", zh: "订货号", de: "Bestellnummer" };
    THE_DEVICE = { en: "The device", zh: "设备", de: "Das Gerät" };
    GSD_FILE = {
        en: "PROFIBUS-DP device description (GSD)",
        zh: "PROFIBUS-DP 设备描述文件（GSD）",
        de: "PROFIBUS-DP-Gerätebeschreibung (GSD)",
    };
    GSDML_FILE = {
        en: "PROFINET device description (GSDML)",
        zh: "PROFINET 设备描述文件（GSDML）",
        de: "PROFINET-Gerätebeschreibung (GSDML)",
    };
    DEVICE_SYMBOL = { en: "Device symbol", zh: "设备图标", de: "Gerätesymbol" };
    SYMBOL_SIZE = {
        en: "70 x 40 pixels, 16 colours",
        zh: "70 x 40 像素，16 色",
        de: "70 x 40 Pixel, 16 Farben",
    };
    RUST_LAYOUT = {
        en: "Firmware layout (Rust, no_std)",
        zh: "固件数据布局（Rust，no_std）",
        de: "Firmware-Layout (Rust, no_std)",
    };
    C_LAYOUT = {
        en: "Firmware layout (C99 and C++)",
        zh: "固件数据布局（C99 和 C++）",
        de: "Firmware-Layout (C99 und C++)",
    };
    WITH = { en: " with ", zh: " 及 ", de: " mit " };
    FINGERPRINT = { en: "fingerprint ", zh: "指纹 ", de: "Fingerabdruck " };
    GENERATED_FILES = {
        en: "The files gsdc generates from the description",
        zh: "gsdc 由设备描述生成的文件",
        de: "Die Dateien, die gsdc aus der Beschreibung erzeugt",
    };
    FILE = { en: "File", zh: "文件", de: "Datei" };
    WHAT_IT_IS = { en: "What it is", zh: "用途", de: "Zweck" };
    IDENTIFICATION = { en: "Identification", zh: "标识", de: "Kennung" };
    YES = { en: "yes", zh: "是", de: "ja" };
    NO = { en: "no", zh: "否", de: "nein" };
    GSD_REVISION = { en: "GSD revision", zh: "GSD 版本", de: "GSD-Revision" };
    BAUD_RATES = {
        en: "Baud rates (kbit/s; M = Mbit/s)",
        zh: "波特率（kbit/s；M = Mbit/s）",
        de: "Baudraten (kbit/s; M = Mbit/s)",
    };
    AUTO_BAUD = {
        en: "Detects the baud rate (Auto_Baud_supp)",
        zh: "自动识别波特率（Auto_Baud_supp）",
        de: "Erkennt die Baudrate (Auto_Baud_supp)",
    };
    MIN_SLAVE_INTERVAL = { all: "Min_Slave_Interval" };
    FREEZE_MODE = { en: "Freeze mode", zh: "Freeze 模式", de: "Freeze-Modus" };
    SYNC_MODE = { en: "Sync mode", zh: "Sync 模式", de: "Sync-Modus" };
    MAX_IO_BYTES = {
        en: "Input and output bytes at most",
        zh: "最大输入、输出字节数",
        de: "Eingangs- und Ausgangsbytes höchstens",
    };
    MAX_DIAG_DATA_LEN = { all: "Max_Diag_Data_Len" };
    DPV1_C1_READ_WRITE = {
        en: "DPV1 class 1 read and write",
        zh: "DPV1 一类主站读写",
        de: "DPV1 Klasse 1 Lesen und Schreiben",
    };
    DPV1_C1_LIMITS = {
        en: "DPV1 C1_Max_Data_Len, response timeout",
        zh: "DPV1 C1_Max_Data_Len、响应超时",
        de: "DPV1 C1_Max_Data_Len, Antwortüberwachungszeit",
    };
    PROFIBUS_BUS_PARAMETERS = {
        en: "PROFIBUS-DP bus parameters",
        zh: "PROFIBUS-DP 总线参数",
        de: "PROFIBUS-DP-Busparameter",
    };
    GSDML_VERSION = { en: "GSDML version", zh: "GSDML 版本", de: "GSDML-Version" };
    IMPLEMENTATION_TYPE = { en: "Based on", zh: "基于", de: "Basiert auf" };
    REQUIRED_SCHEMA_VERSION = { en: "engineering tools need at least GSDML", zh: "工程工具至少需支持 GSDML", de: "Engineering-Werkzeuge brauchen mindestens GSDML" };
    NAME_OF_STATION = { en: "Name of station (default)", zh: "默认设备名称", de: "Gerätename (Vorgabe)" };
    PORTS = { en: "Ports", zh: "端口数", de: same };
    MIN_DEVICE_INTERVAL = {
        en: "Shortest update time (MinDeviceInterval)",
        zh: "最短更新时间（MinDeviceInterval）",
        de: "Kürzeste Aktualisierungszeit (MinDeviceInterval)",
    };
    MAX_IO_DATA = {
        en: "IO data bytes at most, in and out (IOPS and IOCS included)",
        zh: "最大 IO 数据字节数，输入、输出（含 IOPS、IOCS）",
        de: "IO-Datenbytes höchstens, Eingänge und Ausgänge (mit IOPS und IOCS)",
    };
    IO_DATA_TOGETHER = { en: "together", zh: "合计", de: "zusammen" };
    MODULE_SLOTS = {
        en: "Slots of the modules (each slot takes one, its own telegram)",
        zh: "模块插槽（每个插槽插一个模块，各有自己的报文）",
        de: "Steckplätze der Module (jeder Steckplatz nimmt eines, mit eigenem Telegramm)",
    };
    SAFETY_MODULES = {
        en: "PROFIsafe modules (slots; safety data bytes in/out, message trailer included)",
        zh: "PROFIsafe 模块（插槽；安全数据输入/输出字节数，含报文尾）",
        de: "PROFIsafe-Module (Steckplätze; Bytes der Sicherheitsdaten ein/aus, mit Telegrammabschluss)",
    };
    PROFINET_DEVICE = { en: "PROFINET device", zh: "PROFINET 设备", de: "PROFINET-Gerät" };
    IRT = {
        en: "Isochronous real time (RT_CLASS_3)",
        zh: "等时实时（RT_CLASS_3）",
        de: "Isochrone Echtzeit (RT_CLASS_3)",
    };
    ISOCHRONOUS_MODE = {
        en: "Isochronous mode of the modules (IsochroneMode)",
        zh: "模块的等时同步模式（IsochroneMode）",
        de: "Taktsynchronität der Module (IsochroneMode)",
    };
    ISOCHRONOUS_REQUIRED = { en: "required", zh: "必需", de: "erforderlich" };
    DEVICE_ACCESS_POINTS = {
        en: "Device access points",
        zh: "设备访问点",
        de: "Gerätezugriffspunkte",
    };
    ALL_MODULES = { en: "all", zh: "全部", de: "alle" };
    TO_CHECK = {
        en: "To check before shipping",
        zh: "发布前需核对",
        de: "Vor der Auslieferung zu prüfen",
    };
    CHECKLIST_INTRO = {
        en: "Placeholders stand where the manual gives no value; the description's own choices and gsdc's defaults where the manual is silent; the other rows are gsdc's conventions. The card's firmware must follow every row.",
        zh: "占位值用于手册未给出的值；描述文件自行确定的值与 gsdc 默认值用于手册未说明之处；其余各行是 gsdc 的约定。扩展卡固件必须与每一行一致。",
        de: "Platzhalter stehen, wo das Handbuch keinen Wert angibt; die eigene Wahl der Beschreibung und die Vorgaben von gsdc, wo das Handbuch nichts sagt; die übrigen Zeilen sind Konventionen von gsdc. Die Firmware der Karte muss jeder Zeile folgen.",
    };
    BYTE_ORDER = {
        en: "Byte order of every word",
        zh: "各字的字节顺序",
        de: "Bytereihenfolge jedes Worts",
    };
    BYTE_ORDER_RULE = {
        en: "gsdc: high byte first (PROFIBUS and PROFINET convention)",
        zh: "gsdc 约定：高字节在前（PROFIBUS、PROFINET 惯例）",
        de: "gsdc: höherwertiges Byte zuerst (Konvention von PROFIBUS und PROFINET)",
    };
    PROFINET_NUMBERS = {
        en: "PROFINET module ident numbers, record indexes and record layout",
        zh: "PROFINET 模块标识号、记录索引与记录布局",
        de: "PROFINET-Modulidentnummern, Datensatzindizes und Datensatzaufbau",
    };
    PROFINET_RECORD_NUMBERS = {
        en: "PROFINET record indexes and record layout",
        zh: "PROFINET 记录索引与记录布局",
        de: "PROFINET-Datensatzindizes und Datensatzaufbau",
    };
    AS_TABLES_ABOVE = {
        en: "gsdc: as the tables above give them",
        zh: "gsdc 约定：见上文各表",
        de: "gsdc: wie in den Tabellen oben",
    };
    PKW_RESERVED_BITS = { en: "PKW reserved bits", zh: "PKW 保留位", de: "Reservierte Bits im PKW" };
    WRITTEN_0 = {
        en: "gsdc: written 0, not read",
        zh: "gsdc 约定：写 0，不读取",
        de: "gsdc: als 0 geschrieben, nicht gelesen",
    };
    DPV1_RECORD_DATA = { en: "DPV1 record data", zh: "DPV1 记录数据", de: "DPV1-Datensatzdaten" };
    DPV1_RECORD_RULE = {
        en: "gsdc: the parameter's 16-bit value, high byte first",
        zh: "gsdc 约定：参数的 16 位值，高字节在前",
        de: "gsdc: der 16-Bit-Wert des Parameters, höherwertiges Byte zuerst",
    };
    CHECKLIST_CAPTION = {
        en: "Placeholders and gsdc's choices",
        zh: "占位值与 gsdc 的约定",
        de: "Platzhalter und Festlegungen von gsdc",
    };
    WHAT = { en: "What", zh: "内容", de: "Was" };
    STATUS = { en: "Status", zh: "说明", de: same };

    // -----------------------------------------------------------------------
    // The cyclic telegrams and their words

    MASTER_TO_DRIVE = { en: "master → drive", zh: "主站 → 变频器", de: "Master → Antrieb" };
    DRIVE_TO_MASTER = { en: "drive → master", zh: "变频器 → 主站", de: "Antrieb → Master" };
    CYCLIC_PPO = {
        en: "Cyclic data: PPO types",
        zh: "周期数据：PPO 类型",
        de: "Zyklische Daten: PPO-Typen",
    };
    PPO_TYPES = { en: "PPO types", zh: "PPO 类型", de: "PPO-Typen" };
    CYCLIC_MODULES = { en: "Cyclic data: modules", zh: "周期数据：模块", de: "Zyklische Daten: Module" };
    PROFINET_MODULES = { en: "PROFINET modules", zh: "PROFINET 模块", de: "PROFINET-Module" };
    CYCLIC_BOTH = {
        en: "Cyclic data: PPO types and modules",
        zh: "周期数据：PPO 类型与模块",
        de: "Zyklische Daten: PPO-Typen und Module",
    };
    PPO_AND_MODULES = {
        en: "PPO types and PROFINET modules",
        zh: "PPO 类型与 PROFINET 模块",
        de: "PPO-Typen und PROFINET-Module",
    };
    TELEGRAMS_INTRO = {
        en: "Each module carries the same number of words each way: the parameter channel (PKW) when it has one, then its process data words (PZD). Every word is 16 bits, high byte first.",
        zh: "每个模块在两个方向上传送相同数量的字：先是参数区（PKW，若有），后是过程数据区（PZD）。每个字 16 位，高字节在前。",
        de: "Jedes Modul überträgt in beiden Richtungen gleich viele Wörter: den Parameterkanal (PKW), wenn es ihn hat, dann seine Prozessdatenwörter (PZD). Jedes Wort hat 16 Bit, höherwertiges Byte zuerst.",
    };
    BUS = { en: "Bus", zh: "总线", de: same };
    PKW_WORDS = { en: "PKW words", zh: "PKW 字数", de: "PKW-Wörter" };
    PZD_WORDS = { en: "PZD words", zh: "PZD 字数", de: "PZD-Wörter" };
    BYTES_EACH_WAY = { en: "Bytes each way", zh: "每方向字节数", de: "Byte je Richtung" };
    CONFIG_BYTES_GSD = {
        en: "Config bytes (GSD)",
        zh: "配置字节（GSD）",
        de: "Konfigurationsbytes (GSD)",
    };
    MODULE_IDENT_GSDML = {
        en: "Module ident number (GSDML)",
        zh: "模块标识号（GSDML）",
        de: "Modulidentnummer (GSDML)",
    };
    PPO_OVERVIEW = {
        en: "PPO types, one box per word",
        zh: "PPO 类型，每个字一个方框",
        de: "PPO-Typen, ein Kasten je Wort",
    };
    MODULES_OVERVIEW = {
        en: "PROFINET modules, one box per word",
        zh: "PROFINET 模块，每个字一个方框",
        de: "PROFINET-Module, ein Kasten je Wort",
    };
    NOT_MAPPED = { en: "not mapped", zh: "未映射", de: "nicht zugeordnet" };
    ROLE_COMMAND_ADDRESS = { en: "command, address", zh: "命令、地址", de: "Befehl, Adresse" };
    ROLE_RESPONSE_ADDRESS = { en: "response, address", zh: "响应、地址", de: "Antwort, Adresse" };
    ROLE_ADDRESS_RESERVED = { en: "address, reserved", zh: "地址、保留", de: "Adresse, reserviert" };
    RESERVED = { en: "reserved", zh: "保留", de: "reserviert" };
    ROLE_VALUE_TO_WRITE = { en: "value to write", zh: "写入值", de: "zu schreibender Wert" };
    ROLE_VALUE_OR_ERROR_CODE = { en: "value or error", zh: "参数值或错误代码", de: "Wert oder Fehlercode" };
    ROLE_REQUEST_ID_PNU = { en: "request id, PNU", zh: "请求标识、参数号", de: "Auftragskennung, PNU" };
    ROLE_RESPONSE_ID_PNU = { en: "response id, PNU", zh: "应答标识、参数号", de: "Antwortkennung, PNU" };
    ROLE_SUBINDEX = { en: "subindex", zh: "子索引", de: "Subindex" };
    ROLE_VALUE_HIGH = { en: "value, high word", zh: "参数值高 16 位", de: "Wert, höherwertiges Wort" };
    ROLE_VALUE_LOW = { en: "value, low word", zh: "参数值低 16 位", de: "Wert, niederwertiges Wort" };
    ROLE_VALUE_OR_ERROR_NUMBER = {
        en: "value or error number",
        zh: "参数值或错误号",
        de: "Wert oder Fehlernummer",
    };
    ROLE_STATIONS = { en: "stations", zh: "站号", de: "Stationen" };
    ROLE_COMMAND = { en: "command", zh: "命令", de: "Befehl" };
    ROLE_REPLY = { en: "reply", zh: "应答", de: "Antwort" };
    ROLE_ADDRESS = { en: "address", zh: "地址", de: "Adresse" };
    ROLE_VALUE_OR_COUNT = { en: "value or count", zh: "参数值或个数", de: "Wert oder Anzahl" };
    ROLE_VALUE_OR_ERROR = { en: "value or error", zh: "参数值或错误码", de: "Wert oder Fehler" };
    WORDS_HEADING = {
        en: "The words of each telegram",
        zh: "各报文的字",
        de: "Die Wörter jedes Telegramms",
    };
    WORDS_INTRO = {
        en: "A shorter module carries the first words of a longer one when they are the same; each diagram shows the longest and names the others. The PZD words carry what the parameter telegram or the records map to them; the diagrams show the defaults.",
        zh: "较短模块的字与较长模块的前几个字相同时，只画出最长的模块，并列出其余模块。PZD 字传送参数报文或记录中映射的内容，图中为默认值。",
        de: "Ein kürzeres Modul überträgt die ersten Wörter eines längeren, wenn sie gleich sind; jedes Bild zeigt das längste und nennt die übrigen. Die PZD-Wörter übertragen, was das Parametriertelegramm oder die Datensätze ihnen zuordnen; die Bilder zeigen die Vorgabewerte.",
    };
    ONE_YES_ZERO_NO = { en: "1 = yes, 0 = no", zh: "1：有效，0：无效", de: "1 = ja, 0 = nein" };
    BITS = { en: "Bits", zh: "位", de: "Bit" };
    VALUES = { en: "Values", zh: "取值", de: "Werte" };
    also_first_words(names: &str) = {
        en: " (its first words are also {names})",
        zh: "（{names} 为其前几个字）",
        de: " (seine ersten Wörter sind auch {names})",
    };
    default_set_by(role: &str, parameter: &str) = {
        en: "{role} (default; {parameter} sets it)",
        zh: "{role}（默认值；由 {parameter} 设置）",
        de: "{role} (Vorgabewert; einstellbar mit {parameter})",
    };
    default_value(role: &str) = {
        en: "{role} (default)",
        zh: "{role}（默认值）",
        de: "{role} (Vorgabewert)",
    };
    bit_by_bit(name: &str, direction: &str) = {
        en: "{name}, PZD1 {direction}, bit by bit",
        zh: "{name}（PZD1，{direction}）各位",
        de: "{name}, PZD1 {direction}, bitweise",
    };

    // -----------------------------------------------------------------------
    // The parameter channel

    CODE = { en: "Code", zh: "代码", de: same };
    PKW_HEADING = {
        en: "The parameter channel (PKW)",
        zh: "参数区（PKW）",
        de: "Der Parameterkanal (PKW)",
    };
    PKW_INTRO = {
        en: "The PKW words read or change one drive parameter per request, in the first 8 bytes of a module that has them.",
        zh: "PKW 区位于带 PKW 的模块的前 8 个字节，每次请求读写变频器的一个参数。",
        de: "Die PKW-Wörter lesen oder ändern je Auftrag einen Antriebsparameter, in den ersten 8 Byte eines Moduls, das sie hat.",
    };
    EXAMPLES_READ_WRITE = {
        en: "The examples read and write ",
        zh: "以下示例读写 ",
        de: "Die Beispiele lesen und schreiben ",
    };
    THE_PKW_WORDS = { en: "The PKW words", zh: "PKW 数据格式", de: "Die PKW-Wörter" };
    PKE_REPEAT = {
        en: "A request is executed again every cycle while it stays in the telegram: a write left there writes the EEPROM again and again. Send command 0 when done.",
        zh: "PKW 数据以循环执行的方式与变频器交互：写命令留在报文中会持续写 EEPROM。操作完成后请发送命令 0。",
        de: "Ein Auftrag wird in jedem Zyklus erneut ausgeführt, solange er im Telegramm steht: ein dort belassener Schreibauftrag beschreibt das EEPROM immer wieder. Senden Sie danach Befehl 0.",
    };
    PKE_REQUEST_HEAD = {
        en: "Request (master → drive)",
        zh: "主站发送数据",
        de: "Auftrag (Master → Antrieb)",
    };
    PKE_RESPONSE_HEAD = {
        en: "Response (drive → master)",
        zh: "变频器响应数据",
        de: "Antwort (Antrieb → Master)",
    };
    PKE_REQUEST_PKE = {
        en: "bits 15-12: command; bits 11-8: reserved; bits 7-0: address, high byte",
        zh: "高 4 位：命令代码；低 4 位（位 11-8）：保留；低 8 位：功能码参数地址高位",
        de: "Bit 15-12: Befehl; Bit 11-8: reserviert; Bit 7-0: Adresse, höherwertiges Byte",
    };
    PKE_RESPONSE_PKE = {
        en: "bits 15-12: response code; bits 7-0: address, high byte",
        zh: "高 4 位：响应代码；低 8 位：功能码参数地址高位",
        de: "Bit 15-12: Antwortcode; Bit 7-0: Adresse, höherwertiges Byte",
    };
    PKE_IND = {
        en: "bits 15-8: address, low byte; bits 7-0: reserved",
        zh: "高 8 位：功能码参数地址低位；低 8 位：保留",
        de: "Bit 15-8: Adresse, niederwertiges Byte; Bit 7-0: reserviert",
    };
    PKE_PWE_HIGH = {
        en: "high word: reserved",
        zh: "高 16 位：保留",
        de: "höherwertiges Wort: reserviert",
    };
    PKE_PWE_LOW_REQUEST = {
        en: "low word: the value to write; unused when reading",
        zh: "低 16 位：写请求时为参数值；读请求时无使用",
        de: "niederwertiges Wort: der zu schreibende Wert; beim Lesen ungenutzt",
    };
    PKE_PWE_LOW_RESPONSE = {
        en: "low word: done, the value; cannot execute, the error code",
        zh: "低 16 位：请求成功时为参数值；失败时为错误代码",
        de: "niederwertiges Wort: ausgeführt, der Wert; nicht ausführbar, der Fehlercode",
    };
    PKE_READ = { en: "read the parameter", zh: "读取功能码参数数据", de: "Parameter lesen" };
    PKE_CHANGE = { en: "change the parameter", zh: "更改功能码参数数据", de: "Parameter ändern" };
    PKE_COMMANDS_CAPTION = {
        en: "Request commands (PKE bits 15-12, decimal)",
        zh: "命令代码（PKE 高 4 位，十进制）",
        de: "Auftragsbefehle (PKE Bit 15-12, dezimal)",
    };
    PKE_DONE_CODE = { en: "done", zh: "功能码参数操作正确", de: "ausgeführt" };
    PKE_FAILED_CODE = {
        en: "cannot execute: PWE low holds the error code",
        zh: "无法执行：PWE 低 16 位为错误代码",
        de: "nicht ausführbar: das niederwertige PWE-Wort enthält den Fehlercode",
    };
    PKE_RESPONSES_CAPTION = {
        en: "Response codes (PKE bits 15-12, decimal)",
        zh: "响应代码（PKE 高 4 位，十进制）",
        de: "Antwortcodes (PKE Bit 15-12, dezimal)",
    };
    PKE_ERRORS_CAPTION = {
        en: "Error codes (as in Modbus)",
        zh: "错误代码（与标准 MODBUS 一致）",
        de: "Fehlercodes (wie bei Modbus)",
    };
    DONE = { en: "done", zh: "操作正确", de: "ausgeführt" };
    DONE_VALUE_WRITTEN = {
        en: "done: the value written",
        zh: "操作正确：返回写入值",
        de: "ausgeführt: der geschriebene Wert",
    };
    WORKED_EXAMPLES = {
        en: "Worked examples, computed from the description",
        zh: "应用举例（由设备描述计算）",
        de: "Beispiele, aus der Beschreibung berechnet",
    };
    REQUEST = { en: "Request", zh: "请求", de: "Auftrag" };
    MASTER_SENDS = { en: "Master sends", zh: "主站发送 PKW", de: "Master sendet" };
    OUTCOME = { en: "Outcome", zh: "结果", de: "Ergebnis" };
    DRIVE_ANSWERS = { en: "Drive answers", zh: "变频器响应 PKW", de: "Antrieb antwortet" };
    STATION_REQUEST_HEAD = {
        en: "Request (controller → drive)",
        zh: "控制器请求",
        de: "Auftrag (Controller → Antrieb)",
    };
    STATION_REPLY_HEAD = {
        en: "Reply (drive → controller)",
        zh: "从站应答",
        de: "Antwort (Antrieb → Controller)",
    };
    STATION_PKW0_REQUEST = {
        en: "high byte: target station (the RS-485 slave); low byte: source station (this drive's own)",
        zh: "Byte0：目标站号（485 从站）；Byte1：源站号（本机站号）",
        de: "höherwertiges Byte: Zielstation (der RS-485-Slave); niederwertiges Byte: Quellstation (die dieses Antriebs)",
    };
    STATION_PKW0_REPLY = {
        en: "high byte: target station (the RS-485 master); low byte: source station (the answering drive)",
        zh: "Byte0：目标站号（485 主站）；Byte1：源站号（本机站号）",
        de: "höherwertiges Byte: Zielstation (der RS-485-Master); niederwertiges Byte: Quellstation (der antwortende Antrieb)",
    };
    STATION_PKW1_REQUEST = { en: "the command", zh: "读写功能码命令", de: "der Befehl" };
    STATION_PKW1_REPLY = {
        en: "the command; 0x80 + the command on error",
        zh: "应答命令；错误应答为 0x80+命令码",
        de: "der Befehl; bei Fehler 0x80 + Befehl",
    };
    STATION_PKW2_REQUEST = {
        en: "the parameter's address",
        zh: "需要读写的功能码地址",
        de: "die Adresse des Parameters",
    };
    STATION_PKW2_REPLY = { en: "the same address", zh: "功能码地址", de: "dieselbe Adresse" };
    STATION_PKW3_REQUEST = {
        en: "write: the value; read: the count, always 1",
        zh: "写操作：写的具体值；读操作：读的个数（固定值 1）",
        de: "Schreiben: der Wert; Lesen: die Anzahl, stets 1",
    };
    STATION_PKW3_REPLY = {
        en: "read: the value; write: 0; error: the error code",
        zh: "读操作应答：功能码值；写操作应答：0；错误应答：错误码",
        de: "Lesen: der Wert; Schreiben: 0; Fehler: der Fehlercode",
    };
    STATION_READ = { en: "read one parameter", zh: "读一个", de: "einen Parameter lesen" };
    STATION_WRITE_STORE = {
        en: "write one parameter and store it in EEPROM",
        zh: "写一个，存 EEPROM",
        de: "einen Parameter schreiben und im EEPROM speichern",
    };
    STATION_WRITE = {
        en: "write one parameter without storing it",
        zh: "写一个，不存 EEPROM",
        de: "einen Parameter schreiben, ohne ihn zu speichern",
    };
    STATION_COMMANDS_CAPTION = { en: "Commands (PKW1)", zh: "命令（PKW1）", de: "Befehle (PKW1)" };
    COMMAND = { en: "Command", zh: "命令", de: "Befehl" };
    REPLY_ON_ERROR = { en: "Reply on error", zh: "错误应答", de: "Antwort bei Fehler" };
    STATION_NO_ERROR_CODES = {
        en: "The manual lists no error codes: the reply to a failed request carries the drive's error code in PKW3.",
        zh: "手册未列出错误码：错误应答在 PKW3 中返回变频器的错误码。",
        de: "Das Handbuch nennt keine Fehlercodes: die Antwort auf einen fehlgeschlagenen Auftrag trägt den Fehlercode des Antriebs in PKW3.",
    };
    STATION_DONE_VALUE = { en: "done: the value", zh: "读操作应答：功能码值", de: "ausgeführt: der Wert" };
    STORED_IN_EEPROM = { en: ", stored in EEPROM", zh: "，存 EEPROM", de: ", im EEPROM gespeichert" };
    NOT_STORED = { en: ", not stored", zh: "，不存 EEPROM", de: ", nicht gespeichert" };
    STATION_DONE_WRITE = { en: "done", zh: "写操作应答", de: "ausgeführt" };
    FAILED = { en: "failed", zh: "错误应答", de: "fehlgeschlagen" };
    STATION_LEGEND = {
        en: "tt: the target station of the request, ss: its source station (the reply swaps them); vvvv: the value; xxxx: the drive's error code.",
        zh: "tt：请求的目标站号，ss：请求的源站号（应答中二者互换）；vvvv：参数值；xxxx：变频器的错误码。",
        de: "tt: die Zielstation des Auftrags, ss: seine Quellstation (die Antwort vertauscht beide); vvvv: der Wert; xxxx: der Fehlercode des Antriebs.",
    };
    PROFIDRIVE_INTRO = {
        en: "The channel is the PROFIdrive profile's, as its PPO types carry it: PKE holds the request or response id and the parameter number (PNU), IND the subindex, PWE1 and PWE2 the value.",
        zh: "参数区为 PROFIdrive 行规的参数通道（PPO 类型）：PKE 含请求或应答标识与参数号（PNU），IND 为子索引，PWE1、PWE2 为参数值。",
        de: "Der Kanal ist der des PROFIdrive-Profils, wie ihn seine PPO-Typen tragen: PKE enthält die Auftrags- oder Antwortkennung und die Parameternummer (PNU), IND den Subindex, PWE1 und PWE2 den Wert.",
    };
    PROFIDRIVE_REQUEST_HEAD = {
        en: "Request (master → drive)",
        zh: "主站请求",
        de: "Auftrag (Master → Antrieb)",
    };
    PROFIDRIVE_RESPONSE_HEAD = {
        en: "Response (drive → master)",
        zh: "变频器应答",
        de: "Antwort (Antrieb → Master)",
    };
    PROFIDRIVE_PKE_REQUEST = {
        en: "bits 15-12: request id; bit 11: SPM, 0; bits 10-0: PNU",
        zh: "位 15-12：请求标识；位 11：SPM，为 0；位 10-0：参数号",
        de: "Bit 15-12: Auftragskennung; Bit 11: SPM, 0; Bit 10-0: PNU",
    };
    PROFIDRIVE_PKE_RESPONSE = {
        en: "bits 15-12: response id; bit 11: SPM, 0; bits 10-0: PNU",
        zh: "位 15-12：应答标识；位 11：SPM，为 0；位 10-0：参数号",
        de: "Bit 15-12: Antwortkennung; Bit 11: SPM, 0; Bit 10-0: PNU",
    };
    PROFIDRIVE_IND = {
        en: "bits 15-8: subindex; bits 7-0: 0, not read (not defined by the profile)",
        zh: "位 15-8：子索引；位 7-0：为 0，不读取（行规未定义）",
        de: "Bit 15-8: Subindex; Bit 7-0: 0, nicht gelesen (vom Profil nicht festgelegt)",
    };
    PROFIDRIVE_PWE1 = {
        en: "a double word's high word; 0 otherwise",
        zh: "双字参数值的高 16 位；其余为 0",
        de: "das höherwertige Wort eines Doppelworts; sonst 0",
    };
    PROFIDRIVE_PWE2_REQUEST = {
        en: "a word, or a double word's low word",
        zh: "单字参数值，或双字参数值的低 16 位",
        de: "ein Wort oder das niederwertige Wort eines Doppelworts",
    };
    PROFIDRIVE_PWE2_RESPONSE = {
        en: "a word, or a double word's low word; response 7: the error number",
        zh: "单字参数值，或双字参数值的低 16 位；应答 7：错误号",
        de: "ein Wort oder das niederwertige Wort eines Doppelworts; Antwort 7: die Fehlernummer",
    };
    REQUEST_IDS_CAPTION = {
        en: "Request ids (PKE bits 15-12, decimal)",
        zh: "请求标识（PKE 位 15-12，十进制）",
        de: "Auftragskennungen (PKE Bit 15-12, dezimal)",
    };
    ID = { en: "Id", zh: "标识", de: "Kennung" };
    RESPONSE_IDS_CAPTION = {
        en: "Response ids (PKE bits 15-12, decimal)",
        zh: "应答标识（PKE 位 15-12，十进制）",
        de: "Antwortkennungen (PKE Bit 15-12, dezimal)",
    };
    PROFIDRIVE_REFUSED = {
        en: "The card refuses request 10 (reserved) and 11 to 15, which are not the profile's (MICROMASTER and MASTERDRIVES store a value in EEPROM with 11 to 14). It sends no parameter change reports (responses 9 to 12): SPM is always 0.",
        zh: "请求标识 10（保留）及 11 至 15（非行规定义；MICROMASTER 与 MASTERDRIVES 用 11 至 14 将参数值写入 EEPROM）不被接受。本卡不发送参数修改报告（应答 9 至 12）：SPM 恒为 0。",
        de: "Die Karte weist Auftrag 10 (reserviert) und 11 bis 15 zurück, die nicht zum Profil gehören (MICROMASTER und MASTERDRIVES speichern mit 11 bis 14 einen Wert im EEPROM). Sie sendet keine Parameteränderungsberichte (Antworten 9 bis 12): SPM ist stets 0.",
    };
    ERROR_NUMBERS_CAPTION = {
        en: "Error numbers of response 7 (PWE2, decimal)",
        zh: "应答 7 的错误号（PWE2，十进制）",
        de: "Fehlernummern von Antwort 7 (PWE2, dezimal)",
    };
    NUMBER = { en: "Number", zh: "错误号", de: "Nummer" };
    OTHER_NUMBERS = {
        en: "Other numbers are the drive's own: Siemens manuals give those from 101 on as device-specific.",
        zh: "其它错误号由变频器自定义：西门子手册中 101 起为设备专用错误号。",
        de: "Andere Nummern sind die des Antriebs: Siemens-Handbücher führen die ab 101 als gerätespezifisch.",
    };
    WORD_PARAMETER_VALUE = {
        en: "a word parameter's value",
        zh: "单字参数值",
        de: "der Wert eines Wort-Parameters",
    };
    DOUBLE_WORD_PARAMETER_VALUE = {
        en: "a double word parameter's value",
        zh: "双字参数值",
        de: "der Wert eines Doppelwort-Parameters",
    };
    ELEMENT_VALUE = {
        en: "the element's value (word)",
        zh: "数组元素值（单字）",
        de: "der Wert des Elements (Wort)",
    };
    CANNOT_EXECUTE_XXXX = {
        en: "cannot execute: error number xxxx",
        zh: "无法执行：错误号 xxxx",
        de: "nicht ausführbar: Fehlernummer xxxx",
    };
    PROFIDRIVE_LEGEND = {
        en: "vvvv: the value (vvvvvvvv: a double word, high word first); ss: the subindex; xxxx: the error number.",
        zh: "vvvv：参数值（vvvvvvvv：双字，高 16 位在前）；ss：子索引；xxxx：错误号。",
        de: "vvvv: der Wert (vvvvvvvv: ein Doppelwort, höherwertiges Wort zuerst); ss: der Subindex; xxxx: die Fehlernummer.",
    };
    the_default_of(name: &str) = {
        en: "the default of {name}",
        zh: "{name}的默认值",
        de: "der Vorgabewert von {name}",
    };
    the_parameter_that_sets(name: &str) = {
        en: "the parameter that sets {name}",
        zh: "设置{name}的参数",
        de: "der Parameter, der {name} einstellt",
    };
    /// After the parameter: how the channel numbers it, and why it is the
    /// examples' parameter.
    examples_encoded(number: &str, why: &str) = {
        en: " ({number}), {why}. The telegrams are encoded by the firmware layout's own code.",
        zh: "（{number}，{why}）。报文由固件数据布局的编码代码生成。",
        de: " ({number}), {why}. Die Telegramme kodiert der eigene Code des Firmware-Layouts.",
    };
    address_number(address: u16) = {
        en: "address 0x{address:04X}",
        zh: "地址 0x{address:04X}",
        de: "Adresse 0x{address:04X}",
    };
    read_parameter(name: &str) = { en: "read {name}", zh: "读 {name}", de: "{name} lesen" };
    change_to_vvvv(name: &str) = {
        en: "change {name} to vvvv",
        zh: "将 {name} 改为 vvvv",
        de: "{name} auf vvvv ändern",
    };
    /// `how`: stored in EEPROM or not.
    write_vvvv_to(name: &str, how: &str) = {
        en: "write vvvv to {name}{how}",
        zh: "将 vvvv 写入 {name}{how}",
        de: "vvvv in {name} schreiben{how}",
    };
    change_to_word(name: &str) = {
        en: "change {name} to vvvv (word)",
        zh: "将 {name} 改为 vvvv（单字）",
        de: "{name} auf vvvv ändern (Wort)",
    };
    change_to_double_word(name: &str) = {
        en: "change {name} to vvvvvvvv (double word)",
        zh: "将 {name} 改为 vvvvvvvv（双字）",
        de: "{name} auf vvvvvvvv ändern (Doppelwort)",
    };
    read_element(name: &str) = {
        en: "read element ss of {name}",
        zh: "读 {name} 的元素 ss",
        de: "Element ss von {name} lesen",
    };

    // -----------------------------------------------------------------------
    // Parameters, records and the diagnosis

    DEFAULT = { en: "Default", zh: "默认值", de: "Vorgabewert" };
    RANGE_OR_CHOICES = { en: "Range or choices", zh: "范围或选项", de: "Bereich oder Auswahlwerte" };
    DRIVE_PARAMETER = { en: "Drive parameter", zh: "变频器参数", de: "Antriebsparameter" };
    PARAMETERS = { en: "Parameters", zh: "参数", de: "Parameter" };
    PARAMETERS_MAPPINGS = {
        en: "Parameters: mappings and settings",
        zh: "参数：映射与设置",
        de: "Parameter: Zuordnungen und Einstellungen",
    };
    PROFINET_RECORDS = {
        en: "PROFINET parameter records",
        zh: "PROFINET 参数记录",
        de: "PROFINET-Parameterdatensätze",
    };
    RECORDS_INTRO = {
        en: "The controller writes these records when it plugs a module. Each holds one Unsigned16 per entry, high byte first; a module's PZD record holds the words it transports, and the tables show the longest.",
        zh: "控制器插入模块时写入以下参数记录。每个条目一个 Unsigned16，高字节在前；模块的 PZD 记录只含该模块传输的字，下表为最长的记录。",
        de: "Der Controller schreibt diese Datensätze, wenn er ein Modul steckt. Jeder enthält ein Unsigned16 je Eintrag, höherwertiges Byte zuerst; der PZD-Datensatz eines Moduls enthält die Wörter, die es überträgt, und die Tabellen zeigen den längsten.",
    };
    FAIL_SAFE_CAPTION = {
        en: "Fail-safe values: each module's settings record ends with one per output item, 0 by default, any value of its type",
        zh: "故障安全值：各模块的设置记录以每个输出数据项一个值结尾，默认为 0，可取其类型的任意值",
        de: "Ersatzwerte: der Einstellungsdatensatz jedes Moduls endet mit einem je Ausgangsdatum, Vorgabe 0, jeder Wert seines Typs",
    };
    FAIL_SAFE_VALUES = { en: "Fail-safe values", zh: "故障安全值", de: "Ersatzwerte" };
    RECORDS_INTRO_TYPED = {
        en: "The controller writes these records when it plugs a module. Each holds its entries one after the other, each of its type, high byte first; a module's PZD record holds the words it transports, and the tables show the longest.",
        zh: "控制器插入模块时写入以下参数记录。各条目依次排列，各为其类型，高字节在前；模块的 PZD 记录只含该模块传输的字，下表为最长的记录。",
        de: "Der Controller schreibt diese Datensätze, wenn er ein Modul steckt. Jeder enthält seine Einträge hintereinander, jeden in seinem Typ, höherwertiges Byte zuerst; der PZD-Datensatz eines Moduls enthält die Wörter, die es überträgt, und die Tabellen zeigen den längsten.",
    };
    USER_PRM_HEADING = {
        en: "PROFIBUS parameter telegram (User_Prm_Data)",
        zh: "PROFIBUS 参数报文（User_Prm_Data）",
        de: "PROFIBUS-Parametriertelegramm (User_Prm_Data)",
    };
    USER_PRM_TYPES = {
        en: " Every entry is one Unsigned16, high byte first; the configuration tool shows it in decimal.",
        zh: "每个条目为一个 Unsigned16，高字节在前；组态软件中以十进制显示。",
        de: " Jeder Eintrag ist ein Unsigned16, höherwertiges Byte zuerst; das Projektierungswerkzeug zeigt ihn dezimal.",
    };
    USER_PRM_ENTRY_TYPES = {
        en: " An Unsigned8 or a Signed8 is one byte, an Unsigned16 two, high byte first; the configuration tool shows the values in decimal.",
        zh: "Unsigned8 或 Signed8 占一个字节，Unsigned16 占两个字节，高字节在前；组态软件中以十进制显示。",
        de: " Ein Unsigned8 oder Signed8 ist ein Byte, ein Unsigned16 zwei, höherwertiges Byte zuerst; das Projektierungswerkzeug zeigt die Werte dezimal.",
    };
    USER_PRM_GATEWAY_TYPES = {
        en: " An Unsigned8 or a Signed8 is one byte, an Unsigned16 two, high byte first; a BitArea(first-last) is those bits of its byte, whose other bits other parameters hold. The configuration tool shows the values in decimal.",
        zh: "Unsigned8 或 Signed8 占一个字节，Unsigned16 占两个字节，高字节在前；BitArea(起始位-结束位) 为所在字节中的这些位，该字节的其余位属于其它参数。组态软件中以十进制显示。",
        de: " Ein Unsigned8 oder Signed8 ist ein Byte, ein Unsigned16 zwei, höherwertiges Byte zuerst; eine BitArea(erstes-letztes) sind diese Bits ihres Bytes, dessen übrige Bits andere Parameter belegen. Das Projektierungswerkzeug zeigt die Werte dezimal.",
    };
    DPV1_STATUS = {
        en: "DPV1_Status_1 to DPV1_Status_3",
        zh: "DPV1_Status_1～DPV1_Status_3",
        de: "DPV1_Status_1 bis DPV1_Status_3",
    };
    CONSTANT = { en: "constant", zh: "常量", de: "Konstante" };
    USER_PRM_DATA = { all: "User_Prm_Data" };
    WITH_EVERY_DEFAULT = {
        en: "With every default: ",
        zh: "全部为默认值时：",
        de: "Mit allen Vorgabewerten: ",
    };
    DPV1_INDEXES = { en: "DPV1 indexes", zh: "DPV1 自定义 Index", de: "DPV1-Indizes" };
    DPV1_INTRO = {
        en: "A DPV1 class 1 master reads (SFB52) and writes (SFB53) the parameter mapped to an index.",
        zh: "DPV1 一类主站通过 SFB52 读、SFB53 写映射到各 Index 的功能码。",
        de: "Ein DPV1-Master Klasse 1 liest (SFB52) und schreibt (SFB53) den einem Index zugeordneten Parameter.",
    };
    DPV1_CAPTION = {
        en: "DPV1 indexes and the parameters they map",
        zh: "DPV1 Index 及其映射的参数",
        de: "DPV1-Indizes und die zugeordneten Parameter",
    };
    INDEX = { all: "Index" };
    IN_USER_PRM = { en: "In User_Prm_Data", zh: "在 User_Prm_Data 中", de: "Im User_Prm_Data" };
    DEVICE_RELATED_UNDESCRIBED = {
        en: "device-related, not described",
        zh: "设备专用，未定义",
        de: "gerätebezogen, nicht beschrieben",
    };
    STATION_STATUS = {
        en: "Station_Status_1 to Station_Status_3",
        zh: "站状态 1～3",
        de: "Station_Status_1 bis Station_Status_3",
    };
    MASTER_ADDRESS = { en: "the master's address", zh: "主站号", de: "die Adresse des Masters" };
    BLOCK_OTHER_BITS_0 = {
        en: "Block (header first), other bits 0",
        zh: "诊断块（含块头，其余位为 0）",
        de: "Block (Kopfbyte zuerst), übrige Bits 0",
    };
    user_prm_intro(len: u16) = {
        en: "The master sends it before data exchange, after the 7 standard bytes: {len} bytes, offsets counted from its first byte.",
        zh: "主站在数据交换前发送参数报文，位于 7 个标准字节之后：共 {len} 字节，偏移从其第一个字节算起。",
        de: "Der Master sendet es vor dem Datenaustausch, nach den 7 Standardbytes: {len} Byte, die Offsets ab seinem ersten Byte gezählt.",
    };
    index_record_length(length: u8) = {
        en: "Each index's record is {length} bytes; the card refuses others.",
        zh: "每个 Index 的记录长度为 {length} 字节；其它长度被拒绝。",
        de: "Der Datensatz jedes Index ist {length} Byte lang; andere Längen weist die Karte zurück.",
    };
    module_values_caption(name: &str) = {
        en: "{name}: the value each module writes, which the user cannot change",
        zh: "{name}：各模块写入的值，用户不可更改",
        de: "{name}: der Wert, den jedes Modul schreibt; der Benutzer kann ihn nicht ändern",
    };
    module_defaults_caption(name: &str) = {
        en: "{name}: each module's default, which the user may change",
        zh: "{name}：各模块的默认值，用户可以更改",
        de: "{name}: der Vorgabewert jedes Moduls; der Benutzer kann ihn ändern",
    };
    /// A fail-safe value and its type: `Fail safe NSOLL_B (Unsigned32)`.
    fail_safe_value(name: &str, data_type: &str) = {
        en: "{name} ({data_type})",
        zh: "{name}（{data_type}）",
        de: same,
    };
    OWN_RECORDS = {
        en: "Records of the device access point and the ports",
        zh: "设备接入点和端口的参数记录",
        de: "Datensätze des Gerätezugangspunkts und der Ports",
    };
    OWN_RECORDS_INTRO = {
        en: "The controller writes these records at startup, with the values the user set: those of the device access point to its own submodule (slot 0, subslot 1), those of the ports to every port, those of a safety module to its submodule. Each value is high byte first; a bit's place counts from bit 0 of its byte.",
        zh: "控制器在启动时以用户设定的值写入以下参数记录：设备接入点的记录写入其自身子模块（插槽 0，子插槽 1），端口的记录写入每个端口，安全模块的记录写入其子模块。各值高字节在前；位的位置从其字节的 Bit0 算起。",
        de: "Der Controller schreibt diese Datensätze beim Anlauf mit den Werten, die der Benutzer eingestellt hat: die des Gerätezugangspunkts in dessen eigenes Submodul (Steckplatz 0, Subslot 1), die der Ports in jeden Port, die eines Sicherheitsmoduls in dessen Submodul. Jeder Wert steht mit dem höherwertigen Byte zuerst; die Stelle eines Bits zählt ab Bit 0 seines Bytes.",
    };
    ACCESS_POINT_RECORD = { en: "Device access point", zh: "设备接入点", de: "Gerätezugangspunkt" };
    PORT_RECORD = { en: "Every port", zh: "每个端口", de: "Jeder Port" };
    /// Whose records, and the device access points that have them where
    /// not every one has: `Every port (V1, V3)`.
    records_of(whose: &str, daps: &str) = {
        en: "{whose} ({daps})",
        zh: "{whose}（{daps}）",
        de: same,
    };
    /// A value the controller may not change: `1, fixed`.
    fixed_value(value: &str) = {
        en: "{value}, fixed",
        zh: "{value}，固定",
        de: "{value}, fest",
    };
    /// `size`: [`bytes_count`], or [`ONE_BYTE`].
    own_record_caption(whose: &str, index: u16, name: &str, size: &str) = {
        en: "{whose}, record {index}: {name}, {size}",
        zh: "{whose}，记录 {index}：{name}，{size}",
        de: "{whose}, Datensatz {index}: {name}, {size}",
    };
    record_caption(index: u16, name: &str, size: &str) = {
        en: "Record {index}: {name}, {size}",
        zh: "记录 {index}：{name}，{size}",
        de: "Datensatz {index}: {name}, {size}",
    };
    diagnosis_intro(standard: u8, length: u8) = {
        en: "The slave's diagnosis: {standard} standard bytes, then the device-related block of {length} bytes, its header byte first (bits 7-6 = 00, bits 5-0 = the block's length). Unit_Diag_Area bits count from bit 0 of the byte after the header.",
        zh: "从站诊断数据：{standard} 个标准字节，之后是 {length} 字节的设备专用诊断块，首字节为块头（位 7-6 = 00，位 5-0 = 块长度）。Unit_Diag_Area 的位从块头后一个字节的位 0 算起。",
        de: "Die Diagnose des Slaves: {standard} Standardbytes, dann der gerätebezogene Block von {length} Byte, sein Kopfbyte zuerst (Bit 7-6 = 00, Bit 5-0 = die Länge des Blocks). Die Bits eines Unit_Diag_Area zählen ab Bit 0 des Bytes nach dem Kopfbyte.",
    };
    ident_number_bytes(high: u8, low: u8) = {
        en: "Ident_Number, high byte then low: {high:02X} {low:02X}",
        zh: "Ident_Number，高字节、低字节：{high:02X} {low:02X}",
        de: "Ident_Number, höherwertiges, dann niederwertiges Byte: {high:02X} {low:02X}",
    };
    f_parameters_caption(module: &str, size: &str, param_crc: &str, io_crc: u32) = {
        en: "F-parameters of module \"{module}\": {size} (F_ParamDescCRC {param_crc}, F_IO_StructureDescCRC {io_crc})",
        zh: "模块“{module}”的 F 参数：{size}（F_ParamDescCRC {param_crc}，F_IO_StructureDescCRC {io_crc}）",
        de: "F-Parameter des Moduls „{module}“: {size} (F_ParamDescCRC {param_crc}, F_IO_StructureDescCRC {io_crc})",
    };
    diagnosis_type_values(id: u8, bits: &str) = {
        en: "UnitDiagType {id}, X_Unit_Diag_Area {bits}: values",
        zh: "UnitDiagType {id}，X_Unit_Diag_Area {bits}：取值",
        de: "UnitDiagType {id}, X_Unit_Diag_Area {bits}: Werte",
    };
    diagnosis_type_bits(id: u8) = {
        en: "UnitDiagType {id}: bits",
        zh: "UnitDiagType {id}：位",
        de: "UnitDiagType {id}: Bits",
    };
    area_values(bits: &str) = {
        en: "Unit_Diag_Area {bits}: values",
        zh: "Unit_Diag_Area {bits}：取值",
        de: "Unit_Diag_Area {bits}: Werte",
    };

    // -----------------------------------------------------------------------
    // A gateway

    /// `a or b`: between alternatives.
    OR_SEPARATOR = { en: " or ", zh: "或 ", de: " oder " };
    /// `a; b`: between the parts of a table cell.
    PART_SEPARATOR = { en: "; ", zh: "；", de: same };
    FULL_STOP = { en: ".", zh: "。", de: same };
    DIRECTION = { en: "Direction", zh: "方向", de: "Richtung" };
    WORDS = { en: "Words", zh: "字数", de: "Wörter" };
    INPUT_NODES_TO_MASTER = {
        en: "input, nodes → master",
        zh: "输入，节点 → 主站",
        de: "Eingänge, Knoten → Master",
    };
    OUTPUT_MASTER_TO_NODES = {
        en: "output, master → nodes",
        zh: "输出，主站 → 节点",
        de: "Ausgänge, Master → Knoten",
    };
    ORDER_NODE_ASCENDING = {
        en: "the nodes in use in ascending node number, each node's words together",
        zh: "使用中的节点按节点号升序排列，每个节点的字连续排列",
        de: "die genutzten Knoten aufsteigend nach Knotennummer, die Wörter jedes Knotens zusammenhängend",
    };
    SECOND_BUS = { en: "Second bus", zh: "第二总线", de: "Zweiter Bus" };
    NODE_NUMBERS = { en: "Node numbers", zh: "节点号", de: "Knotennummern" };
    OWN_NODE = { en: "The gateway's own node", zh: "网桥本身的节点号", de: "Eigener Knoten des Gateways" };
    NODES_IN_USE = { en: "Nodes in use", zh: "使用的节点数", de: "Genutzte Knoten" };
    WORDS_A_NODE_SENDS = {
        en: "Words a node sends (input)",
        zh: "每个节点发送的字数（输入）",
        de: "Wörter, die ein Knoten sendet (Eingänge)",
    };
    WORDS_A_NODE_RECEIVES = {
        en: "Words a node receives (output)",
        zh: "每个节点接收的字数（输出）",
        de: "Wörter, die ein Knoten empfängt (Ausgänge)",
    };
    MAX_INPUT_LEN = {
        en: "Input bytes at most (Max_Input_Len)",
        zh: "最大输入字节数（Max_Input_Len）",
        de: "Eingangsbytes höchstens (Max_Input_Len)",
    };
    MAX_OUTPUT_LEN = {
        en: "Output bytes at most (Max_Output_Len)",
        zh: "最大输出字节数（Max_Output_Len）",
        de: "Ausgangsbytes höchstens (Max_Output_Len)",
    };
    NODE_WORDS_IN_DATA = {
        en: "The nodes' words in the data",
        zh: "各节点的字在数据中的顺序",
        de: "Wörter der Knoten in den Daten",
    };
    MAX_MODULE = {
        en: "Modules at most (Max_Module)",
        zh: "最多模块数（Max_Module）",
        de: "Module höchstens (Max_Module)",
    };
    MODULES = { en: "Modules", zh: "模块", de: "Module" };
    THE_MODULE_SIZES = { en: " The module sizes: ", zh: "模块大小：", de: " Die Modulgrößen: " };
    WHOLE_MODULE = { en: "the whole module", zh: "整个模块", de: "das ganze Modul" };
    EACH_WORD = { en: "each word on its own", zh: "按字", de: "jedes Wort für sich" };
    THE_MODULES = { en: "The modules", zh: "模块", de: "Die Module" };
    BYTE_COUNT = { en: "Bytes", zh: "字节数", de: "Byte" };
    CONFIG_BYTE = { en: "Config byte", zh: "配置字节", de: "Konfigurationsbyte" };
    CONSISTENCY = { en: "Consistency", zh: "一致性", de: "Konsistenz" };
    AN_EXAMPLE = { en: "An example", zh: "示例", de: "Ein Beispiel" };
    EXAMPLE_DATA = {
        en: "The example's data: each node's words in the data order",
        zh: "示例的数据：各节点的字按数据顺序排列",
        de: "Die Daten des Beispiels: die Wörter jedes Knotens in der Reihenfolge der Daten",
    };
    ALL_NODES = { en: "all", zh: "合计", de: "Summe" };
    EXAMPLE_NODES = { en: "The example's nodes", zh: "示例的节点", de: "Die Knoten des Beispiels" };
    NODE = { en: "Node", zh: "节点", de: "Knoten" };
    WORDS_SENT = { en: "Words sent", zh: "发送字数", de: "Gesendete Wörter" };
    IN_INPUT_DATA = { en: "In the input data", zh: "在输入数据中", de: "In den Eingangsdaten" };
    WORDS_RECEIVED = { en: "Words received", zh: "接收字数", de: "Empfangene Wörter" };
    IN_OUTPUT_DATA = { en: "In the output data", zh: "在输出数据中", de: "In den Ausgangsdaten" };
    EXAMPLE_MODULES = {
        en: "The modules the master plugs for the example",
        zh: "示例中主站插入的模块",
        de: "Die Module, die der Master für das Beispiel steckt",
    };
    MODULES_FEWEST = { en: "Modules, fewest", zh: "模块（最少）", de: "Module, möglichst wenige" };
    CONFIG_BYTES_CHK_CFG = {
        en: "Config bytes (Chk_Cfg)",
        zh: "配置字节（Chk_Cfg）",
        de: "Konfigurationsbytes (Chk_Cfg)",
    };
    THE_TYPE = { en: "the type (table below)", zh: "类型（见下表）", de: "der Typ (Tabelle unten)" };
    HIGH_BYTE = { en: "high byte", zh: "高字节", de: "höherwertiges Byte" };
    LOW_BYTE = { en: "low byte", zh: "低字节", de: "niederwertiges Byte" };
    NOT_USED = { en: "not used", zh: "未使用", de: "nicht genutzt" };
    HHLL = {
        en: "hhll: 16 bits, high byte first",
        zh: "hhll：16 位，高字节在前",
        de: "hhll: 16 Bit, höherwertiges Byte zuerst",
    };
    FAULT_CODE = { en: "Code", zh: "故障码", de: "Fehlercode" };
    FAULT_CODE_MEANING = {
        en: "Meaning of the code",
        zh: "故障码含义",
        de: "Bedeutung des Fehlercodes",
    };
    BLOCK_HEADER_FIRST = {
        en: "Block, header first",
        zh: "诊断块（含块头）",
        de: "Block, Kopfbyte zuerst",
    };
    gateway_heading(bus: &str) = {
        en: "Cyclic data: the {bus} nodes' words",
        zh: "周期数据：{bus} 节点的字",
        de: "Zyklische Daten: die Wörter der {bus}-Knoten",
    };
    gateway_own_node(n: u8) = {
        en: ", the gateway itself being node {n}",
        zh: "，网桥本身为节点 {n}",
        de: ", wobei das Gateway selbst Knoten {n} ist",
    };
    /// `own`: [`gateway_own_node`], or nothing.
    gateway_intro(bus: &str, first: u8, last: u8, own: &str) = {
        en: "The card is a gateway to {bus}: it carries the data of the {bus} nodes {first} to {last}{own}. The master sets in the parameter telegram how many nodes are in use and how many words each one sends (the master's input) and receives (its output), and plugs modules until its input and output equal the nodes' totals. Every word is 16 bits, high byte first.",
        zh: "本卡为 {bus} 网桥：传送 {bus} 节点 {first}～{last} 的数据{own}。主站在参数报文中设定使用的节点数及每个节点发送（主站输入）和接收（主站输出）的字数，并插入模块，直至输入、输出长度等于各节点的总和。每个字 16 位，高字节在前。",
        de: "Die Karte ist ein Gateway zu {bus}: sie überträgt die Daten der {bus}-Knoten {first} bis {last}{own}. Der Master legt im Parametriertelegramm fest, wie viele Knoten genutzt werden und wie viele Wörter jeder sendet (die Eingänge des Masters) und empfängt (seine Ausgänge), und steckt Module, bis seine Eingänge und Ausgänge den Summen der Knoten gleichen. Jedes Wort hat 16 Bit, höherwertiges Byte zuerst.",
    };
    /// A node's words: their range, and the first node's parameter.
    words_from_first(range: &str, name: &str) = {
        en: "{range} (\"{name}\" and on)",
        zh: "{range}（“{name}”等）",
        de: "{range} („{name}“ und folgende)",
    };
    node_count(range: &str, name: &str, default: u8) = {
        en: "{range} (\"{name}\"), default {default}",
        zh: "{range}（“{name}”），默认值 {default}",
        de: "{range} („{name}“), Vorgabewert {default}",
    };
    gateway_caption(bus: &str) = {
        en: "The gateway to {bus}",
        zh: "{bus} 网桥",
        de: "Das Gateway zu {bus}",
    };
    gateway_modules_intro(max: u8) = {
        en: "Each module is a block of words one way, with one config identifier byte (Chk_Cfg): bit 7 consistency, bit 6 words, bits 5-4 the direction (01 input, 10 output), bits 3-0 the words less one. The master plugs modules, at most {max}, until their input words equal the words the nodes in use send and their output words the words they receive.",
        zh: "每个模块为一个方向的若干字，对应一个配置标识字节（Chk_Cfg）：位 7 一致性，位 6 字，位 5-4 方向（01 输入，10 输出），位 3-0 字数减 1。主站插入模块（最多 {max} 个），使输入字数等于使用中的节点发送的字数，输出字数等于其接收的字数。",
        de: "Jedes Modul ist ein Block von Wörtern in einer Richtung, mit einem Kennungsbyte der Konfiguration (Chk_Cfg): Bit 7 Konsistenz, Bit 6 Wörter, Bit 5-4 die Richtung (01 Eingang, 10 Ausgang), Bit 3-0 die Anzahl der Wörter minus eins. Der Master steckt Module, höchstens {max}, bis ihre Eingangswörter den Wörtern gleichen, die die genutzten Knoten senden, und ihre Ausgangswörter den Wörtern, die sie empfangen.",
    };
    gateway_example_nodes(nodes: usize, most_in: u8, input_len: u16, receiving: usize, most_out: u8) = {
        en: "An example gsdc computes from the description: {nodes} nodes in use, each sending its most words ({most_in}), as many nodes as {input_len} bytes of input hold; the first {receiving} of them also receive their most words ({most_out}).",
        zh: "以下示例由 gsdc 根据设备描述计算：使用 {nodes} 个节点，每个节点发送最多的字数（{most_in}），节点数为 {input_len} 字节输入所能容纳的最多节点数；其中前 {receiving} 个节点还接收最多的字数（{most_out}）。",
        de: "Ein Beispiel, das gsdc aus der Beschreibung berechnet: {nodes} genutzte Knoten, jeder sendet seine meisten Wörter ({most_in}), so viele Knoten, wie {input_len} Byte Eingänge fassen; die ersten {receiving} davon empfangen auch ihre meisten Wörter ({most_out}).",
    };
    gateway_example_totals(input: u32, input_bytes: u32, output: u32, output_bytes: u32) = {
        en: " That is {input} words ({input_bytes} bytes) of input and {output} words ({output_bytes} bytes) of output. The master plugs the modules and sends the parameter telegram of the tables below.",
        zh: "即输入 {input} 个字（{input_bytes} 字节），输出 {output} 个字（{output_bytes} 字节）。主站插入下表的模块，并发送下表的参数报文。",
        de: " Das sind {input} Wörter ({input_bytes} Byte) Eingänge und {output} Wörter ({output_bytes} Byte) Ausgänge. Der Master steckt die Module und sendet das Parametriertelegramm der Tabellen unten.",
    };
    node(n: u8) = { en: "node {n}", zh: "节点 {n}", de: "Knoten {n}" };
    words_count(n: u8) = { en: "{n} words", zh: "{n} 个字", de: "{n} Wörter" };
    example_user_prm(len: usize) = {
        en: "User_Prm_Data of the example, {len} bytes",
        zh: "示例的 User_Prm_Data，{len} 字节",
        de: "User_Prm_Data des Beispiels, {len} Byte",
    };
    gateway_diagnosis_intro(standard: u8, bus: &str) = {
        en: "The master reads the slave's diagnosis (STEP 7: SFC13): {standard} standard bytes, then the device-related block: its header (bits 7-6 = 00, bits 5-0 = the block's length, the header included), the type, the {bus} node and the code, whose meaning depends on the type.",
        zh: "主站读取从站诊断数据（STEP 7：SFC13）：{standard} 个标准字节，之后是设备专用诊断块：块头（位 7-6 = 00，位 5-0 = 块长度，含块头）、类型、{bus} 节点号和故障码，故障码的含义取决于类型。",
        de: "Der Master liest die Diagnose des Slaves (STEP 7: SFC13): {standard} Standardbytes, dann den gerätebezogenen Block: sein Kopfbyte (Bit 7-6 = 00, Bit 5-0 = die Länge des Blocks, Kopfbyte eingeschlossen), den Typ, den {bus}-Knoten und den Code, dessen Bedeutung vom Typ abhängt.",
    };
    bits_of_byte(first: u16, last: u16, byte: u16) = {
        en: "bits {first}-{last} (byte {byte})",
        zh: "位 {first}-{last}（字节 {byte}）",
        de: "Bit {first}-{last} (Byte {byte})",
    };
    gsd_names_areas(areas: &str) = {
        en: "The GSD names the values of Unit_Diag_Area {areas}, counted from the byte after the header, so an engineering tool shows the type and the listed codes as text.",
        zh: "GSD 文件为 Unit_Diag_Area {areas}的取值命名（位从块头后一个字节算起），组态软件以文本显示类型和列出的故障码。",
        de: "Die GSD benennt die Werte von Unit_Diag_Area {areas}, gezählt ab dem Byte nach dem Kopfbyte, so dass ein Projektierungswerkzeug den Typ und die aufgeführten Codes als Text zeigt.",
    };
    diagnosis_type(value: &str) = { en: "type {value}", zh: "类型 {value}", de: "Typ {value}" };
    diagnosis_types(values: &str) = { en: "types {values}", zh: "类型 {values}", de: "Typen {values}" };
    length_of_types(len: u8, types: &str) = {
        en: "{len:02X} ({types})",
        zh: "{len:02X}（{types}）",
        de: same,
    };
    the_node(bus: &str, range: &str) = {
        en: "the {bus} node, {range}",
        zh: "{bus} 节点号，{range}",
        de: "der {bus}-Knoten, {range}",
    };
    types_code(types: &str) = {
        en: "{types}: the code",
        zh: "{types}：故障码",
        de: "{types}: der Code",
    };
    /// A type's code of 16 bits: its name, and which half of it a byte is.
    type_code_word_half(types: &str, name: &str, half: &str) = {
        en: "{types}: {name}, {half}",
        zh: "{types}：{name}，{half}",
        de: same,
    };
    diagnosis_types_caption(node: u8) = {
        en: "Diagnosis types and codes, with the block each gives at node {node}",
        zh: "诊断类型与故障码，及节点 {node} 报出的诊断块",
        de: "Diagnosetypen und -codes, mit dem Block, den jeder bei Knoten {node} meldet",
    };

    // -----------------------------------------------------------------------
    // Tested on the wire (`gsdc doc --wire-results`)

    TESTED_ON_THE_WIRE = {
        en: "Tested on the wire",
        zh: "总线实测",
        de: "Auf dem Bus getestet",
    };
    no_wire_exchange(file: &str) = {
        en: "{file}: no exchange on the wire is recorded for this file (the results given are of other files, or of none on this bus).",
        zh: "{file}：此文件没有总线交换记录（所给的结果属于其他文件，或没有此总线的结果）。",
        de: "{file}: für diese Datei ist kein Austausch auf dem Bus aufgezeichnet (die angegebenen Ergebnisse gehören zu anderen Dateien oder zu keiner auf diesem Bus).",
    };
    wire_dp(file: &str, passed: usize, master: &str, reader: &str, sha256: &str) = {
        en: "{file}: every exchange passed ({passed} of them) between the DP master {master}, configured only from this file through {reader}, and a DP slave built only from this description's layout (wire/dp). The file's SHA-256: {sha256}.",
        zh: "{file}：仅由此文件（经 {reader} 读取）配置的 DP 主站 {master} 与仅由本描述的布局构建的 DP 从站（wire/dp）之间的全部交换（{passed} 项）均通过。该文件的 SHA-256：{sha256}。",
        de: "{file}: alle Austausche bestanden ({passed}) zwischen dem DP-Master {master}, nur aus dieser Datei über {reader} konfiguriert, und einem DP-Slave, nur aus dem Layout dieser Beschreibung gebaut (wire/dp). SHA-256 der Datei: {sha256}.",
    };
    wire_pn(file: &str, passed: usize, controller: &str, device: &str, sha256: &str) = {
        en: "{file}: every exchange passed ({passed} of them) between the IO controller {controller}, configured only from this file, and the IO device {device}, built only from this description's layout (wire/pn). The file's SHA-256: {sha256}.",
        zh: "{file}：仅由此文件配置的 IO 控制器 {controller} 与仅由本描述的布局构建的 IO 设备 {device}（wire/pn）之间的全部交换（{passed} 项）均通过。该文件的 SHA-256：{sha256}。",
        de: "{file}: alle Austausche bestanden ({passed}) zwischen dem IO-Controller {controller}, nur aus dieser Datei konfiguriert, und dem IO-Device {device}, nur aus dem Layout dieser Beschreibung gebaut (wire/pn). SHA-256 der Datei: {sha256}.",
    };

    // -----------------------------------------------------------------------
    // What the manual gives besides the telegrams: where each mapping is
    // set, the set-up, the manual's worked examples, a draft's notice

    /// The title's notice while the description has a placeholder.
    draft_notice(placeholders: &str) = {
        en: "DRAFT, not for release (placeholders: {placeholders}): ",
        zh: "草稿，不得发布（占位值：{placeholders}）：",
        de: "ENTWURF, nicht zur Freigabe (Platzhalter: {placeholders}): ",
    };
    GSDC_LAYOUT = { en: "gsdc's layout", zh: "gsdc 布局", de: "Anordnung von gsdc" };
    FAIL_SAFE = {
        en: "Fail_Safe (no output data in Clear)",
        zh: "Fail_Safe（Clear 时无输出数据）",
        de: "Fail_Safe (keine Ausgangsdaten im Zustand Clear)",
    };
    FAIL_SAFE_REQUIRED = {
        en: "Fail_Safe_required (the master must use Fail_Safe)",
        zh: "Fail_Safe_required（主站必须使用 Fail_Safe）",
        de: "Fail_Safe_required (der Master muss Fail_Safe nutzen)",
    };
    WHERE_SET_HEADING = {
        en: "Where each mapping is set",
        zh: "各映射在何处设置",
        de: "Wo jede Zuordnung eingestellt wird",
    };
    SET_BY_THE_MASTER_PARA = {
        en: "Set by the master: the configuration tool holds the values, and the master writes them at every startup, on PROFIBUS in the parameter telegram (User_Prm_Data), on PROFINET in the module's parameter records. A value changed at the drive is overwritten at the next startup.",
        zh: "由主站设置：数值保存在组态软件中，主站在每次启动时写入，PROFIBUS 通过参数报文（User_Prm_Data），PROFINET 通过模块的参数记录。在变频器上修改的值会在下次启动时被覆盖。",
        de: "Vom Master eingestellt: das Projektierungswerkzeug hält die Werte, und der Master schreibt sie bei jedem Anlauf, bei PROFIBUS im Parametriertelegramm (User_Prm_Data), bei PROFINET in den Parameterdatensätzen des Moduls. Ein am Antrieb geänderter Wert wird beim nächsten Anlauf überschrieben.",
    };
    SET_AT_THE_DRIVE_PARA = {
        en: "Set at the drive: with its keypad, a PKW write or the drive's own tool, as its parameters. No parameter telegram or record carries them: the master writes nothing at startup, and the card uses what the drive holds.",
        zh: "在变频器上设置：通过键盘、PKW 写操作或变频器自身的工具，作为其功能参数设置。参数报文和参数记录都不包含这些参数：主站在启动时不写入任何值，扩展卡使用变频器中保存的值。",
        de: "Am Antrieb eingestellt: über sein Bedienfeld, einen PKW-Schreibauftrag oder das Werkzeug des Antriebs, als seine Parameter. Kein Parametriertelegramm und kein Datensatz überträgt sie: der Master schreibt beim Anlauf nichts, und die Karte verwendet, was der Antrieb hält.",
    };
    WHERE_SET_CAPTION = {
        en: "Where each mapping is set",
        zh: "各映射的设置位置",
        de: "Einstellort jeder Zuordnung",
    };
    MAPPING = { en: "Mapping", zh: "映射", de: "Zuordnung" };
    DRIVE_PARAMETERS = { en: "Drive parameters", zh: "变频器参数", de: "Antriebsparameter" };
    SET = { en: "Set", zh: "设置", de: "Eingestellt" };
    CARRIED_BY = { en: "Carried by", zh: "承载方式", de: "Übertragen in" };
    BY_THE_MASTER = { en: "by the master", zh: "由主站设置", de: "vom Master" };
    AT_THE_DRIVE = { en: "at the drive", zh: "在变频器上设置", de: "am Antrieb" };
    in_record(index: u16) = { en: "record {index}", zh: "记录 {index}", de: "Datensatz {index}" };
    NOTHING_THE_DRIVE_HOLDS = {
        en: "nothing: the drive holds them",
        zh: "无：由变频器保存",
        de: "nichts: der Antrieb hält sie",
    };
    /// Between the parts of a cell that says several things.
    SEMICOLON = { en: "; ", zh: "；", de: same };
    /// What the manual names a byte of the diagnosis, and the areas in it.
    byte_and_areas(said: &str, areas: &str) = {
        en: "{said}: {areas}",
        zh: "{said}：{areas}",
        de: same,
    };
    SETUP_HEADING = { en: "Setting up the drive", zh: "变频器设置", de: "Einstellungen am Antrieb" };
    SETUP_INTRO = {
        en: "What the manual tells the user to set on the drive and the card, and what it says of them, each table as the section of the manual it names gives it.",
        zh: "手册要求在变频器和扩展卡上进行的设置及其说明，每个表格按所注明的手册章节列出。",
        de: "Was das Handbuch am Antrieb und an der Karte einzustellen vorgibt und was es dazu sagt, jede Tabelle so, wie der genannte Abschnitt des Handbuchs sie gibt.",
    };
    SETTING = { en: "Setting", zh: "设置项", de: "Einstellung" };
    manual_section_titled(section: &str, title: &str) = {
        en: "Manual {section}: {title}",
        zh: "手册 {section}：{title}",
        de: "Handbuch {section}: {title}",
    };
    manual_section(section: &str) = {
        en: "Manual {section}",
        zh: "手册 {section}",
        de: "Handbuch {section}",
    };
    /// A setting's value and what it means.
    value_means(value: &str, meaning: &str) = {
        en: "{value}: {meaning}",
        zh: "{value}：{meaning}",
        de: same,
    };
    MANUAL_EXAMPLES_INTRO = {
        en: "The manual's examples, as it prints them; the last column is what the firmware layout's codec reads in them (gsdc's words).",
        zh: "手册中的示例，按手册原样列出；最后一列为固件数据布局的解码代码对其的解读（gsdc 的说明）。",
        de: "Die Beispiele des Handbuchs, wie es sie druckt; die letzte Spalte ist, was der Codec des Firmware-Layouts darin liest (Worte von gsdc).",
    };
    section_figure(section: &str, figure: &str) = {
        en: "{section}, {figure}",
        zh: "{section}，{figure}",
        de: same,
    };
    PKW_OF_EVERY_MODULE = {
        en: "the PKW words of every module",
        zh: "各模块的 PKW",
        de: "die PKW-Wörter jedes Moduls",
    };
    MANUAL_EXAMPLES_CAPTION = {
        en: "Worked examples of the manual",
        zh: "手册中的应用举例",
        de: "Beispiele des Handbuchs",
    };
    MANUAL = { en: "Manual", zh: "手册", de: "Handbuch" };
    BYTES_AS_PRINTED = { en: "Bytes as printed", zh: "数据（手册原样）", de: "Bytes wie gedruckt" };
    MEANING_THE_MANUALS = {
        en: "Meaning (the manual's)",
        zh: "含义（手册原文）",
        de: "Bedeutung (laut Handbuch)",
    };
    READ_BY_THE_CODEC = { en: "Read by the codec", zh: "解码结果", de: "Vom Codec gelesen" };
    /// One telegram of an example whose word the manual names.
    named_word_reads(name: &str, value: u16, read: &str) = {
        en: "{name} = {value}: {read}",
        zh: "{name} = {value}：{read}",
        de: same,
    };
    change_to_value(name: &str, value: &str) = {
        en: "change {name} to {value}",
        zh: "将 {name} 改为 {value}",
        de: "{name} auf {value} ändern",
    };
    done_value(name: &str, value: &str) = {
        en: "done: {name} = {value}",
        zh: "操作正确：{name} = {value}",
        de: "ausgeführt: {name} = {value}",
    };
    cannot_execute_at(name: &str, meaning: &str) = {
        en: "cannot execute {name}: {meaning}",
        zh: "无法执行 {name}：{meaning}",
        de: "{name} nicht ausführbar: {meaning}",
    };
    REFUSED = { en: "refused", zh: "拒绝", de: "abgewiesen" };
    A_REQUEST_THE_CODEC_READS = {
        en: "a request the codec reads",
        zh: "可解码的请求",
        de: "ein Auftrag, den der Codec liest",
    };
    A_RESPONSE_THE_CODEC_READS = {
        en: "a response the codec reads",
        zh: "可解码的响应",
        de: "eine Antwort, die der Codec liest",
    };
    /// A computed example's failure: the error code left open.
    cannot_execute_eeee(first: u16, last: u16) = {
        en: "cannot execute: error code eeee, {first} to {last}",
        zh: "无法执行：错误代码 eeee，{first}～{last}",
        de: "nicht ausführbar: Fehlercode eeee, {first} bis {last}",
    };
    VVVV_EEEE_LEGEND = {
        en: "vvvv: the parameter's value; eeee: the error code.",
        zh: "vvvv：参数值；eeee：错误代码。",
        de: "vvvv: der Wert des Parameters; eeee: der Fehlercode.",
    };
}
