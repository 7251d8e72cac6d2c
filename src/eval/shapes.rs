//! Shape constructors with schema-checked parameters (groups and CSG are in `compound`, meshes
//! in `mesh`, prisms and text in `extrude`, lathes, sors, superellipsoids and polynomial surfaces in
//! `revolve`, sphere sweeps in `sweep`, bicubic patches in `patch`).

use glam::DVec3;

use super::args::Params;
use super::args::{ArgVal, CallSite};
use super::error::R;
use super::host::BuiltinFn;
use super::host::Host;
use super::schema::{Group, Lit, Param, Range, Sig, Ty, Unit};
use super::types;
use super::value::Value;
use crate::ir::{BlobComponent, Shape, Spindle};
use crate::source::Span;

mod common;
mod compound;
mod extrude;
mod flat;
mod height_field;
mod isosurface;
mod mesh;
mod mesh_inline;
mod patch;
mod revolve;
mod sweep;

use common::{checked, direction, point, radius, unit_dir};

pub(crate) use compound::{FNS as COMPOUND_FNS, require_closed, require_closed_to};
pub(crate) use height_field::FNS as HEIGHT_FIELD_FNS;
pub(crate) use isosurface::FNS as ISOSURFACE_FNS;
pub(crate) use revolve::FNS as REVOLVE_FNS;
pub(crate) use sweep::FNS as SWEEP_FNS;

/// Shape constructors with their schemas (groups and CSG are in `compound`). The ranges of a shape's numbers are checked by
/// geometry's shape rules once the shape is made (`checked`), which name the parameter to
/// blame; the schema states them for the reference.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[
    (&SPHERE, sphere),
    (&PLANE, plane),
    (&BOX, box_),
    (&flat::TRIANGLE, flat::triangle),
    (&flat::QUAD, flat::quad),
    (&flat::POLYGON, flat::polygon),
    (&flat::DISK, flat::disk),
    (&flat::RING, flat::ring),
    (&CYLINDER, cylinder),
    (&CONE, cone),
    (&TORUS, torus),
    (&QUADRIC, quadric),
    (&BLOB, blob),
    (&mesh::MESH, mesh::mesh),
    (&extrude::PRISM, extrude::prism),
    (&extrude::TEXT, extrude::text),
    (&patch::BICUBIC_PATCH, patch::bicubic_patch),
];

/// `capped: Bool = true` of cylinders and cones.
const CAPPED: Param = Param::new(
    "capped",
    Ty::Bool,
    "closes the ends (`false`: an open tube)",
)
.or(Lit::Bool(true));

/// The ends of cylinders and cones: `base` and `top`, or `center`, `axis` and `height`.
const ENDS: [Param; 5] = [
    Param::new("base", Ty::Vec3, "the centre of the base end")
        .unit(Unit::Length)
        .optional(),
    Param::new("top", Ty::Vec3, "the centre of the top end (≠ base)")
        .unit(Unit::Length)
        .optional(),
    point("center", "the middle, without `base` and `top`"),
    direction("axis", "from base to top, without both ends"),
    Param::new(
        "height",
        Ty::Float,
        "the length along `axis`, without both ends",
    )
    .unit(Unit::Length)
    .range(Range::Positive)
    .or(Lit::Float(1.0)),
];

/// `sphere(center, radius)`.
static SPHERE: Sig = Sig::new(
    "sphere",
    Group::Shape,
    "A sphere.",
    &[
        point("center", "the centre"),
        radius("radius", "the radius", 1.0),
    ],
    "Object",
)
.examples(&["sphere(center: [0, 1, 0], radius: 1)"]);
fn sphere(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &SPHERE, a)?;
    let (center, _) = p.vec3(it, "center")?;
    let (radius, rs) = p.float(it, "radius")?;
    checked(Shape::Sphere { center, radius }, s, &[("radius", rs)])
}

/// `plane(point, normal)`.
static PLANE: Sig = Sig::new(
    "plane",
    Group::Shape,
    "A half-space: the normal points outside.",
    &[
        point("point", "a point of the plane"),
        direction("normal", "the outward normal (normalised)"),
    ],
    "Object",
)
.examples(&["plane(point: [0, 0, 0], normal: Y)"]);
fn plane(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &PLANE, a)?;
    let (point, _) = p.vec3(it, "point")?;
    let normal = unit_dir(it, &mut p, "normal")?;
    checked(Shape::Plane { point, normal }, s, &[])
}

/// `box(min, max)`.
static BOX: Sig = Sig::new(
    "box",
    Group::Shape,
    "An axis-aligned box (before transforms).",
    &[
        Param::new("min", Ty::Vec3, "the lowest corner")
            .unit(Unit::Length)
            .or(Lit::Vec3([-0.5, -0.5, -0.5])),
        Param::new("max", Ty::Vec3, "the highest corner (> min on every axis)")
            .unit(Unit::Length)
            .or(Lit::Vec3([0.5, 0.5, 0.5])),
    ],
    "Object",
)
.examples(&["box(min: [-1, 0, -1], max: [1, 2, 1])"]);
fn box_(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &BOX, a)?;
    let (min, _) = p.vec3(it, "min")?;
    let (max, ms) = p.vec3(it, "max")?;
    checked(Shape::Box { min, max }, s, &[("max", ms)])
}

/// Reads `base`/`top`, or `center`/`axis`/`height` (centred on `center` along `axis`), with the
/// span to blame for the top.
fn ends(it: &dyn Host, p: &mut Params) -> R<(DVec3, DVec3, Span)> {
    let base = p.get("base");
    let top = p.get("top");
    let (center, _) = p.vec3(it, "center")?;
    let axis = unit_dir(it, p, "axis")?;
    let (height, hs) = p.float(it, "height")?;
    Ok(match (base, top) {
        (Some((b, bs)), Some((t, ts))) => {
            let (b, t) = (types::vec3(it, &b, bs)?, types::vec3(it, &t, ts)?);
            (b, t, ts)
        }
        (Some((b, bs)), None) => {
            let b = types::vec3(it, &b, bs)?;
            (b, b + axis * height, hs)
        }
        (None, Some((t, ts))) => {
            let t = types::vec3(it, &t, ts)?;
            (t - axis * height, t, ts)
        }
        (None, None) => (
            center - axis * (height / 2.0),
            center + axis * (height / 2.0),
            hs,
        ),
    })
}

/// `cylinder(radius, base, top, center, axis, height, capped)`.
static CYLINDER: Sig = Sig::new(
    "cylinder",
    Group::Shape,
    "A cylinder from `base` to `top`, or centred on `center` along `axis`.",
    &[
        radius("radius", "the radius", 1.0),
        ENDS[0],
        ENDS[1],
        ENDS[2],
        ENDS[3],
        ENDS[4],
        CAPPED,
    ],
    "Object",
)
.examples(&[
    "cylinder(base: [0, 0, 0], top: [0, 2, 0], radius: 0.25)",
    "cylinder(radius: 0.5, center: [0, 0, 0], axis: X, height: 3, capped: false)",
]);
fn cylinder(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &CYLINDER, a)?;
    let (radius, rs) = p.float(it, "radius")?;
    let (base, top, top_span) = ends(it, &mut p)?;
    let capped = p.bool(it, "capped")?;
    checked(
        Shape::Cylinder {
            base,
            top,
            radius,
            capped,
        },
        s,
        &[("radius", rs), ("top", top_span)],
    )
}

/// A cone's radius at one end (>= 0, not both 0, by the shape rules).
const fn end_radius(name: &'static str, doc: &'static str, default: f64) -> Param {
    Param::new(name, Ty::Float, doc)
        .unit(Unit::Length)
        .range(Range::NonNegative)
        .checked_by_builtin()
        .or(Lit::Float(default))
}

/// `cone(base_radius, top_radius, base, top, center, axis, height, capped)`.
static CONE: Sig = Sig::new(
    "cone",
    Group::Shape,
    "A cone, or a frustum when both radii are > 0; ends as for `cylinder`.",
    &[
        end_radius("base_radius", "the radius at `base`", 1.0),
        end_radius("top_radius", "the radius at `top`", 0.0),
        ENDS[0],
        ENDS[1],
        ENDS[2],
        ENDS[3],
        ENDS[4],
        CAPPED,
    ],
    "Object",
)
.examples(&[
    "cone(base_radius: 1, top_radius: 0.2, base: [0, 0, 0], axis: Y, height: 1.5, capped: false)",
]);
fn cone(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &CONE, a)?;
    let (br, bs) = p.float(it, "base_radius")?;
    let (tr, ts) = p.float(it, "top_radius")?;
    let (base, top, top_span) = ends(it, &mut p)?;
    let capped = p.bool(it, "capped")?;
    checked(
        Shape::Cone {
            base,
            top,
            base_radius: br,
            top_radius: tr,
            capped,
        },
        s,
        &[("base_radius", bs), ("top_radius", ts), ("top", top_span)],
    )
}

/// `torus(major_radius, minor_radius, center)`.
static TORUS: Sig = Sig::new(
    "torus",
    Group::Shape,
    "A torus in the xz-plane around +Y.",
    &[
        Param::new(
            "major_radius",
            Ty::Float,
            "from the centre to the tube's centre",
        )
        .unit(Unit::Length)
        .range(Range::Positive)
        .checked_by_builtin(),
        Param::new(
            "minor_radius",
            Ty::Float,
            "the tube's radius (larger than major_radius: a spindle torus)",
        )
        .unit(Unit::Length)
        .range(Range::Positive)
        .checked_by_builtin(),
        point("center", "the centre"),
        Param::new(
            "spindle",
            Ty::String,
            "a spindle torus's parts (minor_radius > major_radius): \"union\" (both surfaces, all inside), \"merge\" (the outer surface), \"intersection\" (the inner lemon alone) or \"difference\" (both surfaces, the lemon outside)",
        )
        .checked_by_builtin()
        .or(Lit::Name("\"union\"")),
    ],
    "Object",
)
.examples(&[
    "torus(major_radius: 1, minor_radius: 0.25, center: [0, 1, 0])",
    "torus(major_radius: 0.5, minor_radius: 1, spindle: \"difference\")",
]);
fn torus(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &TORUS, a)?;
    let (major, ms) = p.float(it, "major_radius")?;
    let (minor, ns) = p.float(it, "minor_radius")?;
    let (center, _) = p.vec3(it, "center")?;
    let (spindle, ss) = match p.get("spindle") {
        None => (Spindle::default(), s.span),
        Some((Value::Str(name), sp)) => {
            let names = Spindle::NAMES.map(|(n, _)| n);
            (
                Spindle::NAMES[common::choice(&name, &names, "spindle", sp)?].1,
                sp,
            )
        }
        Some((other, sp)) => return Err(types::mismatch(it, "String", &other, sp).into()),
    };
    checked(
        Shape::Torus {
            center,
            major_radius: major,
            minor_radius: minor,
            spindle,
        },
        s,
        &[("major_radius", ms), ("minor_radius", ns), ("spindle", ss)],
    )
}

/// `quadric(squares, mixed, linear, constant)`.
static QUADRIC: Sig = Sig::new(
    "quadric",
    Group::Shape,
    "The surface A·x² + B·y² + C·z² + D·xy + E·xz + F·yz + G·x + H·y + I·z + J = 0, inside where \
     negative (POV-Ray's `quadric`; usually unbounded: bound it with CSG).",
    &[
        Param::new(
            "squares",
            Ty::Vec3,
            "A, B, C: the coefficients of x², y², z²",
        ),
        Param::new("mixed", Ty::Vec3, "D, E, F: the coefficients of xy, xz, yz")
            .or(Lit::Vec3([0.0, 0.0, 0.0])),
        Param::new("linear", Ty::Vec3, "G, H, I: the coefficients of x, y, z")
            .or(Lit::Vec3([0.0, 0.0, 0.0])),
        Param::new("constant", Ty::Float, "J").or(Lit::Float(0.0)),
    ],
    "Object",
)
.examples(&[
    "quadric(squares: [1, 1, 1], constant: -1)  // the unit sphere",
    "quadric(squares: [1, 0, 1], linear: [0, -1, 0])  // the paraboloid y = x² + z²",
]);
fn quadric(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &QUADRIC, a)?;
    let (squares, ss) = p.vec3(it, "squares")?;
    let (mixed, ms) = p.vec3(it, "mixed")?;
    let (linear, ls) = p.vec3(it, "linear")?;
    let (constant, cs) = p.float(it, "constant")?;
    checked(
        Shape::Quadric {
            squares,
            mixed,
            linear,
            constant,
        },
        s,
        &[
            ("squares", ss),
            ("mixed", ms),
            ("linear", ls),
            ("constant", cs),
        ],
    )
}

/// `blob(components, threshold)`.
static BLOB: Sig = Sig::new(
    "blob",
    Group::Shape,
    "A blob: the surface where the components' summed field reaches `threshold`.",
    &[
        Param::new(
            "components",
            Ty::ListOf(&Ty::Record),
            "at least one `blob component` record",
        ),
        Param::new("threshold", Ty::Float, "the field value on the surface")
            .range(Range::Positive)
            .checked_by_builtin()
            .or(Lit::Float(0.5)),
    ],
    "Object",
)
.examples(&[
    "blob(components: [{ center: [-0.4, 0, 0] }, { center: [0.4, 0, 0] }], threshold: 0.6)",
]);

/// A blob's component, a record in `blob(components: [...])`.
pub(crate) static BLOB_COMPONENT: Sig = Sig::new(
    "blob component",
    Group::Record,
    "One component of a `blob`: a sphere of influence, or a cylinder of influence with round ends when `end` is given.",
    &[
        point("center", "the centre (a cylinder's first end)"),
        Param::new(
            "end",
            Ty::Vec3,
            "a cylinder component's other end (POV-Ray's blob `cylinder`)",
        )
        .optional(),
        radius("radius", "how far its field reaches", 1.0),
        Param::new(
            "strength",
            Ty::Float,
            "its field at the centre (negative subtracts)",
        )
        .or(Lit::Float(1.0)),
    ],
    "",
)
.examples(&["blob(components: [{ center: [0, 0, 0], radius: 1, strength: 1 }, { center: [0.5, 0, 0], strength: -0.5 }])"]);
fn blob(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &BLOB, a)?;
    let (v, sp) = p.req("components")?;
    let Value::List(items) = &v else {
        return Err(types::mismatch(it, "List", &v, sp).into());
    };
    let mut components = Vec::with_capacity(items.len());
    for c in items.iter() {
        let site = CallSite {
            span: sp,
            name: "blob component",
        };
        let arg = ArgVal {
            name: None,
            value: c.clone(),
            span: sp,
        };
        let mut cp = Params::new(site, &BLOB_COMPONENT, vec![arg])?;
        let (center, _) = cp.vec3(it, "center")?;
        let end = cp.vec3_opt(it, "end")?.map(|(e, _)| e);
        let (radius, _) = cp.float(it, "radius")?;
        let (strength, _) = cp.float(it, "strength")?;
        components.push(BlobComponent {
            center,
            radius,
            strength,
            end,
        });
    }
    let (threshold, ts) = p.float(it, "threshold")?;
    checked(
        Shape::Blob {
            components,
            threshold,
        },
        s,
        &[
            ("components", sp),
            ("end", sp),
            ("radius", sp),
            ("strength", sp),
            ("threshold", ts),
        ],
    )
}
