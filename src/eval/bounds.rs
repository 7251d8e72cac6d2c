//! `obj.bounds`: world-space axis-aligned bounds of an object value, as a record with `min`,
//! `max`, `center`, `size`, `top_center` and `bottom_center` (top and bottom along +Y).
//!
//! Every fact comes from geometry (`geometry::shapes::bounds` per shape, `geometry::shapes::csg::bounds`
//! for CSG, `Aabb::transformed` for the corners) and a mesh's vertex bounds from the asset
//! service; only the walk over object values is here: each leaf's box is moved into world
//! space by its whole chain of transforms before boxes combine, which is tighter for rotated
//! groups than combining first.

use glam::{DAffine3, DVec3};

use crate::geometry::{Aabb, shapes, shapes::csg};
use crate::ir::{CsgOp, Shape};
use crate::source::Span;

use super::error::{R, error};
use super::host::Host;
use super::value::{Obj, ObjShape, Value};

/// A mesh's vertex bounds, through the asset service (which keeps the load for the render; no
/// BVH is built to answer).
fn mesh_bounds(source: &crate::ir::MeshSource, smooth: bool, span: Span) -> R<Aabb> {
    let mesh = crate::assets::mesh_of(source, smooth).map_err(|e| e.diagnostic_of(span, source))?;
    Ok(Aabb::new(mesh.min, mesh.max))
}

fn unbounded(span: Span) -> super::error::EvalError {
    error(
        "rtc::value::unbounded",
        span,
        "this object has no finite bounds",
    )
    .with_label("it contains an infinite plane")
    .with_help("ask for the bounds of a finite part instead")
    .into()
}

/// Bounds in the space the object's own transform maps into, composed with `parent`.
fn bb(o: &Obj, parent: DAffine3, span: Span) -> R<Aabb> {
    let t = parent * o.transform;
    match &o.shape {
        ObjShape::Prim(Shape::Mesh { source, smooth, .. }) => {
            Ok(mesh_bounds(source, *smooth, span)?.transformed(&t))
        }
        ObjShape::Prim(s) => {
            let local = shapes::bounds(s).filter(Aabb::is_finite);
            local
                .map(|b| b.transformed(&t))
                .ok_or_else(|| unbounded(span))
        }
        ObjShape::Group(ch) => combined(CsgOp::Union, ch, t, span),
        ObjShape::Csg(op, ch) => combined(*op, &ch.items(), t, span),
    }
}

/// Bounds of `op` over `ch`, each placed by `t`.
fn combined(op: CsgOp, ch: &[Obj], t: DAffine3, span: Span) -> R<Aabb> {
    // A difference is bounded by its base alone: the cutters need no bounds of their own.
    let operands = match op {
        CsgOp::Difference => &ch[..ch.len().min(1)],
        // An inverted solid is everything outside its operand: unbounded.
        CsgOp::Inverse => return Err(unbounded(span)),
        _ => ch,
    };
    let overlap = matches!(op, CsgOp::Intersection | CsgOp::Clip);
    let mut boxes = Vec::with_capacity(operands.len());
    for c in operands {
        match bb(c, t, span) {
            Ok(b) => boxes.push(b),
            // An intersection (or a clip) is bounded by its finite operands (an infinite one
            // leaves the others' overlap as it is).
            Err(_) if overlap => {}
            Err(e) => return Err(e),
        }
    }
    if overlap && boxes.is_empty() {
        return Err(unbounded(span));
    }
    let b = csg::bounds(op, &boxes);
    if !b.is_finite() {
        return Err(unbounded(span));
    }
    // An empty overlap is reported as a box of no size at its corner.
    Ok(Aabb::new(b.min, b.max.max(b.min)))
}

/// The `bounds` record of an object.
pub(crate) fn bounds_value(_it: &mut dyn Host, o: &Obj, span: Span) -> R<Value> {
    let b = bb(o, DAffine3::IDENTITY, span)?;
    let (lo, hi) = (b.min, b.max);
    let c = (lo + hi) / 2.0;
    Ok(super::value::record_of(
        &[
            ("min", Value::Vec3(lo)),
            ("max", Value::Vec3(hi)),
            ("center", Value::Vec3(c)),
            ("size", Value::Vec3(hi - lo)),
            ("top_center", Value::Vec3(DVec3::new(c.x, hi.y, c.z))),
            ("bottom_center", Value::Vec3(DVec3::new(c.x, lo.y, c.z))),
        ],
        span,
    ))
}
