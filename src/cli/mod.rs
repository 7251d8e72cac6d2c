//! Binary-only parts of the command line.

pub mod progress;
pub mod report;
pub mod shard;
pub mod stats;
