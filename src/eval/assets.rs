//! Asset paths (meshes, images): resolved relative to the file that names them, then in the
//! directories of `RTC_ASSET_PATH`, and required to exist, so `rtc check` catches a missing file
//! before any ray is traced.

use std::path::PathBuf;

use crate::source::Span;

use super::error::{R, error};
use super::interp::Interp;

/// Environment variable: directories (separated like `PATH`) searched for assets that are not
/// found next to the file naming them, such as large models kept outside a repository.
pub const ASSET_PATH_VAR: &str = "RTC_ASSET_PATH";

/// Resolves `rel` against the current module's directory, then each `RTC_ASSET_PATH`
/// directory; errors if no such file exists.
pub fn existing(it: &Interp, rel: &str, span: Span, what: &str) -> R<PathBuf> {
    let path = super::modules::resolve(&it.scope.dir, rel);
    if path.is_file() {
        return Ok(path);
    }
    let search = std::env::var_os(ASSET_PATH_VAR).unwrap_or_default();
    let dirs: Vec<PathBuf> = std::env::split_paths(&search)
        .filter(|d| !d.as_os_str().is_empty())
        .collect();
    if std::path::Path::new(rel).is_relative()
        && let Some(found) = dirs.iter().map(|d| d.join(rel)).find(|p| p.is_file())
    {
        return Ok(found);
    }
    let shown = path.display().to_string();
    let file = it.sources.get(it.scope.file).path.display().to_string();
    let searched = if dirs.is_empty() {
        format!("{ASSET_PATH_VAR} is not set")
    } else {
        format!("nor in {ASSET_PATH_VAR} = `{}`", search.to_string_lossy())
    };
    Err(error(
        "rtc::asset::missing",
        span,
        format!("{what} file not found: `{shown}`"),
    )
    .with_label(format!("resolved to `{shown}` ({searched})"))
    .with_help(format!(
        "check the path; it is relative to `{file}`, or add the directory holding it to {ASSET_PATH_VAR}"
    ))
    .into())
}
