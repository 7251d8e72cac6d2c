//! Transforms as values: `translate`, `scale`, `rotate`, `matrix`, `around`, and their method
//! forms on objects and transforms (applied in reading order).

use crate::num::Norm;
use glam::{DAffine3, DMat3, DVec3};

use super::args::Params;
use super::args::{ArgVal, CallSite};
use super::error::{R, error};
use super::host::BuiltinFn;
use super::host::Host;
use super::schema::{Group, Lit, Param, Range, Sig, Ty, Unit};
use super::types;
use super::value::Value;
use crate::source::Span;

/// Transform constructors (each builds a `DAffine3`; the value is made here, so that the
/// method forms on objects never put a transform behind an `Rc` only to take it out).
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[
    (&TRANSLATE, |it, s, a| translate(it, s, a).map(t)),
    (&SCALE, |it, s, a| scale(it, s, a).map(t)),
    (&ROTATE, |it, s, a| rotate(it, s, a).map(t)),
    (&MATRIX, |it, s, a| matrix(it, s, a).map(t)),
    (&AROUND, |it, s, a| around(it, s, a).map(t)),
    (&IDENTITY, |it, s, a| identity(it, s, a).map(t)),
    (&super::motion::LOOK_AT, super::motion::look_at_fn),
];

/// The methods of objects and transforms that apply a transform (`.rotate(y: 30deg)`), in
/// the order messages list them.
pub(crate) static METHODS: &[&Sig] = &[&TRANSLATE, &SCALE, &ROTATE, &MATRIX, &AROUND, &TRANSFORM];

/// Whether `name` is one of [`METHODS`].
pub(crate) fn is_method(name: &str) -> bool {
    METHODS.iter().any(|m| m.name == name)
}

fn t(a: DAffine3) -> Value {
    Value::Transform(std::rc::Rc::new(a))
}

/// Errors if `a` is singular (it would flatten space) or not finite.
pub(crate) fn nonsingular(a: DAffine3, span: Span) -> R<DAffine3> {
    let det = a.matrix3.determinant();
    if det == 0.0 || !det.is_finite() || !a.translation.is_finite() {
        return Err(
            error("rtc::transform::singular", span, "singular transform")
                .with_label("this flattens space (a zero scale or a degenerate matrix)")
                .with_help("use non-zero scale factors, e.g. `scale(0.001)` instead of `scale(0)`")
                .into(),
        );
    }
    Ok(a)
}

/// `translate(offset)`.
static TRANSLATE: Sig = Sig::new(
    "translate",
    Group::Transform,
    "Moves by `offset`.",
    &[Param::new("offset", Ty::Vec3, "the move").unit(Unit::Length)],
    "Transform",
)
.examples(&["translate(offset: [1, 2, 3])"]);
fn translate(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<DAffine3> {
    let mut p = Params::new(s, &TRANSLATE, a)?;
    let (v, sp) = p.vec3(it, "offset")?;
    nonsingular(DAffine3::from_translation(v), sp)
}

/// `scale(factor)`.
static SCALE: Sig = Sig::new(
    "scale",
    Group::Transform,
    "Scales about the origin; negative factors mirror.",
    &[Param::new(
        "factor",
        Ty::OneOf(&[Ty::Float, Ty::Vec3]),
        "one factor, or one per axis (none zero)",
    )],
    "Transform",
)
.examples(&["scale(factor: [2, 1, 1])", "scale(0.5)"]);
fn scale(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<DAffine3> {
    let mut p = Params::new(s, &SCALE, a)?;
    let (v, sp) = p.req("factor")?;
    let f = match &v {
        Value::Vec3(x) => *x,
        other => match other.as_f64() {
            Some(x) => DVec3::splat(x),
            None => return Err(types::mismatch(it, "Vec3", other, sp).into()),
        },
    };
    nonsingular(DAffine3::from_scale(f), sp)
}

/// An angle about an axis, 0 unless given.
const fn about(name: &'static str, doc: &'static str) -> Param {
    Param::new(name, Ty::Angle, doc)
        .unit(Unit::Angle)
        .or(Lit::Degrees(0.0))
}

/// `rotate(x, y, z)` or `rotate(axis, angle)`.
static ROTATE: Sig = Sig::new(
    "rotate",
    Group::Transform,
    "Rotates about X, then Y, then Z (right-handed, about the origin), or about `axis`.",
    &[
        about("x", "about the X axis (first)"),
        about("y", "about the Y axis (second)"),
        about("z", "about the Z axis (third)"),
        Param::new(
            "axis",
            Ty::Vec3,
            "an axis through the origin, instead of x, y, z",
        )
        .range(Range::NonZero)
        .optional(),
        Param::new(
            "angle",
            Ty::Angle,
            "the angle about `axis` (required with it)",
        )
        .unit(Unit::Angle)
        .optional(),
    ],
    "Transform",
)
.examples(&[
    "rotate(x: 10deg, y: 20deg, z: 30deg)",
    "rotate(axis: [1, 1, 0], angle: 45deg)",
]);
fn rotate(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<DAffine3> {
    let mut p = Params::new(s, &ROTATE, a)?;
    if let Some((axis, _)) = p.vec3_opt(it, "axis")? {
        let (an, ans) = p.req("angle")?;
        let angle = p.angle_in(it, "angle", &an, ans)?;
        return Ok(DAffine3::from_axis_angle(axis.unit(), angle));
    }
    let (x, _) = p.angle(it, "x")?;
    let (y, _) = p.angle(it, "y")?;
    let (z, _) = p.angle(it, "z")?;
    Ok(DAffine3::from_rotation_z(z) * DAffine3::from_rotation_y(y) * DAffine3::from_rotation_x(x))
}

/// `matrix(rows)`.
static MATRIX: Sig = Sig::new(
    "matrix",
    Group::Transform,
    "An explicit affine map: `[[a, b, c, tx], [d, e, f, ty], [g, h, i, tz]]`.",
    &[Param::new(
        "rows",
        Ty::ListOf(&Ty::List),
        "3 rows of 4 numbers",
    )],
    "Transform",
)
.examples(&["matrix(rows: [[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0]])"]);
fn matrix(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<DAffine3> {
    let mut p = Params::new(s, &MATRIX, a)?;
    let (v, sp) = p.req("rows")?;
    let bad = || {
        error("rtc::type::mismatch", sp, "expected 3 rows of 4 numbers")
            .with_label("not a 3×4 matrix")
            .with_help("write `matrix([[1, 0, 0, tx], [0, 1, 0, ty], [0, 0, 1, tz]])`")
    };
    let Value::List(rows) = &v else {
        return Err(bad().into());
    };
    if rows.len() != 3 {
        return Err(bad().into());
    }
    let mut m = [[0.0; 4]; 3];
    for (i, r) in rows.iter().enumerate() {
        let Value::List(cells) = r else {
            return Err(bad().into());
        };
        if cells.len() != 4 {
            return Err(bad().into());
        }
        for (j, c) in cells.iter().enumerate() {
            m[i][j] = types::num(it, c, sp)?;
        }
    }
    let mat = DMat3::from_cols(
        DVec3::new(m[0][0], m[1][0], m[2][0]),
        DVec3::new(m[0][1], m[1][1], m[2][1]),
        DVec3::new(m[0][2], m[1][2], m[2][2]),
    );
    let tr = DVec3::new(m[0][3], m[1][3], m[2][3]);
    nonsingular(DAffine3::from_mat3_translation(mat, tr), sp)
}

/// `around(pivot, transform)`.
static AROUND: Sig = Sig::new(
    "around",
    Group::Transform,
    "Applies `transform` about `pivot` instead of the origin.",
    &[
        Param::new("pivot", Ty::Vec3, "the fixed point").unit(Unit::Length),
        Param::new("transform", Ty::Transform, "the transform to apply"),
    ],
    "Transform",
)
.examples(&["around(pivot: [1, 0, 0], transform: rotate(y: 90deg))"]);
fn around(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<DAffine3> {
    let mut p = Params::new(s, &AROUND, a)?;
    let (pivot, _) = p.vec3(it, "pivot")?;
    let (tv, ts) = p.req("transform")?;
    let Value::Transform(inner) = tv else {
        return Err(types::mismatch(it, "Transform", &tv, ts).into());
    };
    Ok(DAffine3::from_translation(pivot) * *inner * DAffine3::from_translation(-pivot))
}

/// `identity()`.
static IDENTITY: Sig = Sig::new(
    "identity",
    Group::Transform,
    "The identity.",
    &[],
    "Transform",
)
.examples(&["identity()"]);
fn identity(_: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<DAffine3> {
    Params::new(s, &IDENTITY, a)?;
    Ok(DAffine3::IDENTITY)
}

/// `.transform(t)`: applies a transform value.
static TRANSFORM: Sig = Sig::new(
    "transform",
    Group::Method,
    "Applies the transform `transform`.",
    &[Param::new(
        "transform",
        Ty::Transform,
        "the transform to apply",
    )],
    "the receiver, transformed",
)
.examples(&["box().transform(transform: rotate(y: 90deg) >> translate([0, 1, 0]))"]);

/// Builds the transform a method such as `.rotate(y: 30deg)` applies (`.transform(t)` passes `t`).
pub(crate) fn method_transform(
    it: &mut dyn Host,
    name: &'static str,
    site: CallSite,
    args: Vec<ArgVal>,
) -> R<DAffine3> {
    match name {
        "translate" => translate(it, site, args),
        "scale" => scale(it, site, args),
        "rotate" => rotate(it, site, args),
        "matrix" => matrix(it, site, args),
        "around" => around(it, site, args),
        _ => {
            let mut p = Params::new(site, &TRANSFORM, args)?;
            let (tv, ts) = p.req("transform")?;
            match tv {
                Value::Transform(a) => Ok(*a),
                other => Err(types::mismatch(it, "Transform", &other, ts).into()),
            }
        }
    }
}
