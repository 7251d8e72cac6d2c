//! Binary-only parts of the command line.

pub mod accuracy;
pub mod accuracy_table;
pub mod progress;
pub mod report;
pub mod stats;
