//! GSDML reader and rules beyond the schema (being written).
