//! Shared helpers for the command-line tests: run the `rtc` binary, make a scratch directory.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs the `rtc` binary with `args` from the repository root.
#[allow(dead_code)] // not every test that shares these helpers runs the binary
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

/// Every file below `dir` whose extension is one of `extensions`, in sorted path order.
#[allow(dead_code)] // not every command-line test walks a folder
pub fn files_below(dir: &Path, extensions: &[&str]) -> Vec<PathBuf> {
    fn walk(dir: &Path, extensions: &[&str], out: &mut Vec<PathBuf>) {
        let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        entries.sort();
        for p in entries {
            if p.is_dir() {
                walk(&p, extensions, out);
            } else if p
                .extension()
                .is_some_and(|e| extensions.iter().any(|x| e == *x))
            {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    walk(dir, extensions, &mut out);
    out
}
