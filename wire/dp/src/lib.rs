//! The PROFIBUS-DP exchange: a DP slave built from the layouts of
//! wire-firmware ([`slave`]) on profirust's simulated bus ([`station`]),
//! and profirust's DP master configured only from the GSD file ([`gsd`],
//! [`bus`]); [`exchange`] runs them through every module, the manuals'
//! exchanges ([`manuals`]) and the mistakes a master must see refused.

pub mod bus;
pub mod exchange;
pub mod gateway;
pub mod gsd;
pub mod manuals;
pub mod report;
pub mod slave;
pub mod station;
