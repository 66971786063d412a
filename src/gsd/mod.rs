//! GSD reader, keyword schema and rules (being written).
