//! Sphere sweeps: `sphere_sweep(points, radii, spline)` (POV-Ray's `sphere_sweep`;
//! docs/language.md).

use crate::eval::args::{ArgVal, CallSite, Params};
use crate::eval::error::R;
use crate::eval::host::{BuiltinFn, Host};
use crate::eval::schema::{Group, Param, Sig, Ty, Unit};
use crate::eval::types;
use crate::eval::value::Value;
use crate::ir::{Shape, SweepSpline};

use super::common::{checked, choice};

/// The constructors of this file.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[(&SPHERE_SWEEP, sphere_sweep)];

/// `sphere_sweep(points, radii, spline)`.
static SPHERE_SWEEP: Sig = Sig::new(
    "sphere_sweep",
    Group::Shape,
    "The union of the spheres whose centre and radius run along a spline through the given \
     spheres (POV-Ray's `sphere_sweep`): a tube of varying thickness.",
    &[
        Param::new(
            "points",
            Ty::ListOf(&Ty::Vec3),
            "the spheres' centres (linear: at least 2; catmull_rom, b_spline: at least 4)",
        )
        .unit(Unit::Length),
        Param::new(
            "radii",
            Ty::ListOf(&Ty::Float),
            "one radius > 0 per point",
        )
        .unit(Unit::Length),
        Param::new(
            "spline",
            Ty::String,
            "\"linear\" (default: spheres joined by cones), \"catmull_rom\" (through every point \
             but the first and last, which only steer) or \"b_spline\" (smooth, near the points)",
        )
        .optional(),
    ],
    "Object",
)
.examples(&[
    "sphere_sweep(points: [[-1, 0, 0], [0, 0.5, 0], [1, 0, 0]], radii: [0.1, 0.3, 0.1])",
    "sphere_sweep(points: [[-2, 0, 0], [-1, 0, 0], [0, 1, 0], [1, 0, 0], [2, 0, 0]], radii: [0.2, 0.2, 0.3, 0.2, 0.2], spline: \"catmull_rom\")",
]);
fn sphere_sweep(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &SPHERE_SWEEP, a)?;
    let (v, ps) = p.req("points")?;
    let points = match &v {
        Value::List(items) => {
            let mut out = Vec::with_capacity(items.len());
            for x in items.iter() {
                out.push(types::vec3(it, x, ps)?);
            }
            out
        }
        _ => return Err(types::mismatch(it, "List", &v, ps).into()),
    };
    let (v, rs) = p.req("radii")?;
    let radii = match &v {
        Value::List(items) => {
            let mut out = Vec::with_capacity(items.len());
            for x in items.iter() {
                out.push(types::num(it, x, rs)?);
            }
            out
        }
        // Three radii in brackets read as a vector: still the list of three.
        Value::Vec3(x) => x.to_array().to_vec(),
        _ => return Err(types::mismatch(it, "List", &v, rs).into()),
    };
    let spline = match p.get("spline") {
        None => SweepSpline::Linear,
        Some((Value::Str(name), ns)) => {
            SweepSpline::NAMED[choice(&name, &SweepSpline::NAMES, "spline", ns)?].1
        }
        Some((other, ns)) => return Err(types::mismatch(it, "String", &other, ns).into()),
    };
    if radii.len() != points.len() {
        return Err(crate::eval::error::error(
            "rtc::param::out_of_range",
            rs,
            format!(
                "a sphere sweep needs one radius per point: {} points, {} radii",
                points.len(),
                radii.len()
            ),
        )
        .with_label(format!("{} radii", radii.len()))
        .with_help(format!(
            "give exactly {} radii, one for each point",
            points.len()
        ))
        .into());
    }
    let spheres = points.into_iter().zip(radii).collect();
    checked(
        Shape::SphereSweep { spline, spheres },
        s,
        &[("points", ps), ("radii", rs)],
    )
}
