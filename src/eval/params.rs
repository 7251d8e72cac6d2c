//! Scene inputs from the command line: `param name = default` statements that
//! `rtc render --set name=value` overrides, and the built-ins `frame` and `time`.

use crate::diag::{Diagnostic, Severity};
use crate::source::SourceMap;
use crate::syntax::ast::{Expr, Let, Stmt};
use crate::syntax::intern::Sym;

use super::error::error;
use super::options::EvalOptions;
use super::value::Value;

/// One `--set NAME=VALUE`, its value parsed as an expression.
#[derive(Clone, Debug)]
pub(crate) struct Override {
    /// The parameter it sets.
    pub(crate) name: Sym,
    /// The value, evaluated where the `param` statement is.
    pub(crate) value: Expr,
}

/// Parses every `--set` value as one expression; each gets a source of its own (`--set NAME`),
/// so a mistake in it is reported there.
pub(crate) fn parse_overrides(
    opts: &EvalOptions,
    sources: &mut SourceMap,
) -> (Vec<Override>, Vec<Diagnostic>) {
    let mut out = Vec::new();
    let mut diags = Vec::new();
    for (name, text) in &opts.overrides {
        // A file of its own, after the header every file needs: the value is its line 2.
        let source = format!("rtc 1.1\n{text}\n");
        let file = sources.add(format!("--set {name}"), source.clone());
        let (ast, errs) = crate::syntax::parse(file, &source);
        let failed = !errs.is_empty();
        diags.extend(errs);
        let value = match ast.map(crate::syntax::ast::File::into_stmts) {
            Some(mut stmts) if stmts.len() == 1 => match stmts.pop() {
                Some(Stmt::Expr(e)) => Some(e),
                _ => None,
            },
            _ => None,
        };
        match value {
            Some(value) => out.push(Override {
                name: Sym::new(name),
                value,
            }),
            None if failed => {}
            None => diags.push(
                Diagnostic::new(
                    Severity::Error,
                    "rtc::param::value",
                    None,
                    format!("`--set {name}={text}` is not one value"),
                )
                .with_help(format!(
                    "give one expression, e.g. `--set {name}=3`, `--set {name}=[1, 0, 0]` or `--set {name}='\"text\"'`"
                )),
            ),
        }
    }
    (out, diags)
}

/// The value of the built-ins `frame` (Int), `time` (seconds, `frame / fps`) and `fps`.
pub(crate) fn frame_builtin(opts: &EvalOptions, name: &str) -> Option<Value> {
    match name {
        "frame" => Some(Value::Int(opts.frame)),
        "time" => Some(Value::Float(opts.frame as f64 / opts.fps)),
        "fps" => Some(Value::Float(opts.fps)),
        _ => None,
    }
}

/// The names [`frame_builtin`] knows (for did-you-mean).
pub(crate) const FRAME_BUILTINS: &[&str] = &["frame", "time", "fps"];

/// The error for `param` anywhere but the top level of the scene file.
pub(crate) fn misplaced(l: &Let) -> Diagnostic {
    error(
        "rtc::param::position",
        l.span,
        "`param` is only for the top level of the scene file",
    )
    .with_label("not at the top level of the scene file")
    .with_help(format!(
        "declare it at the top of the scene file, or write `let {} = ...`",
        l.name.sym
    ))
}
