//! Binary-only parts of the command line.

pub mod converge;
pub mod progress;
pub mod report;
pub mod stats;
