//! The solid modifiers of objects, after POV-Ray's: `.inverse()` turns a solid inside out (for
//! CSG: `a & b.inverse()` is `a - b`), `.clipped_by(solid)` keeps an object's surface where it
//! lies inside a solid, without closing it.

use std::rc::Rc;

use glam::DAffine3;

use super::args::{ArgVal, CallSite, Params};
use super::error::R;
use super::host::Host;
use super::operands::Operands;
use super::schema::{Group, Param, Sig, Ty};
use super::shapes::require_closed_to;
use super::types;
use super::value::{Obj, ObjShape, Value};
use crate::ir::{CsgOp, Visibility};

/// The modifier methods of objects.
pub(crate) static METHODS: &[&Sig] = &[&INVERSE, &CLIPPED_BY];

/// `.inverse()`.
static INVERSE: Sig = Sig::new(
    "inverse",
    Group::Method,
    "The solid turned inside out: inside becomes outside, the surface faces the other way (for CSG: `a & b.inverse()` is `a - b`).",
    &[],
    "Object",
)
.examples(&["box() & sphere(radius: 1.2).inverse()"]);

/// `.clipped_by(solid)`.
static CLIPPED_BY: Sig = Sig::new(
    "clipped_by",
    Group::Method,
    "The object's surface where it lies inside `solid`, left open (unlike `&`, the solid's own faces are not shown).",
    &[Param::new("solid", Ty::Object, "the closed solid that keeps the surface inside it")],
    "Object",
)
.examples(&["sphere().clipped_by(solid: box(min: [-1, -1, -1], max: [1, 0.5, 1]))"]);

/// Whether `name` is a modifier method.
pub(crate) fn is_method(name: &str) -> bool {
    METHODS.iter().any(|m| m.name == name)
}

/// `o.inverse()` or `o.clipped_by(solid)` (`site.name` tells which).
pub(crate) fn modify(it: &mut dyn Host, o: Rc<Obj>, site: CallSite, args: Vec<ArgVal>) -> R<Value> {
    if site.name == "inverse" {
        // The schema refuses arguments with the usual diagnostics.
        Params::new(site, &INVERSE, args)?;
        require_closed_to(it, &o, o.span, "be turned inside out")?;
        // Turning a solid inside out twice gives it back.
        if let ObjShape::Csg(CsgOp::Inverse, inner) = &o.shape
            && o.transform == DAffine3::IDENTITY
            && o.material.is_none()
            && o.motion.is_none()
            && o.visibility.is_all()
        {
            return Ok(Value::Object(Rc::new(inner.items()[0].clone())));
        }
        return Ok(node(CsgOp::Inverse, vec![(*o).clone()], site));
    }
    let mut p = Params::new(site, &CLIPPED_BY, args)?;
    let (v, span) = p.req("solid")?;
    let Value::Object(solid) = &v else {
        return Err(types::mismatch(it, "Object", &v, span).into());
    };
    require_closed_to(it, solid, span, "clip a surface")?;
    Ok(node(
        CsgOp::Clip,
        vec![(*o).clone(), (**solid).clone()],
        site,
    ))
}

/// A one- or two-operand node over `children`, placed where they are.
fn node(op: CsgOp, children: Vec<Obj>, site: CallSite) -> Value {
    Value::Object(Rc::new(Obj {
        shape: ObjShape::Csg(op, Operands::new(children)),
        transform: DAffine3::IDENTITY,
        material: None,
        motion: None,
        span: site.span,
        origin: 0,
        visibility: Visibility::ALL,
    }))
}
