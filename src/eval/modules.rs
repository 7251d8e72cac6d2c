//! Modules: one scope per file, `pub` exports, the embedded standard library, import caching and
//! cycle detection.

use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::rc::Rc;

use crate::source::{FileId, Span};
use crate::syntax::intern::Sym;

use super::value::Value;

/// The embedded standard library: `std.NAME` is the text of `stdlib/NAME.rtc`. Adding a module
/// is one line here.
pub(crate) const STDLIB: &[(&str, &str)] = &[
    ("prelude", include_str!("../../stdlib/prelude.rtc")),
    ("math", include_str!("../../stdlib/math.rtc")),
    ("color", include_str!("../../stdlib/color.rtc")),
    ("materials", include_str!("../../stdlib/materials.rtc")),
    ("textures", include_str!("../../stdlib/textures.rtc")),
    ("layout", include_str!("../../stdlib/layout.rtc")),
    ("shapes", include_str!("../../stdlib/shapes.rtc")),
];

/// A name bound at module level.
#[derive(Clone, Debug)]
pub(crate) struct Binding {
    /// Its value (meaningless when `poisoned`).
    pub(crate) value: Value,
    /// Exported.
    pub(crate) public: bool,
    /// Where it was bound.
    pub(crate) span: Span,
    /// Its definition failed; uses are silently skipped.
    pub(crate) poisoned: bool,
}

/// The items of one module while it is evaluated (and afterwards, for closures).
#[derive(Debug)]
pub(crate) struct Scope {
    /// Module-level bindings.
    pub(crate) items: RefCell<super::fxhash::FxHashMap<Sym, Binding>>,
    /// Directory that relative paths in this file resolve against.
    pub(crate) dir: PathBuf,
    /// The file.
    pub(crate) file: FileId,
    /// Name for messages (`std.color` or the path).
    pub(crate) name: String,
}

impl Scope {
    /// An empty scope for a file.
    pub(crate) fn new(file: FileId, dir: PathBuf, name: String) -> Scope {
        Scope {
            items: RefCell::new(Default::default()),
            dir,
            file,
            name,
        }
    }
}

/// An evaluated module as a value.
#[derive(Debug)]
pub(crate) struct Module {
    /// `std.color` or the path as written.
    pub(crate) name: String,
    /// Its scope (exports are the `pub` bindings).
    pub(crate) scope: Rc<Scope>,
}

impl Module {
    /// A `pub` binding, or `Err(true)` when the name exists but is private, `Err(false)` if absent.
    pub(crate) fn export(&self, name: Sym) -> Result<Binding, bool> {
        match self.scope.items.borrow().get(&name) {
            Some(b) if b.public => Ok(b.clone()),
            Some(_) => Err(true),
            None => Err(false),
        }
    }

    /// Names of all exports, sorted (for did-you-mean).
    pub(crate) fn export_names(&self) -> Vec<&'static str> {
        let mut v: Vec<&'static str> = self
            .scope
            .items
            .borrow()
            .iter()
            .filter(|(_, b)| b.public)
            .map(|(k, _)| k.as_str())
            .collect();
        v.sort_unstable();
        v
    }
}

/// The stdlib text for `std.NAME`.
pub fn stdlib(name: &str) -> Option<&'static str> {
    STDLIB.iter().find(|(n, _)| *n == name).map(|(_, t)| *t)
}

/// The standard modules that export `name` (read from their `pub let` / `pub fn` lines), for
/// the help of an unknown name: `red` is in `std.color`. `std.prelude` is left out: its names
/// are the same as in `std.math`.
pub(crate) fn std_modules_exporting(name: &str) -> Vec<&'static str> {
    let exports = |text: &str| {
        text.lines().any(|l| {
            let rest = l
                .strip_prefix("pub let ")
                .or_else(|| l.strip_prefix("pub fn "))
                .unwrap_or("");
            rest.strip_prefix(name)
                .is_some_and(|r| r.starts_with([' ', '(', ':', '=']))
        })
    };
    STDLIB
        .iter()
        .filter(|(m, text)| *m != "prelude" && exports(text))
        .map(|(m, _)| *m)
        .collect()
}

/// Resolves `rel` against `dir` without touching the file system (paths stay as the user would
/// write them, so messages are stable).
pub(crate) fn resolve(dir: &Path, rel: &str) -> PathBuf {
    crate::assets::search::join(dir, rel)
}

/// The identity of a module file: its canonical path (symlinks and `..` resolved), so one file
/// reached through several symlinked folders is one module, and a cycle through a link is seen;
/// the path as given when it cannot be canonicalised (it does not exist: reading it fails).
pub(crate) fn identity(path: &Path) -> PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())
}
