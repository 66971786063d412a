//! `[profinet.irt]` and `[profinet.isochronous]`: a card whose PROFINET
//! ASIC runs isochronous real time (RT_CLASS_3, conformance class C), and
//! whose application follows the isochronous cycle. Each value is the
//! number the GSDML file writes, in its units.

use serde::Deserialize;
use toml::Spanned;

/// RT_CLASS_3: the interface's `RT_Class3Properties`,
/// `SynchronisationMode` and `RT_Class3TimingProperties`, and each port's
/// delays.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Irt {
    /// `MaxBridgeDelay`: ns from a frame's arrival at one port to its
    /// sending at the other.
    pub max_bridge_delay: Spanned<u16>,
    /// `MaxNumberIR_FrameData`: the IRT frames the ASIC holds (0..1024).
    pub max_number_ir_frame_data: Spanned<u16>,
    /// `ForwardingMode`: `"Absolute"`, `"Relative"`; unwritten when left out.
    pub forwarding_mode: Option<Spanned<Vec<Spanned<ForwardingMode>>>>,
    /// `StartupMode` of RT_CLASS_3; unwritten (the schema's `Legacy`) when
    /// left out.
    pub startup_mode: Option<Spanned<Vec<Spanned<StartupMode>>>>,
    /// `RT_Class3TimingProperties`: SendClock factors (31.25 us).
    pub send_clock: Spanned<Vec<Spanned<u16>>>,
    pub reduction_ratio: Spanned<Vec<Spanned<u16>>>,
    pub preferred_send_clock: Option<Spanned<u16>>,
    /// `SynchronisationMode`: `MaxLocalJitter` and `T_PLL_MAX` (ns).
    pub max_local_jitter: Option<Spanned<u16>>,
    pub t_pll_max: Option<Spanned<u16>>,
    /// Each port's `MaxPortTxDelay` and `MaxPortRxDelay` (ns).
    pub port_tx_delay: Spanned<u16>,
    pub port_rx_delay: Spanned<u16>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Deserialize)]
pub enum ForwardingMode {
    Absolute,
    Relative,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Deserialize)]
pub enum StartupMode {
    Legacy,
    Advanced,
}

/// Isochronous mode: the `IsochroneMode` of each module's data submodule.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Isochronous {
    /// `IsochroneModeRequired`: the card runs only isochronously.
    pub required: Option<Spanned<bool>>,
    /// `T_DC_Base` (31.25 us, 1..1024), `T_DC_Min`, `T_DC_Max` (its
    /// multiples): the data cycles the application follows.
    pub t_dc_base: Spanned<u16>,
    pub t_dc_min: Spanned<u16>,
    pub t_dc_max: Spanned<u16>,
    /// `T_IO_Base` (ns, 1..32000000), `T_IO_InputMin`, `T_IO_OutputMin`
    /// (its multiples): the least times to read the inputs before and to
    /// apply the outputs after the cycle's start.
    pub t_io_base: Spanned<u32>,
    pub t_io_input_min: Spanned<u32>,
    pub t_io_output_min: Spanned<u32>,
}
