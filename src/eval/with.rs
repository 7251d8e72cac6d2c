//! `base with { field: value }`: a checked copy of a material or record.

use std::rc::Rc;

use crate::source::Span;
use crate::syntax::ast::Name;

use super::error::{R, error, suggest};
use super::host::Host;
use super::value::Value;

/// Applies the updates to a copy of `base`.
pub(crate) fn with(
    it: &mut dyn Host,
    base: Value,
    bspan: Span,
    upd: Vec<(Name, Value, Span)>,
) -> R<Value> {
    match base {
        Value::Material(m) => {
            let mut m2 = (*m).clone();
            m2.made = it.next_made();
            for (name, v, sp) in &upd {
                super::builtins::set_mat_field(it, &mut m2, *name, v, *sp)?;
            }
            let span = upd.first().map_or(bspan, |u| u.0.span);
            super::builtins::mat_warnings(it, &m2, span);
            Ok(Value::Material(Rc::new(m2)))
        }
        Value::Record(r) => {
            let mut r2 = (*r).clone();
            for (name, v, sp) in upd {
                match r2.fields.iter_mut().find(|f| f.name == name.sym) {
                    Some(f) => {
                        f.value = v;
                        f.span = sp;
                    }
                    None => {
                        let names: Vec<&str> = r2.fields.iter().map(|f| f.name.as_str()).collect();
                        let help = suggest(name.sym.as_str(), names.iter().copied())
                            .unwrap_or_else(|| {
                                format!(
                                    "`with` only replaces existing fields: {}",
                                    names.join(", ")
                                )
                            });
                        return Err(error(
                            "rtc::field::unknown",
                            name.span,
                            format!("the record has no field `{}`", name.sym),
                        )
                        .with_label("unknown field")
                        .with_help(help)
                        .into());
                    }
                }
            }
            Ok(Value::Record(Rc::new(r2)))
        }
        other => Err(error(
            "rtc::type::mismatch",
            bspan,
            format!(
                "`with` cannot copy {}",
                super::value::a_type(other.type_name())
            ),
        )
        .with_label(format!(
            "this is {}",
            super::value::a_type(other.type_name())
        ))
        .with_help("`with` works on materials and records")
        .into()),
    }
}
