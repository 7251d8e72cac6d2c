//! Binary-only parts of the command line.

pub mod accuracy;
pub mod accuracy_table;
pub mod check;
pub mod frames;
pub mod converge;
pub mod progress;
pub mod report;
pub mod stats;
pub mod watch;
