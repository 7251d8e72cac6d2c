//! OBJ loading errors with the offending line, found by re-reading the file when tobj (which
//! reports no positions) rejects it, and the one diagnostic each kind of error becomes.

use std::path::Path;

use crate::diag::{Diagnostic, Severity};
use crate::source::Span;

/// Why a mesh could not be loaded.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MeshError {
    /// What went wrong, lower case.
    pub message: String,
    /// 1-based line in the OBJ file, where known.
    pub(crate) line: Option<usize>,
    /// True when the file could not be opened or read at all.
    pub(crate) missing: bool,
    /// True when the file is valid but over the triangle budget.
    pub too_large: bool,
    /// 0-based byte offset in a binary file (STL, PLY), where known and there is no line.
    pub(crate) byte: Option<u64>,
    /// A concrete fix, where the reader knows one.
    pub(crate) fix: Option<String>,
}

impl MeshError {
    /// An error with an optional line.
    pub(crate) fn new(message: impl Into<String>, line: Option<usize>) -> MeshError {
        MeshError {
            message: message.into(),
            line,
            missing: false,
            too_large: false,
            byte: None,
            fix: None,
        }
    }

    /// An error at byte `byte` of a binary file, with the fix `fix`.
    pub(crate) fn at_byte(
        message: impl Into<String>,
        byte: u64,
        fix: impl Into<String>,
    ) -> MeshError {
        MeshError {
            byte: Some(byte),
            fix: Some(fix.into()),
            ..MeshError::new(message, None)
        }
    }

    /// An error on 1-based line `line` of a text file, with the fix `fix`.
    pub(crate) fn at_line(
        message: impl Into<String>,
        line: usize,
        fix: impl Into<String>,
    ) -> MeshError {
        MeshError {
            fix: Some(fix.into()),
            ..MeshError::new(message, Some(line))
        }
    }
}

impl MeshError {
    /// The diagnostic for this error on the mesh `source` placed at `span`:
    /// `rtc::mesh::{not_found, too_large, malformed}`.
    pub(crate) fn diagnostic_of(&self, span: Span, source: &crate::ir::MeshSource) -> Diagnostic {
        match source {
            crate::ir::MeshSource::File(path) => self.diagnostic(span, path),
            // The constructor's checks leave an inline mesh nothing to fail on but its budget
            // and faces that lose their area in single precision.
            crate::ir::MeshSource::Inline(_) => {
                let mut d = Diagnostic::error(
                    if self.too_large {
                        "rtc::mesh::too_large"
                    } else {
                        "rtc::mesh::malformed"
                    },
                    span,
                    format!("this inline mesh cannot be used: {}", self.message),
                )
                .with_label("this mesh");
                if let Some(fix) = &self.fix {
                    d = d.with_help(fix.clone());
                }
                d
            }
        }
    }

    /// The diagnostic for a mesh file at `path` that failed to load, on `span`.
    pub(crate) fn diagnostic(&self, span: Span, path: &Path) -> Diagnostic {
        if self.missing {
            return Diagnostic::error(
                "rtc::mesh::not_found",
                span,
                format!("cannot read the mesh file `{}`", path.display()),
            )
            .with_label("this mesh")
            .with_help("check the path and the file's permissions");
        }
        if self.too_large {
            return Diagnostic::error(
                "rtc::mesh::too_large",
                span,
                format!(
                    "the mesh file `{}` is too large: {}",
                    path.display(),
                    self.message
                ),
            )
            .with_label("this mesh")
            .with_help("simplify the model or split it into several files");
        }
        let at = match (self.line, self.byte) {
            (Some(l), _) => format!(" at line {l}"),
            (None, Some(b)) => format!(" at byte {b}"),
            (None, None) => String::new(),
        };
        let mut d = Diagnostic::new(
            Severity::Error,
            "rtc::mesh::malformed",
            Some(span),
            format!("the mesh file `{}` is malformed{at}", path.display()),
        )
        .with_label("this mesh")
        .with_note(self.message.clone());
        if let Some(l) = self.line {
            d = d.with_note(format!("{}:{l}", path.display()));
        }
        if let Some(fix) = &self.fix {
            d = d.with_help(fix.clone());
        }
        d
    }
}

/// Turns a tobj error into a message and, where the kind allows, the first offending line.
pub(crate) fn locate(path: &Path, e: tobj::LoadError) -> MeshError {
    use tobj::LoadError as E;
    if matches!(e, E::OpenFileFailed | E::ReadError) {
        return MeshError {
            message: "the file cannot be read".into(),
            line: None,
            missing: true,
            too_large: false,
            byte: None,
            fix: None,
        };
    }
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let line = first_bad_line(&text, e);
    MeshError::new(format!("malformed OBJ file: {e}"), line)
}

/// The first line that shows the problem tobj reported.
fn first_bad_line(text: &str, e: tobj::LoadError) -> Option<usize> {
    use tobj::LoadError as E;
    let (mut nv, mut nt, mut nn) = (0i64, 0i64, 0i64);
    for (i, raw) in text.lines().enumerate() {
        let line = raw.split('#').next().unwrap_or("").trim();
        let mut words = line.split_whitespace();
        let Some(kw) = words.next() else { continue };
        let args: Vec<&str> = words.collect();
        let floats_ok = |min: usize, max: usize| {
            (min..=max).contains(&args.len()) && args.iter().all(|a| a.parse::<f32>().is_ok())
        };
        let bad = match kw {
            "v" => {
                nv += 1;
                matches!(e, E::PositionParseError) && !floats_ok(3, 7)
            }
            "vt" => {
                nt += 1;
                matches!(e, E::TexcoordParseError) && !floats_ok(1, 3)
            }
            "vn" => {
                nn += 1;
                matches!(e, E::NormalParseError) && !floats_ok(3, 3)
            }
            "f" => face_is_bad(&args, e, nv, nt, nn),
            _ => false,
        };
        if bad {
            return Some(i + 1);
        }
    }
    None
}

/// Whether a face line shows error `e`, given the counts of elements defined so far.
fn face_is_bad(args: &[&str], e: tobj::LoadError, nv: i64, nt: i64, nn: i64) -> bool {
    use tobj::LoadError as E;
    if matches!(e, E::InvalidPolygon) {
        return args.len() < 3;
    }
    let in_range = |s: &str, n: i64| match s.parse::<i64>() {
        Ok(i) if i > 0 => i <= n,
        Ok(i) if i < 0 => -i <= n,
        _ => false,
    };
    args.iter().any(|a| {
        let parts: Vec<&str> = a.split('/').collect();
        let parse_err = parts.is_empty()
            || parts.len() > 3
            || parts
                .iter()
                .enumerate()
                .any(|(k, p)| !(p.is_empty() && k > 0) && p.parse::<i64>().is_err());
        match e {
            E::FaceParseError => parse_err,
            E::FaceVertexOutOfBounds => !parse_err && !in_range(parts[0], nv),
            E::FaceTexCoordOutOfBounds => {
                !parse_err
                    && parts
                        .get(1)
                        .is_some_and(|p| !p.is_empty() && !in_range(p, nt))
            }
            E::FaceNormalOutOfBounds => {
                !parse_err
                    && parts
                        .get(2)
                        .is_some_and(|p| !p.is_empty() && !in_range(p, nn))
            }
            _ => false,
        }
    })
}
