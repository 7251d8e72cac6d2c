//! Where an asset file named in a scene is looked for. One search order serves the scene
//! language and both course formats:
//!
//! 1. an absolute path is used as written;
//! 2. a relative one is joined to the directory of the file that names it (lexically: `a/../b`
//!    becomes `b`, so messages show the path a user would write);
//! 3. then to each directory of [`ASSET_PATH_VAR`] (separated like `PATH`), for large models kept
//!    outside a repository;
//! 4. then its file name is looked for in `textures/` and `models/` folders one, two and three
//!    levels above the naming file's directory (the course data keeps scenes in `yaml/` and
//!    `yaml/<group>/` next to those folders).
//!
//! The first existing file wins. A miss is one diagnostic, [`MISSING`], naming what was tried.

use std::path::{Component, Path, PathBuf};

use crate::diag::Diagnostic;
use crate::source::Span;

/// Environment variable: directories (separated like `PATH`) searched for assets that are not
/// found next to the file naming them.
const ASSET_PATH_VAR: &str = "RTC_ASSET_PATH";

/// Diagnostic code of an asset file that is not found.
const MISSING: &str = "rtc::asset::missing";

/// How many directory levels above the naming file the course folders are looked for.
const COURSE_LEVELS: usize = 3;

/// An asset that none of the search steps found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct NotFound {
    /// The name as written.
    name: String,
    /// Step 2's path: where the name points from the naming file.
    resolved: PathBuf,
    /// The value of [`ASSET_PATH_VAR`] (empty when unset).
    asset_path: String,
    /// The naming file's directory, whose course folders were searched (`None` for an absolute
    /// name, which is looked for nowhere else).
    course_dir: Option<PathBuf>,
    /// A file next to where the name points whose name is close (`Teddy.OBJ` for `teddy.obj`:
    /// the same but for case first), for "did you mean".
    near: Option<String>,
}

/// The name of a file in `path`'s directory that is close to its file name: the same but for
/// case first, else the closest of the same extension by [`crate::diag::did_you_mean`].
fn near_name(path: &Path) -> Option<String> {
    let want = path.file_name()?.to_str()?;
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .ok()?
        .filter_map(|e| e.ok())
        .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
        .filter_map(|e| e.file_name().into_string().ok())
        .collect();
    names.sort();
    if let Some(same) = names.iter().find(|n| n.eq_ignore_ascii_case(want)) {
        return Some(same.clone());
    }
    // Otherwise only a file of the same kind (extension, any case) is a suggestion.
    let ext = |n: &str| Path::new(n).extension().map(|e| e.to_ascii_lowercase());
    let same_kind = names.iter().filter(|n| ext(n) == ext(want));
    crate::diag::did_you_mean(want, same_kind.map(String::as_str)).map(str::to_owned)
}

/// `rel` joined to `dir` without touching the file system: `.` is dropped and `x/..` removed.
pub(crate) fn join(dir: &Path, rel: &str) -> PathBuf {
    let mut out = PathBuf::new();
    for c in dir.join(rel).components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir if out.file_name().is_some() && !out.ends_with("..") => {
                out.pop();
            }
            other => out.push(other.as_os_str()),
        }
    }
    out
}

/// Finds the file `name` written in a scene whose directory is `dir`, in the order above.
pub(crate) fn find(dir: &Path, name: &str) -> Result<PathBuf, NotFound> {
    let given = Path::new(name);
    let resolved = join(dir, name);
    let asset_path = std::env::var_os(ASSET_PATH_VAR).unwrap_or_default();
    let not_found = |course_dir: Option<PathBuf>| NotFound {
        name: name.to_string(),
        resolved: resolved.clone(),
        asset_path: asset_path.to_string_lossy().into_owned(),
        course_dir,
        near: near_name(&resolved),
    };
    if given.is_absolute() {
        return if given.is_file() {
            Ok(given.to_path_buf())
        } else {
            Err(not_found(None))
        };
    }
    let from_asset_path = std::env::split_paths(&asset_path)
        .filter(|d| !d.as_os_str().is_empty())
        .map(|d| join(&d, name));
    let mut course = Vec::new();
    if let Some(file_name) = given.file_name().and_then(|n| n.to_str()) {
        let mut up = dir.to_path_buf();
        for _ in 0..COURSE_LEVELS {
            up = up.join("..");
            course.push(join(&up.join("textures"), file_name));
            course.push(join(&up.join("models"), file_name));
        }
    }
    std::iter::once(resolved.clone())
        .chain(from_asset_path)
        .chain(course)
        .find(|p| p.is_file())
        .ok_or_else(|| not_found(Some(dir.to_path_buf())))
}

impl NotFound {
    /// The diagnostic for a `kind` file ("mesh", "texture", "image") named at `span` in the
    /// file `naming_file`.
    pub(crate) fn diagnostic(&self, span: Span, kind: &str, naming_file: &Path) -> Diagnostic {
        let searched = if self.asset_path.is_empty() {
            format!("{ASSET_PATH_VAR} is not set")
        } else {
            format!("nor in {ASSET_PATH_VAR} = `{}`", self.asset_path)
        };
        let shown = self.resolved.display();
        let mut d = Diagnostic::error(MISSING, span, format!("{kind} file not found: `{shown}`"))
            .with_label(format!("resolved to `{shown}` ({searched})"))
            .with_help(format!(
                "check the path; it is relative to `{}`, or add the directory holding it to {ASSET_PATH_VAR}",
                naming_file.display()
            ));
        if let Some(near) = &self.near {
            let written = Path::new(&self.name).with_file_name(near);
            d = d.with_help(format!(
                "did you mean `{}`? (file names are case-sensitive)",
                written.display()
            ));
        }
        if let Some(dir) = &self.course_dir {
            let dir = if dir.as_os_str().is_empty() {
                Path::new(".")
            } else {
                dir
            };
            d = d.with_note(format!(
                "also looked in `textures/` and `models/` folders up to {COURSE_LEVELS} levels above `{}`",
                dir.display()
            ));
        }
        d
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn join_is_lexical() {
        assert_eq!(join(Path::new("a/b"), "../c.png"), PathBuf::from("a/c.png"));
        assert_eq!(join(Path::new("a"), "./x/../y"), PathBuf::from("a/y"));
        assert_eq!(join(Path::new(""), "../y"), PathBuf::from("../y"));
        assert_eq!(join(Path::new("a"), "/abs"), PathBuf::from("/abs"));
    }

    #[test]
    fn a_near_name_differs_in_case_or_is_of_the_same_kind() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/diagnostics/lib");
        let near = |name: &str| find(&dir, name).unwrap_err().near;
        assert_eq!(near("teddy.obj").as_deref(), Some("Teddy.obj"));
        assert_eq!(near("TEDDY.OBJ").as_deref(), Some("Teddy.obj"));
        // A close name of another kind is no suggestion (`mats.rtc` for `mats.obj`).
        assert_eq!(near("mats.obj"), None);
    }

    #[test]
    fn course_folders_are_searched_by_file_name() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/course/yaml");
        let found = find(&dir, "earthmap1k.png").expect("found in ../textures");
        assert!(found.ends_with("textures/earthmap1k.png"), "{found:?}");
        let missing = find(&dir, "no-such.png").unwrap_err();
        assert_eq!(missing.resolved, dir.join("no-such.png"));
        assert_eq!(missing.course_dir.as_deref(), Some(dir.as_path()));
    }
}
