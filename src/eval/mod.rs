//! Evaluation of `.rtc` files to the IR: names, types, loops, functions, modules, budgets.

mod args;
mod assets;
mod bounds;
mod budgets;
mod builtins;
mod compile;
mod compile_builtins;
mod compile_calls;
mod compile_ops;
#[cfg(test)]
mod compile_tests;
mod error;
mod fxhash;
mod host;
mod interp;
pub mod library;
mod lower;
mod members;
mod methods;
mod modifiers;
pub mod modules;
mod motion;
mod operands;
mod ops;
mod options;
mod params;
mod parts;
mod provenance;
pub mod rng;
mod schema;
mod shapes;
mod texture_methods;
mod transform;
mod types;
mod value;
mod visibility;
mod with;

use std::path::Path;
use std::rc::Rc;
use std::sync::Arc;

use crate::diag::{Diagnostic, Severity};
use crate::ir::Loaded;
use crate::source::SourceMap;

pub(crate) use builtins::reserved_names;
use options::on_eval_stack;
pub use options::{DEFAULT_FPS, EvalOptions, LoopParts};
pub use value::SHOW_LIMIT;

/// Parses and evaluates the scene file at `path`, reading it from disk.
pub fn load_file(path: &Path, sources: &mut SourceMap, options: &EvalOptions) -> Loaded {
    match crate::source::read_file(path).map(String::from_utf8) {
        Ok(Ok(text)) => load_source(path, text, sources, options),
        Ok(Err(e)) => {
            let mut loaded = Loaded::default();
            loaded
                .diagnostics
                .push(not_text(path, e.as_bytes(), e.utf8_error()));
            loaded
        }
        Err(e) => {
            let mut loaded = Loaded::default();
            loaded.diagnostics.push(
                Diagnostic::new(
                    Severity::Error,
                    crate::diag::IO_ERROR,
                    None,
                    format!("cannot read `{}`: {e}", path.display()),
                )
                .with_help("check the path and the file's permissions"),
            );
            loaded
        }
    }
}

/// The error for a scene file that is not UTF-8 text: where the first bad byte is, and whether the
/// file looks binary (a NUL byte) rather than text in another encoding.
fn not_text(path: &Path, bytes: &[u8], e: std::str::Utf8Error) -> Diagnostic {
    let at = e.valid_up_to();
    let line = bytes[..at].iter().filter(|&&b| b == b'\n').count() + 1;
    let column = at
        - bytes[..at]
            .iter()
            .rposition(|&b| b == b'\n')
            .map_or(0, |p| p + 1)
        + 1;
    let binary = bytes.iter().take(8192).any(|&b| b == 0);
    let (what, help) = if binary {
        (
            "looks like a binary file, not a scene",
            "give `rtc` a `.rtc` text file; images and models are loaded by the scene with `image(...)` and `mesh(...)`",
        )
    } else {
        (
            "is not UTF-8 text",
            "save the file as UTF-8 (e.g. `iconv -f latin1 -t utf-8`)",
        )
    };
    Diagnostic::new(
        Severity::Error,
        "rtc::syntax::encoding",
        None,
        format!(
            "`{}` {what}: byte 0x{:02x} at offset {at} (line {line}, column {column}) is not UTF-8",
            path.display(),
            bytes.get(at).copied().unwrap_or(0),
        ),
    )
    .with_help(help)
}

/// Parses and evaluates `text` as the scene file `path` (relative paths resolve against its
/// directory).
pub fn load_source(
    path: &Path,
    text: impl Into<String>,
    sources: &mut SourceMap,
    options: &EvalOptions,
) -> Loaded {
    let text = text.into();
    on_eval_stack(|| load_source_here(path, text, sources, options)).unwrap_or_else(|| {
        Loaded::failure(
            crate::diag::IO_ERROR,
            "cannot start the evaluation thread",
            "free some memory and retry",
        )
    })
}

fn load_source_here(
    path: &Path,
    text: String,
    sources: &mut SourceMap,
    options: &EvalOptions,
) -> Loaded {
    let mut loaded = Loaded::default();
    let Some((mut it, lowerer)) = run_root(path, text, sources, options, None, &mut loaded) else {
        return loaded;
    };
    let mut findings = it.take_findings();
    findings.extend(it.unknown_overrides());
    let had_errors = findings.iter().any(Diagnostic::is_error);
    loaded.diagnostics.items.extend(findings);
    if had_errors {
        return loaded;
    }
    let mut lowerer = lowerer;
    if let (Some(b), Some(origins)) = (it.take_provenance(), lowerer.origins.take()) {
        loaded.provenance = Some((*b).finish(origins));
    }
    // What the evaluation charged goes on to the preparation, which charges the textures and
    // meshes to the same budget.
    let mut memory = it.memory_used();
    memory.used += lowerer.objects.len() as u64 * budgets::OBJECT_BYTES;
    match lowerer.finish(memory) {
        Ok(scene) => loaded.scene = Some(scene),
        Err(errs) => loaded.diagnostics.items.extend(errs),
    }
    loaded
}

/// Evaluates the scene file `path` (its text `text`) into a lowerer, as the evaluation of
/// record or, with `helper`, as a replay that evaluates a part of one loop (`split`). `None`
/// when it does not parse or the `--set` values are bad; the reasons are in `loaded`.
fn run_root<'a>(
    path: &Path,
    text: String,
    sources: &'a mut SourceMap,
    options: &'a EvalOptions,
    helper: Option<parts::Helper>,
    loaded: &mut Loaded,
) -> Option<(interp::Interp<'a>, lower::Lowerer)> {
    let file = sources.add(path, text);
    // The map's copy, shared: the AST borrows it while evaluation adds imported files.
    let text = Arc::clone(&sources.get(file).text);
    let (ast, diags) = crate::syntax::parse(file, &text);
    for d in diags {
        loaded.diagnostics.push(d);
    }
    let ast = ast?;
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let scope = Rc::new(modules::Scope::new(file, dir, path.display().to_string()));
    let (overrides, bad) = params::parse_overrides(options, sources);
    if !bad.is_empty() {
        loaded.diagnostics.items.extend(bad);
        return None;
    }
    let mut it = interp::Interp::new(options, sources, scope);
    let role = match helper {
        Some(h) => parts::Role::Helper(Box::new(h)),
        None => parts::Role::main(options, file),
    };
    // Modules are told apart by their canonical file (symlinked folders name one file by many
    // paths), so the scene itself is its canonical path too.
    it.begin(modules::identity(path), overrides, role);
    let mut lowerer = lower::Lowerer::default();
    if options.provenance {
        lowerer.origins = Some(Vec::new());
    }
    it.run_module(&ast, Some(&mut lowerer));
    Some((it, lowerer))
}

/// A helper's replay of the scene file: its part of the split loop, if it got there.
fn replay(
    path: &Path,
    text: String,
    sources: &mut SourceMap,
    options: &EvalOptions,
    helper: parts::Helper,
) -> Option<parts::Part> {
    let mut loaded = Loaded::default();
    let (mut it, _) = run_root(path, text, sources, options, Some(helper), &mut loaded)?;
    it.take_part()
}
