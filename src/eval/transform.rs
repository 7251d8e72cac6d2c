//! Transforms as values: `translate`, `scale`, `rotate`, `matrix`, `around`, and their method
//! forms on objects and transforms (applied in reading order).

use crate::num::Norm;
use glam::{DAffine3, DMat3, DVec3};

use super::args::Params;
use super::args::{ArgVal, CallSite};
use super::error::{R, error};
use super::host::BuiltinFn;
use super::host::Host;
use super::types;
use super::value::Value;
use crate::source::Span;

/// Transform constructors (each builds a `DAffine3`; the value is made here, so that the
/// method forms on objects never put a transform behind an `Rc` only to take it out).
pub const FNS: &[(&str, BuiltinFn)] = &[
    ("translate", |it, s, a| translate(it, s, a).map(t)),
    ("scale", |it, s, a| scale(it, s, a).map(t)),
    ("rotate", |it, s, a| rotate(it, s, a).map(t)),
    ("matrix", |it, s, a| matrix(it, s, a).map(t)),
    ("around", |it, s, a| around(it, s, a).map(t)),
    ("identity", |it, s, a| identity(it, s, a).map(t)),
    ("look_at", super::motion::look_at_fn),
];

/// Names usable as methods on objects and transforms.
pub const METHODS: &[&str] = &[
    "translate",
    "scale",
    "rotate",
    "matrix",
    "around",
    "transform",
];

fn t(a: DAffine3) -> Value {
    Value::Transform(std::rc::Rc::new(a))
}

/// Errors if `a` is singular (it would flatten space) or not finite.
pub fn nonsingular(a: DAffine3, span: Span) -> R<DAffine3> {
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

fn translate(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<DAffine3> {
    let mut p = Params::new(s, &["offset"], a)?;
    let (v, sp) = p.vec3(it, "offset")?;
    nonsingular(DAffine3::from_translation(v), sp)
}

fn scale(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<DAffine3> {
    let mut p = Params::new(s, &["factor"], a)?;
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

fn rotate(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<DAffine3> {
    let mut p = Params::new(s, &["x", "y", "z", "axis", "angle"], a)?;
    if let Some((av, asp)) = p.get("axis") {
        let axis = types::vec3(it, &av, asp)?;
        if axis.length_squared() == 0.0 {
            return Err(error(
                "rtc::param::out_of_range",
                asp,
                "`axis` must be a non-zero vector",
            )
            .with_label("this vector has length 0")
            .with_help("give a direction, e.g. `axis: Y`")
            .into());
        }
        let (an, ans) = p.req("angle")?;
        let angle = types::angle(it, &an, ans)?;
        return Ok(DAffine3::from_axis_angle(axis.unit(), angle));
    }
    let (x, _) = p.angle_or(it, "x", 0.0)?;
    let (y, _) = p.angle_or(it, "y", 0.0)?;
    let (z, _) = p.angle_or(it, "z", 0.0)?;
    Ok(DAffine3::from_rotation_z(z) * DAffine3::from_rotation_y(y) * DAffine3::from_rotation_x(x))
}

fn matrix(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<DAffine3> {
    let mut p = Params::new(s, &["rows"], a)?;
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

fn around(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<DAffine3> {
    let mut p = Params::new(s, &["pivot", "transform"], a)?;
    let (pivot, _) = p.vec3(it, "pivot")?;
    let (tv, ts) = p.req("transform")?;
    let Value::Transform(inner) = tv else {
        return Err(types::mismatch(it, "Transform", &tv, ts).into());
    };
    Ok(DAffine3::from_translation(pivot) * *inner * DAffine3::from_translation(-pivot))
}

fn identity(_: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<DAffine3> {
    Params::new(s, &[], a)?;
    Ok(DAffine3::IDENTITY)
}

/// Builds the transform a method such as `.rotate(y: 30deg)` applies (`.transform(t)` passes `t`).
pub fn method_transform(
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
            let mut p = Params::new(site, &["transform"], args)?;
            let (tv, ts) = p.req("transform")?;
            match tv {
                Value::Transform(a) => Ok(*a),
                other => Err(types::mismatch(it, "Transform", &other, ts).into()),
            }
        }
    }
}
