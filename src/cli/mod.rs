//! Binary-only parts of the command line.

pub mod report;
pub mod stats;
