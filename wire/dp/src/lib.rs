//! The PROFIBUS-DP exchange.
