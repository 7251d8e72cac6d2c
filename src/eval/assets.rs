//! Asset paths (meshes, images): resolved relative to the file that names them and required to
//! exist, so `rtc check` catches a missing file before any ray is traced.

use std::path::PathBuf;

use crate::source::Span;

use super::error::{R, error};
use super::interp::Interp;

/// Resolves `rel` against the current module's directory; errors if no such file exists.
pub fn existing(it: &Interp, rel: &str, span: Span, what: &str) -> R<PathBuf> {
    let path = super::modules::resolve(&it.scope.dir, rel);
    if path.is_file() {
        return Ok(path);
    }
    let shown = path.display().to_string();
    let file = it.sources.get(it.scope.file).path.display().to_string();
    Err(error(
        "rtc::asset::missing",
        span,
        format!("{what} file not found: `{shown}`"),
    )
    .with_label(format!("resolved to `{shown}`"))
    .with_help(format!("check the path; it is relative to `{file}`"))
    .into())
}
