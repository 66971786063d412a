//! gsdc's words in the GSDML: the names and descriptions of its modules,
//! records, catalogue groups and ports, the PROFIdrive words and the PKW
//! channel's words. The German follows Siemens' German PROFIdrive terms
//! (Steuerwort, Zustandswort, Drehzahlsollwert, Parameterdatensatz).

use super::phrases;

phrases! {
    /// The PROFIdrive module access point, named as ABB's FENA names it.
    MODULE_ACCESS_POINT = { en: "Module Access Point", zh: "模块访问点", de: "Modulzugriffspunkt" };
    MODULE_ACCESS_POINT_INFO = {
        en: "PROFIdrive parameter access through this submodule",
        zh: "通过此子模块进行 PROFIdrive 参数访问",
        de: "PROFIdrive-Parameterzugriff über dieses Submodul",
    };

    /// The hardware catalogue's groups.
    CATEGORY_STANDARD_TELEGRAMS = { en: "Standard telegrams", zh: "标准报文", de: "Standardtelegramme" };
    CATEGORY_PKW_PZD = { en: "PKW and PZD", zh: "PKW 和 PZD", de: "PKW und PZD" };
    CATEGORY_PZD = { all: "PZD" };

    /// PROFIdrive's name of its telegram 1.
    STANDARD_TELEGRAM_1 = { en: "Standard telegram 1", zh: "标准报文 1", de: "Standardtelegramm 1" };
    STANDARD_TELEGRAM_2 = { en: "Standard telegram 2", zh: "标准报文 2", de: "Standardtelegramm 2" };

    /// What a module carries.
    profidrive_telegram_1_info(bytes: u16) = {
        en: "PROFIdrive standard telegram 1: STW1 and NSOLL_A to the drive, ZSW1 and NIST_A from it; {bytes} bytes each way",
        zh: "PROFIdrive 标准报文 1：STW1 和 NSOLL_A 发往驱动器，ZSW1 和 NIST_A 来自驱动器；每个方向 {bytes} 字节",
        de: "PROFIdrive-Standardtelegramm 1: STW1 und NSOLL_A zum Antrieb, ZSW1 und NIST_A vom Antrieb; {bytes} Byte je Richtung",
    };
    profidrive_telegram_2_info(bytes: u16) = {
        en: "PROFIdrive standard telegram 2: STW1, NSOLL_B (32 bits) and STW2 to the drive, ZSW1, NIST_B (32 bits) and ZSW2 from it; {bytes} bytes each way",
        zh: "PROFIdrive 标准报文 2：STW1、NSOLL_B（32 位）和 STW2 发往驱动器，ZSW1、NIST_B（32 位）和 ZSW2 来自驱动器；每个方向 {bytes} 字节",
        de: "PROFIdrive-Standardtelegramm 2: STW1, NSOLL_B (32 Bit) und STW2 zum Antrieb, ZSW1, NIST_B (32 Bit) und ZSW2 vom Antrieb; {bytes} Byte je Richtung",
    };
    /// A vendor's telegram 1, under the name the description gives it.
    vendor_telegram_1_info(name: &str, n: u8, bytes: u16) = {
        en: "{name}: {n} PZD words; {bytes} bytes each way",
        zh: "{name}：{n} 个 PZD 字；每个方向 {bytes} 字节",
        de: "{name}: {n} PZD-Wörter; {bytes} Byte je Richtung",
    };
    pzd_module_info(n: u8, bytes: u16) = {
        en: "{n} PZD words; {bytes} bytes each way",
        zh: "{n} 个 PZD 字；每个方向 {bytes} 字节",
        de: "{n} PZD-Wörter; {bytes} Byte je Richtung",
    };
    pzd_module_info_one(bytes: u16) = {
        en: "1 PZD word; {bytes} bytes each way",
        zh: "1 个 PZD 字；每个方向 {bytes} 字节",
        de: "1 PZD-Wort; {bytes} Byte je Richtung",
    };
    pkw_pzd_module_info(pkw: u8, n: u8, bytes: u16) = {
        en: "PKW channel ({pkw} words) and {n} PZD words; {bytes} bytes each way",
        zh: "PKW 通道（{pkw} 个字）和 {n} 个 PZD 字；每个方向 {bytes} 字节",
        de: "PKW-Kanal ({pkw} Wörter) und {n} PZD-Wörter; {bytes} Byte je Richtung",
    };
    pkw_pzd_module_info_one(pkw: u8, bytes: u16) = {
        en: "PKW channel ({pkw} words) and 1 PZD word; {bytes} bytes each way",
        zh: "PKW 通道（{pkw} 个字）和 1 个 PZD 字；每个方向 {bytes} 字节",
        de: "PKW-Kanal ({pkw} Wörter) und 1 PZD-Wort; {bytes} Byte je Richtung",
    };
    /// gsdc's description of a module, then the description's own words.
    with_info(gsdc: &str, info: &str) = {
        en: "{gsdc}. {info}",
        zh: "{gsdc}。{info}",
        de: same,
    };

    /// PROFIdrive's telegram 1 words, with the profile's names (MASTERDRIVES
    /// Compendium table 8.2-16; the German names are the profile's own).
    STW1 = { en: "STW1 (control word 1)", zh: "STW1（控制字 1）", de: "STW1 (Steuerwort 1)" };
    NSOLL_A = { en: "NSOLL_A (speed setpoint A)", zh: "NSOLL_A（速度设定值 A）", de: "NSOLL_A (Drehzahlsollwert A)" };
    ZSW1 = { en: "ZSW1 (status word 1)", zh: "ZSW1（状态字 1）", de: "ZSW1 (Zustandswort 1)" };
    NIST_A = { en: "NIST_A (speed actual value A)", zh: "NIST_A（速度实际值 A）", de: "NIST_A (Drehzahlistwert A)" };
    /// Telegram 2's further words: the 32-bit speed setpoint and actual
    /// value (ABB FENA's GSDML: "Fail safe NSOLL_B", "Fail safe STW2", an
    /// Unsigned32 between two Unsigned16 each way), control and status word
    /// 2 (SINAMICS G120 Fieldbuses function manual, A5E34229197B, 3.1.1.2:
    /// "Control word 2 (STW2)", "Status word 2 (ZSW2)", in telegrams 2, 3
    /// and 4).
    STW2 = { en: "STW2 (control word 2)", zh: "STW2（控制字 2）", de: "STW2 (Steuerwort 2)" };
    NSOLL_B = { en: "NSOLL_B (speed setpoint B)", zh: "NSOLL_B（速度设定值 B）", de: "NSOLL_B (Drehzahlsollwert B)" };
    ZSW2 = { en: "ZSW2 (status word 2)", zh: "ZSW2（状态字 2）", de: "ZSW2 (Zustandswort 2)" };
    NIST_B = { en: "NIST_B (speed actual value B)", zh: "NIST_B（速度实际值 B）", de: "NIST_B (Drehzahlistwert B)" };

    /// The PKW channel's words, the same both ways (MD810's manual writes
    /// `PWE 高 16 位`, `低 16 位`; PROFIdrive's and MV810's names).
    PKE = { all: "PKE" };
    IND = { all: "IND" };
    PWE_HIGH = { en: "PWE high", zh: "PWE 高 16 位", de: "PWE, höherwertiges Wort" };
    PWE_LOW = { en: "PWE low", zh: "PWE 低 16 位", de: "PWE, niederwertiges Wort" };
    PWE1 = { all: "PWE1" };
    PWE2 = { all: "PWE2" };
    PKW_STATION = { en: "Station", zh: "站号", de: same };
    PKW_COMMAND = { en: "Command", zh: "命令", de: "Befehl" };
    PKW_ADDRESS = { en: "Address", zh: "地址", de: "Adresse" };
    PKW_VALUE = { en: "Value", zh: "数值", de: "Wert" };

    /// A bit of a field of several bits: `Control mode bit 1`.
    field_bit(field: &str, index: u8) = {
        en: "{field} bit {index}",
        zh: same,
        de: "{field} Bit {index}",
    };

    /// gsdc's names of the parameter records.
    RECORD_PZD_OUT = {
        en: "PZD output mapping (controller to drive)",
        zh: "PZD 输出映射（控制器到驱动器）",
        de: "PZD-Zuordnung Ausgänge (Controller zum Antrieb)",
    };
    RECORD_PZD_IN = {
        en: "PZD input mapping (drive to controller)",
        zh: "PZD 输入映射（驱动器到控制器）",
        de: "PZD-Zuordnung Eingänge (Antrieb zum Controller)",
    };
    RECORD_INDEXES = { en: "Record index mapping", zh: "记录索引映射", de: "Zuordnung der Datensatzindizes" };
    RECORD_SETTINGS = { en: "Drive settings", zh: "驱动器设置", de: "Antriebseinstellungen" };

    port(number: u8) = { en: "Port {number}", zh: "端口 {number}", de: same };

    // -----------------------------------------------------------------------
    // What gsdc decides where the description says nothing: the headers
    // list it in English, the datasheet's checklist in the page's language.

    NOT_ASSIGNED_BY_PI = { en: "not assigned by PI", zh: "非 PI 分配", de: "nicht von PI vergeben" };
    NOT_COMPUTED_BY_PI_CHECKER = {
        en: "not what PI's GSDML checker computes",
        zh: "非 PI GSDML 检查器计算的值",
        de: "nicht vom GSDML-Checker der PI berechnet",
    };
    NOT_COMPUTED_FOR_THE_MODULE = {
        en: "not the CRCs computed for the module",
        zh: "非为该模块计算的 CRC",
        de: "nicht die für das Modul berechneten CRCs",
    };
    NOT_STATED = {
        en: "the description does not state it",
        zh: "设备描述未说明",
        de: "die Beschreibung gibt ihn nicht an",
    };
    IDENT_NUMBERS = { en: "profinet ident numbers", zh: "PROFINET 标识号", de: "PROFINET-Identnummern" };
    IDENT_NUMBERS_REST = {
        en: "profinet ident numbers [profinet.ident_numbers] does not state",
        zh: "[profinet.ident_numbers] 未给出的 PROFINET 标识号",
        de: "PROFINET-Identnummern, die [profinet.ident_numbers] nicht angibt",
    };
    IDENT_NUMBERS_RULE = {
        en: "modules 0x0000_01nn for nn PZD words, 0x0000_02nn with the PKW channel, 0x0000_0010 and 0x0000_0020 for standard telegrams 1 and 2, each submodule its module's; the DAP and its submodule 0x0000_0001; the interface and ports their subslots (0x8000, 0x8001...)",
        zh: "模块：nn 个 PZD 字为 0x0000_01nn，带 PKW 通道为 0x0000_02nn，标准报文 1 和 2 为 0x0000_0010 和 0x0000_0020，各子模块与其模块相同；DAP 及其子模块为 0x0000_0001；接口和各端口为其子槽号（0x8000、0x8001……）",
        de: "Module 0x0000_01nn für nn PZD-Wörter, 0x0000_02nn mit dem PKW-Kanal, 0x0000_0010 und 0x0000_0020 für die Standardtelegramme 1 und 2, jedes Submodul die seines Moduls; der DAP und sein Submodul 0x0000_0001; die Schnittstelle und die Ports ihre Subslots (0x8000, 0x8001...)",
    };
    IDENT_NUMBERS_WHY = {
        en: "the manual gives none; the layouts carry each",
        zh: "手册未给出；固件数据布局包含每一个",
        de: "das Handbuch nennt keine; die Layouts enthalten jede",
    };
    DAP = { en: "profinet device access point", zh: "PROFINET 设备访问点", de: "PROFINET-Gerätezugangspunkt (DAP)" };
    DAP_SERVICES = { all: "MultipleWriteSupported, LLDP_NoD_Supported, ResetToFactoryModes 2" };
    DAP_SERVICES_WHY = {
        en: "PNIO_Version V2.31 and later requires them; the manual does not say: the card's PROFINET stack must provide them",
        zh: "PNIO_Version V2.31 及以后版本要求；手册未说明：扩展卡的 PROFINET 协议栈必须支持",
        de: "PNIO_Version V2.31 und später fordert sie; das Handbuch sagt nichts dazu: der PROFINET-Stack der Karte muss sie bieten",
    };
    INTERFACE = { en: "profinet interface", zh: "PROFINET 接口", de: "PROFINET-Schnittstelle" };
    INTERFACE_SERVICES = {
        en: "RT_CLASS_1; SNMP and LLDP; DCP and PTP boundaries; startup modes Legacy and Advanced; reduction ratios 1 to 512",
        zh: "RT_CLASS_1；SNMP 和 LLDP；DCP 和 PTP 边界；启动模式 Legacy 和 Advanced；缩减比 1 至 512",
        de: "RT_CLASS_1; SNMP und LLDP; DCP- und PTP-Grenzen; Anlaufarten Legacy und Advanced; Untersetzungsverhältnisse 1 bis 512",
    };
    INTERFACE_SERVICES_WHY = {
        en: "gsdc writes them for every PROFINET card; the manual does not say: the card's PROFINET stack must provide them",
        zh: "gsdc 为每个 PROFINET 扩展卡写入；手册未说明：扩展卡的 PROFINET 协议栈必须支持",
        de: "gsdc schreibt sie für jede PROFINET-Karte; das Handbuch sagt nichts dazu: der PROFINET-Stack der Karte muss sie bieten",
    };

    /// The notice before the device's InfoText while an identity number is
    /// a placeholder: what TIA Portal's catalog shows of a draft.
    draft_one(name: &str) = {
        en: "DRAFT, not for release: {name} is a placeholder, not assigned by PI. ",
        zh: "草稿，不得发布：{name} 为占位值，非 PI 分配。",
        de: "ENTWURF, nicht zur Freigabe: {name} ist ein Platzhalter, nicht von PI vergeben. ",
    };
    draft_many(names: &str) = {
        en: "DRAFT, not for release: {names} are placeholders, not assigned by PI. ",
        zh: "草稿，不得发布：{names} 为占位值，非 PI 分配。",
        de: "ENTWURF, nicht zur Freigabe: {names} sind Platzhalter, nicht von PI vergeben. ",
    };

    /// Why gsdc lays out what the manual gives no bytes for.
    CONFIG_IDENTIFIERS_REASON = {
        en: "the manual gives no config byte: PROFIdrive's PPO form, one general identifier byte each; the layouts carry each",
        zh: "手册未给出配置字节：采用 PROFIdrive 的 PPO 形式，每项一个通用标识字节；数据布局包含每个字节",
        de: "das Handbuch gibt kein Konfigurationsbyte an: die PPO-Form von PROFIdrive, je ein allgemeines Kennungsbyte; die Layouts enthalten jedes",
    };
    GATEWAY_CONFIG_IDENTIFIERS_REASON = {
        en: "the manual's module list is lost (2.4 step 5): DP's general identifier form, one byte per module; the layouts carry each",
        zh: "手册的模块列表已丢失（2.4 第 5 步）：采用 DP 的通用标识格式，每个模块一个字节；数据布局包含每个字节",
        de: "die Modulliste des Handbuchs fehlt (2.4 Schritt 5): die allgemeine Kennungsform von DP, ein Byte je Modul; die Layouts enthalten jedes",
    };
    GATEWAY_MAX_MODULE_REASON = {
        en: "the manual gives no number: the most modules a total of input words up to Max_Input_Len and one of output words up to Max_Output_Len need together, each made of as few modules as it can be",
        zh: "手册未给出数量：输入字总数（至 Max_Input_Len）与输出字总数（至 Max_Output_Len）各以最少的模块组成时，两者合计最多需要的模块数",
        de: "das Handbuch nennt keine Zahl: die meisten Module, die eine Summe von Eingangswörtern bis Max_Input_Len und eine von Ausgangswörtern bis Max_Output_Len zusammen brauchen, jede aus so wenigen Modulen wie möglich",
    };
    GATEWAY_USER_PRM_LAYOUT_REASON = {
        en: "the manual names the parameters (2.4 step 4), not their bytes: gsdc's order and offsets; the layouts carry each",
        zh: "手册给出了参数（2.4 第四步），未给出其字节位置：顺序与偏移由 gsdc 确定；数据布局包含每项",
        de: "das Handbuch nennt die Parameter (2.4 Schritt 4), nicht ihre Bytes: Reihenfolge und Offsets von gsdc; die Layouts enthalten jeden",
    };
    MAX_MODULE_REASON = {
        en: "a PPO type is the whole telegram, so the master plugs one module",
        zh: "一个 PPO 类型即整个报文，因此主站只插入一个模块",
        de: "ein PPO-Typ ist das ganze Telegramm, daher steckt der Master ein Modul",
    };
    USER_PRM_LAYOUT_REASON = {
        en: "the manual gives the entries, not their bytes: gsdc's order (the PZD words out, then in, the DPV1 indexes, the settings) and offsets; the layouts carry each",
        zh: "手册给出了各项，未给出其字节位置：顺序（先输出 PZD，再输入 PZD、DPV1 Index、设置）与偏移由 gsdc 确定；数据布局包含每项",
        de: "das Handbuch gibt die Einträge an, nicht ihre Bytes: Reihenfolge (die PZD-Wörter aus, dann ein, die DPV1-Indizes, die Einstellungen) und Offsets von gsdc; die Layouts enthalten jede",
    };
}
