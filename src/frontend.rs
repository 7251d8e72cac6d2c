//! The result every front end returns, and dispatch by file extension.

use std::path::Path;

use crate::diag::{Diagnostic, Diagnostics, Severity};
use crate::eval::EvalOptions;
use crate::ir::Scene;
use crate::source::SourceMap;

/// Diagnostic code for files that cannot be read or written (the CLI exits with 2 on these).
pub const IO_ERROR: &str = "rtc::io";

/// What a front end produced: a scene when there were no errors, and every finding either way.
#[derive(Debug, Default)]
pub struct Loaded {
    /// The evaluated scene; `None` when errors prevent one.
    pub scene: Option<Scene>,
    /// Errors, warnings and notes from every stage that ran.
    pub diagnostics: Diagnostics,
}

impl Loaded {
    /// A result holding a single error without a source location (I/O, usage).
    pub fn failure(code: &'static str, message: impl Into<String>, help: &str) -> Loaded {
        let mut diagnostics = Diagnostics::default();
        diagnostics.push(Diagnostic::new(Severity::Error, code, None, message).with_help(help));
        Loaded {
            scene: None,
            diagnostics,
        }
    }

    /// True when any diagnostic is an I/O problem rather than a scene error.
    pub fn has_io_error(&self) -> bool {
        self.diagnostics.items.iter().any(|d| d.code == IO_ERROR)
    }
}

/// The scene formats rtc reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SceneFormat {
    /// The rtc scene language.
    Rtc,
    /// The course's legacy line-based format.
    LegacyIn,
    /// The course's YAML scenes.
    CourseYaml,
}

impl SceneFormat {
    /// The format implied by a file's extension.
    pub fn of(path: &Path) -> Option<SceneFormat> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "rtc" => Some(SceneFormat::Rtc),
            "in" => Some(SceneFormat::LegacyIn),
            "yaml" | "yml" => Some(SceneFormat::CourseYaml),
            _ => None,
        }
    }
}

/// Reads and evaluates any supported scene file into the IR.
pub fn load(path: &Path, sources: &mut SourceMap, options: &EvalOptions) -> Loaded {
    match SceneFormat::of(path) {
        Some(SceneFormat::Rtc) => crate::eval::load_file(path, sources, options),
        Some(SceneFormat::LegacyIn) => crate::compat::load_in(path, sources),
        Some(SceneFormat::CourseYaml) => crate::compat::load_yaml(path, sources),
        None => Loaded::failure(
            IO_ERROR,
            format!("`{}` is not a scene file rtc knows", path.display()),
            "scene files end in `.rtc`, `.in` (legacy course format) or `.yaml` (course YAML)",
        ),
    }
}
