//! What a front end returns: the scene when there were no errors, and every finding either way.

use crate::diag::{Diagnostic, Diagnostics, Severity};

use super::Scene;

/// What a front end produced: a scene when there were no errors, and every finding either way.
#[derive(Debug, Default)]
pub struct Loaded {
    /// The evaluated scene; `None` when errors prevent one.
    pub scene: Option<Scene>,
    /// Errors, warnings and notes from every stage that ran.
    pub diagnostics: Diagnostics,
    /// Where each object came from, when evaluation was asked to record it
    /// (`EvalOptions::provenance`; the course front ends have no loops or calls: `None`).
    pub provenance: Option<super::Provenance>,
}

impl Loaded {
    /// A result holding a single error without a source location (I/O, usage).
    pub(crate) fn failure(code: &'static str, message: impl Into<String>, help: &str) -> Loaded {
        let mut diagnostics = Diagnostics::default();
        diagnostics.push(Diagnostic::new(Severity::Error, code, None, message).with_help(help));
        Loaded {
            scene: None,
            diagnostics,
            provenance: None,
        }
    }
}
