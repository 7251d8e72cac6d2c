//! Compatibility front ends for the course's legacy scene files (COURSE.md): the Magdeburg `.in`
//! format and the Groningen course YAML. Both produce the same IR as the scene language.
//!
//! Mapping decisions (COURSE.md §4): the course camera ([`crate::ir::Projection::Course`]; no
//! `Camera` means eye = `Eye`, centre (200, 200, 0), up +Y, 400×400); `reflect = ks` unless the
//! file gives `reflect`; ambient per light; textured spheres sit at the origin with
//! [`course::sphere_orientation`]; assets resolve in the asset service's one search order
//! (`assets::search`).
//!
//! Diagnostic codes: `rtc::io` (unreadable file); `rtc::in::{unknown_record, expected_record,
//! expected_number, extra_number, truncated, unclosed, no_material, duplicate_eye}`;
//! `rtc::yaml::{syntax, empty, extra_document, too_large, type, arity, missing_key, duplicate_key,
//! unknown_key, spelling, unknown_value, unknown_object, unused}`; shared `rtc::compat::{not_finite,
//! out_of_range, degenerate, no_camera, camera_override, encoding, capped}`; the asset
//! service's `rtc::asset::missing` for a texture or mesh file that is not found. Shapes are
//! checked by geometry's rules when the scene is prepared (`rtc::param::*`, the codes the scene
//! language uses), not here: one home for shape validity.

mod course;
mod course_yaml;
mod legacy_in;
mod spans;
mod yaml_objects;
mod yaml_tree;
mod yaml_values;

use std::path::Path;

use crate::diag::{Diagnostic, Diagnostics, Severity};
use crate::ir::Loaded;
use crate::source::{FileId, SourceMap, Span};

pub use spans::erase_spans;

/// Reads a legacy `.in` file (COURSE.md §1) into the IR.
pub fn load_in(path: &Path, sources: &mut SourceMap) -> Loaded {
    match read(path) {
        Ok((text, latin1)) => {
            let loaded = load_in_source(path, &text, sources);
            with_encoding_note(loaded, latin1, sources)
        }
        Err(loaded) => loaded,
    }
}

/// Reads a course YAML scene (COURSE.md §2) into the IR.
pub fn load_yaml(path: &Path, sources: &mut SourceMap) -> Loaded {
    load_yaml_within(path, sources, crate::ir::limits::DEFAULT_MEMORY_BUDGET)
}

/// [`load_yaml`] under a memory budget of `max_memory` bytes (`--memory-budget`).
pub fn load_yaml_within(path: &Path, sources: &mut SourceMap, max_memory: u64) -> Loaded {
    match read(path) {
        Ok((text, latin1)) => {
            let loaded = yaml_source_within(path, &text, sources, max_memory);
            with_encoding_note(loaded, latin1, sources)
        }
        Err(loaded) => loaded,
    }
}

/// Parses `.in` text as if read from `path` (which locates nothing; `.in` has no assets).
pub fn load_in_source(path: &Path, text: &str, sources: &mut SourceMap) -> Loaded {
    let file = sources.add(path, text);
    let mut diags = Diagnostics::default();
    let mut draft = course::Draft::default();
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
        provenance: None,
    }
}

/// Parses course YAML text as if read from `path` (textures and meshes resolve against it).
pub fn load_yaml_source(path: &Path, text: &str, sources: &mut SourceMap) -> Loaded {
    yaml_source_within(
        path,
        text,
        sources,
        crate::ir::limits::DEFAULT_MEMORY_BUDGET,
    )
}

fn yaml_source_within(path: &Path, text: &str, sources: &mut SourceMap, max_memory: u64) -> Loaded {
    let file = sources.add(path, text);
    let mut diags = Diagnostics::default();
    let memory = crate::ir::limits::Memory::new(max_memory);
    let scene = course_yaml::parse(text, file, path, &mut diags, memory);
    sort_by_position(&mut diags);
    Loaded {
        scene,
        diagnostics: diags,
        provenance: None,
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

/// The file's text, and (when it had to be decoded as Latin-1) the byte offset of the first
/// non-UTF-8 byte in the decoded text. Old course files come from systems where Latin-1 was the
/// default; every byte is then one character.
fn read(path: &Path) -> Result<(String, Option<usize>), Loaded> {
    let bytes =
        crate::source::read_regular(path, crate::source::MAX_SOURCE_BYTES).map_err(|e| {
            let mut diagnostics = Diagnostics::default();
            diagnostics.push(
                Diagnostic::new(
                    Severity::Error,
                    crate::diag::IO_ERROR,
                    None,
                    format!("cannot read `{}`: {e}", path.display()),
                )
                .with_help("check the path and that the file is readable"),
            );
            Loaded {
                scene: None,
                diagnostics,
                provenance: None,
            }
        })?;
    Ok(match String::from_utf8(bytes) {
        Ok(text) => (text, None),
        Err(e) => {
            let bytes = e.as_bytes();
            let valid = e.utf8_error().valid_up_to();
            let at = bytes[..valid]
                .iter()
                .map(|&b| if b < 0x80 { 1 } else { 2 })
                .sum();
            (bytes.iter().map(|&b| char::from(b)).collect(), Some(at))
        }
    })
}

/// Adds the Latin-1 warning to the file just loaded (the last one in `sources`).
fn with_encoding_note(mut loaded: Loaded, latin1: Option<usize>, sources: &SourceMap) -> Loaded {
    let (Some(at), Some(last)) = (latin1, sources.files().len().checked_sub(1)) else {
        return loaded;
    };
    let file = FileId(last as u32);
    let text = &sources.get(file).text;
    let end = text[at..].chars().next().map_or(at, |c| at + c.len_utf8());
    loaded.diagnostics.items.insert(
        0,
        Diagnostic::warning(
            "rtc::compat::encoding",
            Span::new(file, at, end),
            "the file is not UTF-8; it was read as Latin-1",
        )
        .with_label("first byte that is not UTF-8")
        .with_help("save the file as UTF-8"),
    );
    loaded
}
