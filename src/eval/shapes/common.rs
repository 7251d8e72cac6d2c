//! What every shape constructor shares: the usual parameters (points, directions, radii) and
//! making a checked shape into a value.

use std::rc::Rc;

use glam::{DAffine3, DVec2, DVec3};

use crate::eval::args::{CallSite, Params};
use crate::eval::error::{R, error, suggest};
use crate::eval::host::Host;
use crate::eval::schema::{Lit, Param, Range, Ty, Unit};
use crate::eval::types;
use crate::eval::value::{Obj, ObjShape, Value};
use crate::ir::Shape;
use crate::num::Norm;
use crate::source::Span;

/// A point, `[0, 0, 0]` unless given.
pub(super) const fn point(name: &'static str, doc: &'static str) -> Param {
    Param::new(name, Ty::Vec3, doc)
        .unit(Unit::Length)
        .or(Lit::Vec3([0.0, 0.0, 0.0]))
}

/// A required point or edge.
pub(super) const fn corner(name: &'static str, doc: &'static str) -> Param {
    Param::new(name, Ty::Vec3, doc).unit(Unit::Length)
}

/// A direction, `Y` unless given, normalised.
pub(super) const fn direction(name: &'static str, doc: &'static str) -> Param {
    Param::new(name, Ty::Vec3, doc)
        .range(Range::NonZero)
        .or(Lit::Vec3([0.0, 1.0, 0.0]))
}

/// A radius (> 0 by the shape rules), `default` unless given.
pub(super) const fn radius(name: &'static str, doc: &'static str, default: f64) -> Param {
    Param::new(name, Ty::Float, doc)
        .unit(Unit::Length)
        .range(Range::Positive)
        .checked_by_builtin()
        .or(Lit::Float(default))
}

/// Checks a shape by geometry's rules (the one home of shape validity, `geometry::shapes`) and
/// makes it a value; a flaw is reported on the span of the parameter it blames (from `spans`),
/// else on the call.
pub(super) fn checked(shape: Shape, s: CallSite, spans: &[(&str, Span)]) -> R<Value> {
    if let Err(flaw) = crate::geometry::shapes::check(&shape) {
        let span = spans
            .iter()
            .find(|(name, _)| *name == flaw.param)
            .map_or(s.span, |(_, sp)| *sp);
        return Err(flaw.diagnostic(span).into());
    }
    Ok(prim(shape, s.span))
}

/// An object of `shape` made at `span`, untransformed and without a material.
pub(super) fn prim(shape: Shape, span: Span) -> Value {
    Value::Object(Rc::new(Obj {
        shape: ObjShape::Prim(shape),
        transform: DAffine3::IDENTITY,
        material: None,
        motion: None,
        span,
        origin: 0,
        visibility: crate::ir::Visibility::ALL,
    }))
}

/// The direction `name`, normalised (its default `Y` is a unit vector: `unit` keeps it).
pub(super) fn unit_dir(it: &dyn Host, p: &mut Params, name: &str) -> R<DVec3> {
    Ok(p.vec3(it, name)?.0.unit())
}

/// A `[a, b]` pair of numbers.
pub(super) fn pair(it: &dyn Host, v: &Value, span: Span) -> R<DVec2> {
    match v {
        Value::List(l) if l.len() == 2 => Ok(DVec2::new(
            types::num(it, &l[0], span)?,
            types::num(it, &l[1], span)?,
        )),
        other => Err(types::mismatch(it, "[Float, Float]", other, span).into()),
    }
}

/// The required list of `[a, b]` pairs `name` (a profile's or an outline's points), with its
/// span.
pub(super) fn pairs(it: &dyn Host, p: &mut Params, name: &str) -> R<(Vec<DVec2>, Span)> {
    let (v, sp) = p.req(name)?;
    let Value::List(items) = &v else {
        return Err(types::mismatch(it, "List", &v, sp).into());
    };
    let points = items
        .iter()
        .map(|x| pair(it, x, sp))
        .collect::<R<Vec<_>>>()?;
    Ok((points, sp))
}

/// The index of `name` among `names`, or `rtc::param::choice` naming them.
pub(super) fn choice(name: &str, names: &[&str], param: &str, span: Span) -> R<usize> {
    if let Some(k) = names.iter().position(|n| *n == name) {
        return Ok(k);
    }
    let list = names
        .iter()
        .map(|n| format!("\"{n}\""))
        .collect::<Vec<_>>()
        .join(", ");
    let help = suggest(name, names.iter().copied())
        .map(|h| format!("{h}; `{param}` is one of {list}"))
        .unwrap_or_else(|| format!("write one of {list}"));
    Err(error(
        "rtc::param::choice",
        span,
        format!("`{param}` cannot be \"{name}\""),
    )
    .with_label(format!("one of {list}"))
    .with_help(help)
    .into())
}
