//! Flat shapes: triangles, parallelograms, polygons, disks and rings (surfaces that enclose no
//! volume; CSG takes none of them).

use super::common::{checked, corner, direction, point, radius, unit_dir};
use crate::eval::args::Params;
use crate::eval::args::{ArgVal, CallSite};
use crate::eval::error::R;
use crate::eval::host::Host;
use crate::eval::schema::{Group, Lit, Param, Range, Sig, Ty, Unit};
use crate::eval::types;
use crate::eval::value::Value;
use crate::ir::Shape;

/// `triangle(a, b, c)`.
pub(super) static TRIANGLE: Sig = Sig::new(
    "triangle",
    Group::Shape,
    "A triangle, front side counter-clockwise (non-zero area).",
    &[
        corner("a", "the first corner"),
        corner("b", "the second corner"),
        corner("c", "the third corner"),
    ],
    "Object",
)
.examples(&["triangle(a: [0, 0, 0], b: [1, 0, 0], c: [0, 1, 0])"]);
pub(super) fn triangle(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &TRIANGLE, a)?;
    let (va, _) = p.vec3(it, "a")?;
    let (vb, _) = p.vec3(it, "b")?;
    let (vc, cs) = p.vec3(it, "c")?;
    checked(
        Shape::Triangle {
            vertices: [va, vb, vc],
        },
        s,
        &[("c", cs)],
    )
}

/// `quad(corner, u, v)`.
pub(super) static QUAD: Sig = Sig::new(
    "quad",
    Group::Shape,
    "The parallelogram `corner + s·u + t·v`, s, t in [0, 1] (u × v ≠ 0).",
    &[
        point("corner", "one corner"),
        corner("u", "one edge"),
        corner("v", "the other edge"),
    ],
    "Object",
)
.examples(&["quad(corner: [0, 0, 0], u: [1, 0, 0], v: [0, 0, 1])"]);
pub(super) fn quad(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &QUAD, a)?;
    let (corner, _) = p.vec3(it, "corner")?;
    let (u, _) = p.vec3(it, "u")?;
    let (v, vs) = p.vec3(it, "v")?;
    checked(Shape::Quad { corner, u, v }, s, &[("v", vs)])
}

/// `polygon(points)`.
pub(super) static POLYGON: Sig = Sig::new(
    "polygon",
    Group::Shape,
    "A flat polygon, closed implicitly; may be concave.",
    &[Param::new(
        "points",
        Ty::ListOf(&Ty::Vec3),
        "at least 3 corners in one plane",
    )
    .unit(Unit::Length)],
    "Object",
)
.examples(&["polygon(points: [[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]])"]);
pub(super) fn polygon(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &POLYGON, a)?;
    let (v, sp) = p.req("points")?;
    let items: Vec<Value> = match &v {
        Value::List(l) => l.to_vec(),
        other => return Err(types::mismatch(it, "List", other, sp).into()),
    };
    let mut points = Vec::with_capacity(items.len());
    for x in &items {
        points.push(types::vec3(it, x, sp)?);
    }
    checked(Shape::Polygon { points }, s, &[("points", sp)])
}

/// `disk(center, normal, radius)`.
pub(super) static DISK: Sig = Sig::new(
    "disk",
    Group::Shape,
    "A flat disk.",
    &[
        point("center", "the centre"),
        direction("normal", "the front side's normal (normalised)"),
        radius("radius", "the radius", 1.0),
    ],
    "Object",
)
.examples(&["disk(center: [0, 0.01, 0], normal: Y, radius: 2)"]);
pub(super) fn disk(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &DISK, a)?;
    let (center, _) = p.vec3(it, "center")?;
    let normal = unit_dir(it, &mut p, "normal")?;
    let (radius, rs) = p.float(it, "radius")?;
    checked(
        Shape::Disk {
            center,
            normal,
            radius,
        },
        s,
        &[("radius", rs)],
    )
}

/// `ring(center, normal, radius, inner)`.
pub(super) static RING: Sig = Sig::new(
    "ring",
    Group::Shape,
    "A disk with a round hole; uv: u around, v from the hole's edge (0) to the rim (1).",
    &[
        point("center", "the centre"),
        direction("normal", "the front side's normal (normalised)"),
        radius("radius", "the outer radius", 1.0),
        Param::new("inner", Ty::Float, "the hole's radius (< radius)")
            .unit(Unit::Length)
            .range(Range::NonNegative)
            .checked_by_builtin()
            .or(Lit::Float(0.5)),
    ],
    "Object",
)
.examples(&["ring(center: [0, 1, 0], normal: Y, radius: 2, inner: 1.5)"]);
pub(super) fn ring(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &RING, a)?;
    let (center, _) = p.vec3(it, "center")?;
    let normal = unit_dir(it, &mut p, "normal")?;
    let (radius, rs) = p.float(it, "radius")?;
    let (inner, is) = p.float(it, "inner")?;
    checked(
        Shape::Ring {
            center,
            normal,
            radius,
            inner,
        },
        s,
        &[("radius", rs), ("inner", is)],
    )
}
