//! Checking a library module on its own (`rtc check lib.rtc`): a file that only defines things
//! (at least one `pub` item, no top-level expression other than `assert`/`print`) is evaluated
//! the way an import evaluates it, so its own errors show and a missing camera is not one.

use std::path::Path;
use std::rc::Rc;

use crate::diag::Diagnostics;
use crate::source::SourceMap;
use crate::syntax::ast::{ExprKind, File, Stmt};

use super::options::{EvalOptions, on_eval_stack};
use super::{interp, modules};

/// What checking a library module found.
#[derive(Debug, Default)]
pub struct Library {
    /// Its exported names, sorted.
    pub exports: Vec<String>,
    /// Every finding of parsing and evaluating it as an import.
    pub diagnostics: Diagnostics,
}

/// True when a parsed file is a library: it exports something and emits nothing (every
/// top-level statement is `let`, `fn`, `import`, or a call of `assert` or `print`).
fn is_library(file: &File<'_>) -> bool {
    // `pub` statements are never read by the fast path: the built ones hold every export.
    let exports = file.built_stmts().iter().any(|s| match s {
        Stmt::Let(l) => l.public,
        Stmt::Fn(f) => f.public,
        _ => false,
    });
    let emits = file.stmts().any(|s| match &*s {
        Stmt::Expr(e) => !is_statement_call(&e.kind),
        _ => false,
    });
    exports && !emits
}

/// `assert(...)` and `print(...)`: expressions that return nothing and emit nothing.
fn is_statement_call(kind: &ExprKind) -> bool {
    let ExprKind::Call(callee, _) = kind else {
        return false;
    };
    matches!(&callee.kind, ExprKind::Ident(name) if matches!(name.as_str(), "assert" | "print"))
}

/// Checks `text` (the file `path`) as a library module when it is one (`is_library`);
/// `None` for a scene file, which the caller loads as a scene. Sources read go into `sources`.
pub fn load_library(
    path: &Path,
    text: &str,
    sources: &mut SourceMap,
    options: &EvalOptions,
) -> Option<Library> {
    // A library exports something, so its text says `pub` (the keyword's only spelling): a
    // scene without the word is not parsed a second time just to learn that (a third of
    // `rtc check` on a generated file of 100 000 spheres).
    if !text.contains("pub") {
        return None;
    }
    let probe = crate::syntax::parse(crate::source::FileId(0), text).0?;
    if !is_library(&probe) {
        return None;
    }
    on_eval_stack(|| evaluate(path, text, sources, options))
}

/// Evaluates a library module as an import would (nothing may be emitted).
fn evaluate(path: &Path, text: &str, sources: &mut SourceMap, options: &EvalOptions) -> Library {
    let file = sources.add(path, text);
    let (ast, diags) = crate::syntax::parse(file, text);
    let mut out = Library::default();
    out.diagnostics.items.extend(diags);
    let Some(ast) = ast else { return out };
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let scope = Rc::new(modules::Scope::new(file, dir, path.display().to_string()));
    let module = modules::Module {
        name: path.display().to_string(),
        scope: scope.clone(),
    };
    let mut it = interp::Interp::new(options, sources, scope);
    it.begin(path.to_path_buf(), Vec::new(), super::parts::Role::Off);
    it.run_module(&ast, None);
    out.diagnostics.items.extend(it.take_findings());
    out.exports = module
        .export_names()
        .into_iter()
        .map(str::to_owned)
        .collect();
    out
}
