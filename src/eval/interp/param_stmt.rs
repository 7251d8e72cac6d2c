//! The `param` statement: its default, or the `--set` value that overrides it, and the `--set`
//! names no `param` declared.

use crate::diag::{Diagnostic, Severity};
use crate::syntax::ast::Let;

use super::super::error::{R, error, suggest};
use super::super::value::Value;
use super::Interp;

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
                    super::super::value::a_type(v.type_name()),
                    super::super::value::a_type(d.type_name())
                ),
            )
            .with_label(format!(
                "{} here",
                super::super::value::a_type(v.type_name())
            ))
            .with_secondary(l.value.span, "the default fixes the type")
            .with_help(format!(
                "give {} value, like the default `{}`",
                super::super::value::a_type(d.type_name()),
                self.snippet(l.value.span)
            ))
            .into()),
        }
    }

    /// Errors for `--set` names that no top-level `param` declares.
    pub(in crate::eval) fn unknown_overrides(&self) -> Vec<Diagnostic> {
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
