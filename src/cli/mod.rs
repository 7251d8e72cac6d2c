//! Binary-only parts of the command line.

pub(crate) mod accuracy;
mod accuracy_table;
pub(crate) mod aov;
pub(crate) mod check;
pub(crate) mod converge;
pub(crate) mod convert;
mod diff;
pub(crate) mod fmt;
mod frames;
pub(crate) mod inputs;
pub(crate) mod interrupt;
mod progress;
pub(crate) mod render;
pub(crate) mod report;
pub(crate) mod shard;
mod stats;
pub(crate) mod watch;
pub(crate) mod why;
mod why_json;

use std::path::Path;

use rtc::diag::{Diagnostics, IO_ERROR};
use rtc::eval::EvalOptions;
use rtc::ir::Loaded;
use rtc::source::SourceMap;

/// How a command ended.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Outcome {
    Ok,
    SceneErrors,
    IoOrUsage,
    Interrupted,
}

impl Outcome {
    /// Which outcome wins when several files are checked: I/O over scene errors over success.
    fn severity(self) -> u8 {
        match self {
            Outcome::Ok => 0,
            Outcome::SceneErrors => 1,
            Outcome::IoOrUsage => 2,
            Outcome::Interrupted => 3,
        }
    }
}

/// Reports a command-line mistake found before any scene is read (exit code 2).
pub(crate) fn usage_error(msg: &str) -> Outcome {
    eprintln!("error: {msg}");
    Outcome::IoOrUsage
}

/// Loads a scene and runs the scene lints on it.
fn load(file: &Path, sources: &mut SourceMap, opts: &EvalOptions) -> Loaded {
    let mut loaded = rtc::loader::load(file, sources, opts);
    if let Some(scene) = &loaded.scene {
        loaded.diagnostics.extend(rtc::check::lint(scene));
    }
    loaded
}

/// The exit outcome of a set of diagnostics (`--deny warnings` makes warnings fail).
fn outcome_of(diags: &Diagnostics, deny_warnings: bool) -> Outcome {
    if diags.items.iter().any(|d| d.code == IO_ERROR) {
        Outcome::IoOrUsage
    } else if diags.has_errors() || (deny_warnings && diags.warning_count() > 0) {
        Outcome::SceneErrors
    } else {
        Outcome::Ok
    }
}
