//! Type names, type-annotation checks and the "expected X, found Y" diagnostic.

use glam::DVec3;

use crate::diag::Diagnostic;
use crate::source::Span;
use crate::syntax::ast::TypeAnn;

use super::error::{Quote, R, error, suggest};
use super::value::Value;

/// Every type name an annotation may use.
const TYPE_NAMES: &[&str] = &[
    "Any",
    "Int",
    "Float",
    "Bool",
    "String",
    "Angle",
    "Vec3",
    "Color",
    "Transform",
    "Object",
    "Material",
    "Texture",
    "Light",
    "Camera",
    "Render",
    "List",
    "Range",
    "Record",
    "Fn",
    "Rng",
];

/// "expected `T`, found `U`" at `span`, with a label and a concrete help where one is known.
pub(crate) fn mismatch(
    it: &(impl Quote + ?Sized),
    expected: &str,
    found: &Value,
    span: Span,
) -> Diagnostic {
    let snippet = it.snippet(span).trim();
    let d = error(
        "rtc::type::mismatch",
        span,
        format!("expected `{expected}`, found `{}`", found.type_name()),
    );
    let is_literal = snippet.parse::<f64>().is_ok();
    match (expected, found) {
        ("Angle", Value::Int(_) | Value::Float(_)) => {
            let help = if is_literal {
                format!(
                    "write `{snippet}deg` (or `{snippet}rad`); angles always carry a unit in rtc"
                )
            } else {
                format!("multiply by a unit: `({snippet}) * 1deg`")
            };
            d.with_label("a plain number has no unit").with_help(help)
        }
        ("Float" | "Int", Value::Angle(_)) => d.with_label("this is an angle").with_help(format!(
            "take its size in a unit: `({snippet}).deg` or `({snippet}).rad`"
        )),
        ("Color", Value::Vec3(v)) => d.with_label("a vector is not a colour").with_help(format!(
            "write `rgb({}, {}, {})`",
            fmt(v.x),
            fmt(v.y),
            fmt(v.z)
        )),
        ("Vec3", Value::Int(_) | Value::Float(_)) => d.with_label("a single number").with_help(
            format!("write a vector: `[{snippet}, {snippet}, {snippet}]`"),
        ),
        ("Int", Value::Float(_)) => d
            .with_label("a fractional number")
            .with_help(format!("round it: `round({snippet})`")),
        ("Bool", Value::Int(_) | Value::Float(_)) => d
            .with_label(format!(
                "this is {}",
                super::value::a_type(found.type_name())
            ))
            .with_help(format!("compare it, e.g. `{snippet} != 0`")),
        ("Material", Value::Color(_)) => d
            .with_label("a colour is not a material")
            .with_help(format!("write `material {{ color: {snippet} }}`")),
        _ => d.with_label(format!(
            "this is {}",
            super::value::a_type(found.type_name())
        )),
    }
}

fn fmt(f: f64) -> String {
    super::value::fmt_f(f)
}

/// True if `v` has the type named `name` (Int counts as Float).
fn has_type(name: &str, v: &Value) -> bool {
    match name {
        "Any" => true,
        "Float" => matches!(v, Value::Float(_) | Value::Int(_)),
        "Fn" => matches!(v, Value::Fn(_) | Value::Builtin(_)),
        "List" => matches!(v, Value::List(_) | Value::Vec3(_)),
        other => v.type_name() == other,
    }
}

/// Checks `v` against an annotation, widening Int to Float where Float is declared.
pub(crate) fn check_ann(it: &(impl Quote + ?Sized), t: &TypeAnn, v: Value, span: Span) -> R<Value> {
    let name = t.name.sym.as_str();
    if !TYPE_NAMES.contains(&name) {
        let d = error(
            "rtc::type::unknown",
            t.name.span,
            format!("unknown type `{name}`"),
        )
        .with_label("not a type");
        let d = match suggest(name, TYPE_NAMES.iter().copied()) {
            Some(h) => d.with_help(h),
            None => d.with_help(format!("use one of: {}", TYPE_NAMES.join(", "))),
        };
        return Err(d.into());
    }
    if !has_type(name, &v) {
        let d = mismatch(it, name, &v, span)
            .with_secondary(t.span, format!("declared as `{name}` here"));
        return Err(d.into());
    }
    if let (Some(elem), Value::List(items)) = (&t.arg, &v) {
        let en = elem.name.sym.as_str();
        if let Some(bad) = items.iter().find(|x| !has_type(en, x)) {
            let d = error(
                "rtc::type::mismatch",
                span,
                format!(
                    "expected `List<{en}>`, found an element of type `{}`",
                    bad.type_name()
                ),
            )
            .with_label(format!("not every element is {}", super::value::a_type(en)))
            .with_secondary(t.span, "declared here")
            .with_help(format!(
                "make every element {}, or declare `List<Any>`",
                super::value::a_type(en)
            ));
            return Err(d.into());
        }
    }
    Ok(match (name, v) {
        ("Float", Value::Int(i)) => Value::Float(i as f64),
        (_, v) => v,
    })
}

/// A number (Int or Float) as f64.
pub(crate) fn num(it: &(impl Quote + ?Sized), v: &Value, span: Span) -> R<f64> {
    v.as_f64()
        .ok_or_else(|| mismatch(it, "Float", v, span).into())
}

/// An Int.
pub(crate) fn int(it: &(impl Quote + ?Sized), v: &Value, span: Span) -> R<i64> {
    match v {
        Value::Int(i) => Ok(*i),
        _ => Err(mismatch(it, "Int", v, span).into()),
    }
}

/// An angle in radians.
pub(crate) fn angle(it: &(impl Quote + ?Sized), v: &Value, span: Span) -> R<f64> {
    match v {
        Value::Angle(a) => Ok(*a),
        _ => Err(mismatch(it, "Angle", v, span).into()),
    }
}

/// A Vec3; a `List` of exactly three numbers (what `.map` on a list gives) is one too.
pub(crate) fn vec3(it: &(impl Quote + ?Sized), v: &Value, span: Span) -> R<DVec3> {
    match v {
        Value::Vec3(x) => Ok(*x),
        Value::List(l) => match l.as_slice() {
            [a, b, c] => match (a.as_f64(), b.as_f64(), c.as_f64()) {
                (Some(x), Some(y), Some(z)) => Ok(DVec3::new(x, y, z)),
                _ => Err(mismatch(it, "Vec3", v, span).into()),
            },
            _ => Err(mismatch(it, "Vec3", v, span).into()),
        },
        _ => Err(mismatch(it, "Vec3", v, span).into()),
    }
}

/// A colour.
pub(crate) fn color(it: &(impl Quote + ?Sized), v: &Value, span: Span) -> R<DVec3> {
    match v {
        Value::Color(x) => Ok(*x),
        _ => Err(mismatch(it, "Color", v, span).into()),
    }
}

/// A Bool.
pub(crate) fn boolean(it: &(impl Quote + ?Sized), v: &Value, span: Span) -> R<bool> {
    match v {
        Value::Bool(b) => Ok(*b),
        _ => Err(mismatch(it, "Bool", v, span).into()),
    }
}

/// A String.
pub(crate) fn string(it: &(impl Quote + ?Sized), v: &Value, span: Span) -> R<std::rc::Rc<str>> {
    match v {
        Value::Str(s) => Ok(s.clone()),
        _ => Err(mismatch(it, "String", v, span).into()),
    }
}
