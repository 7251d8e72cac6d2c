//! Shared helpers for the command-line tests: run the `rtc` binary, make a scratch directory.

use std::path::PathBuf;
use std::process::{Command, Output};

/// Runs the `rtc` binary with `args` from the repository root.
pub fn rtc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the rtc binary runs")
}

/// A fresh directory for this test process and `name`.
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rtc-cli-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
