//! The result every front end returns, and dispatch by file extension.

use crate::diag::Diagnostics;
use crate::ir::Scene;

/// What a front end produced: a scene when there were no errors, and every finding either way.
#[derive(Debug, Default)]
pub struct Loaded {
    /// The evaluated scene; `None` when errors prevent one.
    pub scene: Option<Scene>,
    /// Errors, warnings and notes from every stage that ran.
    pub diagnostics: Diagnostics,
}
