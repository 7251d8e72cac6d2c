//! Compatibility front ends for the course's legacy scene files (COURSE.md): the Magdeburg `.in`
//! format and the Groningen course YAML. Both produce the same IR as the scene language.

pub mod build;
pub mod course_yaml;
pub mod legacy_in;
pub mod spans;
pub mod yaml_objects;
pub mod yaml_tree;
pub mod yaml_values;

use std::path::Path;

use crate::diag::{Diagnostic, Diagnostics, Severity};
use crate::frontend::Loaded;
use crate::source::{FileId, SourceMap, Span};

pub use spans::erase_spans;

/// Reads a legacy `.in` file (COURSE.md §1) into the IR.
pub fn load_in(path: &Path, sources: &mut SourceMap) -> Loaded {
    match read(path) {
        Ok(text) => load_in_source(path, &text, sources),
        Err(loaded) => loaded,
    }
}

/// Reads a course YAML scene (COURSE.md §2) into the IR.
pub fn load_yaml(path: &Path, sources: &mut SourceMap) -> Loaded {
    match read(path) {
        Ok(text) => load_yaml_source(path, &text, sources),
        Err(loaded) => loaded,
    }
}

/// Parses `.in` text as if read from `path` (which locates nothing; `.in` has no assets).
pub fn load_in_source(path: &Path, text: &str, sources: &mut SourceMap) -> Loaded {
    let file = sources.add(path, text);
    let mut diags = Diagnostics::default();
    let mut draft = build::Draft::default();
    legacy_in::parse(text, file, path, &mut draft, &mut diags);
    let scene = draft.finish(
        start_of(file),
        "add an eye record such as `Eye 200 200 1000`",
        &mut diags,
    );
    sort_by_position(&mut diags);
    Loaded {
        scene,
        diagnostics: diags,
    }
}

/// Parses course YAML text as if read from `path` (textures and meshes resolve against it).
pub fn load_yaml_source(path: &Path, text: &str, sources: &mut SourceMap) -> Loaded {
    let file = sources.add(path, text);
    let mut diags = Diagnostics::default();
    let scene = course_yaml::parse(text, file, path, &mut diags);
    sort_by_position(&mut diags);
    Loaded {
        scene,
        diagnostics: diags,
    }
}

/// Source order reads best: the readers visit keys in their own order, not the file's.
fn sort_by_position(diags: &mut Diagnostics) {
    diags
        .items
        .sort_by_key(|d| d.span.map_or((0, 0), |s| (s.start, s.end)));
}

fn start_of(file: FileId) -> Span {
    Span::new(file, 0, 0)
}

fn read(path: &Path) -> Result<String, Loaded> {
    std::fs::read_to_string(path).map_err(|e| {
        let mut diagnostics = Diagnostics::default();
        diagnostics.push(
            Diagnostic::new(
                Severity::Error,
                "rtc::io",
                None,
                format!("cannot read `{}`: {e}", path.display()),
            )
            .with_help("check the path and that the file is readable UTF-8 text"),
        );
        Loaded {
            scene: None,
            diagnostics,
        }
    })
}
