//! Scene inputs from the command line: `param name = default` statements that
//! `rtc render --set name=value` overrides, and the built-ins `frame` and `time`.

use crate::diag::{Diagnostic, Severity};
use crate::source::SourceMap;
use crate::syntax::ast::{Expr, Let, Stmt};
use crate::syntax::intern::Sym;

use super::EvalOptions;
use super::error::{R, error, suggest};
use super::interp::Interp;
use super::value::Value;

/// One `--set NAME=VALUE`, its value parsed as an expression.
#[derive(Clone, Debug)]
pub struct Override {
    /// The parameter it sets.
    pub name: Sym,
    /// The value, evaluated where the `param` statement is.
    pub value: Expr,
}

/// Parses every `--set` value as one expression; each gets a source of its own (`--set NAME`),
/// so a mistake in it is reported there.
pub fn parse_overrides(
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
pub fn frame_builtin(opts: &EvalOptions, name: &str) -> Option<Value> {
    match name {
        "frame" => Some(Value::Int(opts.frame)),
        "time" => Some(Value::Float(opts.frame as f64 / opts.fps)),
        "fps" => Some(Value::Float(opts.fps)),
        _ => None,
    }
}

/// The names [`frame_builtin`] knows (for did-you-mean).
pub const FRAME_BUILTINS: &[&str] = &["frame", "time", "fps"];

impl Interp<'_> {
    /// The value of a top-level `param` statement: its default, or the `--set` value of the same
    /// type (an Int where the default is a Float is taken as that Float).
    pub(super) fn param_value(&mut self, l: &Let) -> R<Value> {
        let default = self.eval(&l.value)?;
        self.params.push(l.name.sym);
        let Some(o) = self
            .overrides
            .iter()
            .find(|o| o.name == l.name.sym)
            .cloned()
        else {
            return Ok(default);
        };
        if let (Value::Str(_), crate::syntax::ast::ExprKind::Ident(word)) =
            (&default, &o.value.kind)
        {
            // `--set label=spiral`: the shell ate no quotes, there were none; the word is not
            // a name the scene means.
            return Err(error(
                "rtc::param::unquoted",
                o.value.span,
                format!("`--set {}`: a `String` value needs quotes", l.name.sym),
            )
            .with_label("a bare word is read as a name")
            .with_secondary(l.value.span, "the default is a `String`")
            .with_help(format!(
                "quote it inside the shell's quotes: `--set {}='\"{word}\"'`",
                l.name.sym
            ))
            .into());
        }
        let v = self.eval(&o.value)?;
        match (&default, v) {
            (Value::Float(_), Value::Int(i)) => Ok(Value::Float(i as f64)),
            (d, v) if d.type_name() == v.type_name() => Ok(v),
            (d, v) => Err(error(
                "rtc::param::type",
                o.value.span,
                format!(
                    "`--set {}` gives {}, but the parameter is {}",
                    l.name.sym,
                    super::value::a_type(v.type_name()),
                    super::value::a_type(d.type_name())
                ),
            )
            .with_label(format!("{} here", super::value::a_type(v.type_name())))
            .with_secondary(l.value.span, "the default fixes the type")
            .with_help(format!(
                "give {} value, like the default `{}`",
                super::value::a_type(d.type_name()),
                self.snippet(l.value.span)
            ))
            .into()),
        }
    }

    /// Errors for `--set` names that no top-level `param` declares.
    pub(super) fn unknown_overrides(&self) -> Vec<Diagnostic> {
        let declared: Vec<&str> = self.params.iter().map(|s| s.as_str()).collect();
        self.overrides
            .iter()
            .filter(|o| !self.params.contains(&o.name))
            .map(|o| {
                let help = match suggest(o.name.as_str(), declared.iter().copied()) {
                    Some(s) => s.replace("name exists", "parameter exists"),
                    None if declared.is_empty() => format!(
                        "declare it in the scene file: `param {} = ...` (a `let` the command line may override)",
                        o.name
                    ),
                    None => format!("the scene's parameters are: {}", declared.join(", ")),
                };
                Diagnostic::new(
                    Severity::Error,
                    "rtc::param::unknown",
                    None,
                    format!("`--set {}`: the scene has no parameter `{}`", o.name, o.name),
                )
                .with_help(help)
            })
            .collect()
    }
}

/// The error for `param` anywhere but the top level of the scene file.
pub fn misplaced(l: &Let) -> Diagnostic {
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
