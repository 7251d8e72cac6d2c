//! Binary-only parts of the command line.

pub mod accuracy;
pub mod accuracy_table;
pub mod check;
pub mod converge;
pub mod frames;
pub mod progress;
pub mod report;
pub mod shard;
pub mod stats;
pub mod watch;
