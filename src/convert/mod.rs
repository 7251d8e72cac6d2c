//! The rtc back end: an IR scene as rtc source. `rtc convert` (docs/convert.md) uses it for a
//! course scene (`.in` or YAML): the course front end reads the file into the IR, the writer
//! goes from that IR back to text, taking from the file only what the IR does not keep: its
//! comments (carried next to the items they precede) and the comments that name materials.
//! [`to_source`] writes the IR of any front end (tests/convert_roundtrip.rs evaluates it back to
//! the same IR for every scene of the repository).
//!
//! Exactness: numbers are written in shortest round-trip form, shapes with the parameters the
//! language stores unchanged, placements as methods whose composition reproduces the transform,
//! motion with the arguments that give back its numbers, the course camera as the field of view
//! whose pixel is |up| to the bit.

mod comments;
mod exact;
mod names;
mod pattern;
mod placement;
mod program;
mod shapes;
mod text;
mod view;
mod write;

use std::path::{Component, Path, PathBuf};

use crate::diag::{Diagnostic, Diagnostics, Severity};
use crate::ir::{MaterialId, Scene};
use crate::source::SourceMap;

use comments::{Comment, Syntax};

/// The result of a conversion: the rtc text unless the course file has errors, and every
/// diagnostic the course front end reported.
#[derive(Debug)]
pub struct Converted {
    /// The rtc source; `None` when the file has errors.
    pub text: Option<String>,
    /// The front end's findings (warnings come with a text too).
    pub diagnostics: Diagnostics,
}

/// Converts the course file at `path` (`.in`, `.yaml` or `.yml`); asset paths in the text are
/// relative to `out_dir`, the directory the rtc file will be in.
pub fn convert(path: &Path, out_dir: &Path, sources: &mut SourceMap) -> Converted {
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    let (loaded, syntax, format) = match ext.as_deref() {
        Some("in") => (
            crate::compat::load_in(path, sources),
            Syntax::In,
            "course `.in`",
        ),
        Some("yaml" | "yml") => (
            crate::compat::load_yaml(path, sources),
            Syntax::Yaml,
            "course YAML",
        ),
        _ => {
            let mut diagnostics = Diagnostics::default();
            diagnostics.push(
                Diagnostic::new(
                    Severity::Error,
                    "rtc::convert::format",
                    None,
                    format!("`{}` is not a course scene", path.display()),
                )
                .with_help("give a course file ending in `.in`, `.yaml` or `.yml`"),
            );
            return Converted {
                text: None,
                diagnostics,
            };
        }
    };
    let text = match &loaded.scene {
        Some(scene) if !loaded.diagnostics.has_errors() => {
            let source = &sources.get(scene.camera.span.file).text;
            let file_name = path
                .file_name()
                .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
            let comments = comments::scan(source, syntax);
            Some(to_rtc(
                scene,
                &comments,
                Some((&file_name, format)),
                out_dir,
            ))
        }
        _ => None,
    };
    Converted {
        text,
        diagnostics: loaded.diagnostics,
    }
}

/// The rtc source of `scene`, from any front end, that evaluates to the same scene (spans
/// apart; equal materials are shared by one `let`); asset and output paths are written
/// relative to `out_dir`, the directory the rtc file will be in.
pub fn to_source(scene: &Scene, out_dir: &Path) -> String {
    to_rtc(scene, &[], None, out_dir)
}

/// The rtc text of `scene` with the `comments` of the file it was read from; `origin` is the
/// course file's name and format.
fn to_rtc(
    scene: &Scene,
    comments: &[Comment],
    origin: Option<(&str, &str)>,
    out_dir: &Path,
) -> String {
    let spans = write::items(scene);
    let hint_of = |id: MaterialId| material_hint(scene, comments, &spans, id);
    let palette = names::palette(scene, |id| hint_of(id).map(|i| comments[i].text.clone()));
    // A comment that became a material's name is not repeated; comments naming materials of
    // YAML objects trail the `material:` key (`material: # blue`).
    let used: Vec<usize> = (0..scene.materials.len())
        .filter_map(|i| hint_of(MaterialId(i as u32)))
        .filter(|&i| !comments[i].own_line)
        .collect();
    let placed = write::place(comments, &spans, &used);
    let out_dir = absolute(out_dir);
    let asset = |p: &Path| relative(&out_dir, &absolute(p));
    let doc = write::Doc {
        origin,
        comments,
        asset: &asset,
    };
    write::write(scene, &doc, &palette, &placed)
}

/// The comment that names material `id`: the last one before the material's text and after
/// every item that ends before it (`material: # blue` in YAML, `#Blue sphere` before an `.in`
/// `Material` record).
fn material_hint(
    scene: &Scene,
    comments: &[Comment],
    spans: &[crate::source::Span],
    id: MaterialId,
) -> Option<usize> {
    let at = scene.material(id).span.start as usize;
    let after = spans
        .iter()
        .filter(|s| (s.end as usize) <= at)
        .map(|s| s.end as usize)
        .max()
        .unwrap_or(0);
    comments
        .iter()
        .rposition(|c| c.start < at && c.start >= after)
}

/// `p` made absolute and without `.` and `..` (the file exists, so symbolic links are resolved
/// too; otherwise against the working directory).
fn absolute(p: &Path) -> PathBuf {
    std::fs::canonicalize(p).unwrap_or_else(|_| {
        let joined = std::env::current_dir().map_or_else(|_| p.to_path_buf(), |d| d.join(p));
        let mut out = PathBuf::new();
        for c in joined.components() {
            match c {
                Component::ParentDir => {
                    out.pop();
                }
                Component::CurDir => {}
                other => out.push(other),
            }
        }
        out
    })
}

/// `target` as a path from the directory `from`, with `/` separators (both absolute); an
/// absolute path when they share no root.
fn relative(from: &Path, target: &Path) -> String {
    let a: Vec<Component> = from.components().collect();
    let b: Vec<Component> = target.components().collect();
    if a.first() != b.first() {
        return target.display().to_string();
    }
    let common = a.iter().zip(&b).take_while(|(x, y)| x == y).count();
    let mut parts: Vec<String> = vec!["..".into(); a.len() - common];
    parts.extend(
        b[common..]
            .iter()
            .map(|c| c.as_os_str().to_string_lossy().into_owned()),
    );
    parts.join("/")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_paths_climb_and_descend() {
        let r = relative(Path::new("/a/b/out"), Path::new("/a/textures/x.png"));
        assert_eq!(r, "../../textures/x.png");
        assert_eq!(relative(Path::new("/a"), Path::new("/a/x.obj")), "x.obj");
    }
}
