//! `isosurface(f, ...)`: POV-Ray's isosurface, its function compiled once by the compiler of
//! `pattern(f)` (docs/language.md §13.9).

use std::sync::Arc;

use glam::DVec3;

use crate::diag::{Diagnostic, number};
use crate::eval::args::{ArgVal, CallSite, Params};
use crate::eval::error::{R, error};
use crate::eval::host::{BuiltinFn, Host};
use crate::eval::schema::{Group, Lit, Param, Range, Sig, Ty, Unit};
use crate::eval::value::Value;
use crate::geometry::shapes::isosurface::{SAFETY, sample_slope, suggested};
use crate::ir::{Container, Shape};

use super::common::checked;

/// The constructors of this file.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[(&ISOSURFACE, isosurface)];

/// POV-Ray's default `accuracy`.
const ACCURACY: f64 = 0.001;

/// `isosurface(f, min, max, center, radius, threshold, max_gradient, accuracy, open)`.
static ISOSURFACE: Sig = Sig::new(
    "isosurface",
    Group::Shape,
    "The surface where `f(p)` equals `threshold` inside a box (`min`, `max`) or a sphere \
     (`radius`, `center`), inside where `f(p)` is below it (POV-Ray's `isosurface`); the \
     container's walls close the solid unless `open`. `f` is compiled once, as for `pattern(f)`.",
    &[
        Param::new("f", Ty::Fn, "a `fn(p)` of the object-space point giving a number"),
        Param::new("min", Ty::Vec3, "the container box's lowest corner")
            .unit(Unit::Length)
            .or(Lit::Vec3([-1.0, -1.0, -1.0])),
        Param::new(
            "max",
            Ty::Vec3,
            "the container box's highest corner (> min on every axis)",
        )
        .unit(Unit::Length)
        .or(Lit::Vec3([1.0, 1.0, 1.0])),
        Param::new(
            "center",
            Ty::Vec3,
            "the container sphere's centre (with `radius`)",
        )
        .unit(Unit::Length)
        .optional(),
        Param::new(
            "radius",
            Ty::Float,
            "a container sphere's radius, instead of the box",
        )
        .unit(Unit::Length)
        .range(Range::Positive)
        .checked_by_builtin()
        .optional(),
        Param::new("threshold", Ty::Float, "the value of `f` on the surface").or(Lit::Float(0.0)),
        Param::new(
            "max_gradient",
            Ty::Float,
            "a bound on how fast `f` changes per unit length; estimated when not given",
        )
        .range(Range::Positive)
        .checked_by_builtin()
        .optional(),
        Param::new(
            "accuracy",
            Ty::Float,
            "the shortest search step: thinner features may be missed",
        )
        .unit(Unit::Length)
        .range(Range::Positive)
        .checked_by_builtin()
        .or(Lit::Float(ACCURACY)),
        Param::new(
            "open",
            Ty::Bool,
            "leaves the container's walls open (a surface, not a solid)",
        )
        .or(Lit::Bool(false)),
    ],
    "Object",
)
.examples(&[
    "isosurface(f: fn(p) { length(p) - 0.8 })  // a sphere",
    "isosurface(f: fn(p) { p.y + 0.2 * sin(4rad * p.x) }, min: [-2, -1, -2], max: [2, 1, 2], max_gradient: 1.2)",
    "isosurface(f: fn(p) { abs(p.x) + abs(p.y) + abs(p.z) }, threshold: 1, radius: 1.2, center: [0, 0, 0], accuracy: 0.0005, open: true)",
]);
fn isosurface(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &ISOSURFACE, a)?;
    let (f, fs) = p.req("f")?;
    let function = Arc::new(it.compile_pattern(f, fs)?);
    let box_given = p.given("min").or(p.given("max"));
    let (min, mins) = p.vec3(it, "min")?;
    let (max, maxs) = p.vec3(it, "max")?;
    let center = p.vec3_opt(it, "center")?;
    let radius = p.float_opt(it, "radius")?;
    let (container, spans) = match (radius, center, box_given) {
        (Some((_, rs)), _, Some(bs)) => {
            return Err(error(
                "rtc::isosurface::container",
                rs,
                "an isosurface's container is a box or a sphere, not both",
            )
            .with_label("a sphere's radius")
            .with_secondary(bs, "a box's corner")
            .with_help(
                "drop `radius` (and `center`) for the box, or `min` and `max` for the sphere",
            )
            .into());
        }
        (None, Some((_, cs)), _) => {
            return Err(error(
                "rtc::param::needs",
                cs,
                "`center` without `radius`: a container sphere needs both",
            )
            .with_label("the centre of no sphere")
            .with_help("add `radius: 1`, or drop `center` for the box `min`..`max`")
            .into());
        }
        (Some((radius, rs)), center, None) => (
            Container::Sphere {
                center: center.map_or(DVec3::ZERO, |c| c.0),
                radius,
            },
            [("radius", rs), ("center", center.map_or(rs, |c| c.1))],
        ),
        (None, None, _) => (Container::Box { min, max }, [("min", mins), ("max", maxs)]),
    };
    let (threshold, ts) = p.float(it, "threshold")?;
    let max_gradient = p.float_opt(it, "max_gradient")?;
    let (accuracy, acs) = p.float(it, "accuracy")?;
    let open = p.bool(it, "open")?;
    let gs = max_gradient.map_or(s.span, |g| g.1);
    let shape = Shape::Isosurface {
        function: function.clone(),
        container,
        threshold,
        max_gradient: max_gradient.map(|g| g.0),
        accuracy,
        open,
    };
    let value = checked(
        shape,
        s,
        &[
            spans[0],
            spans[1],
            ("threshold", ts),
            ("max_gradient", gs),
            ("accuracy", acs),
        ],
    )?;
    if let Some((given, span)) = max_gradient
        && let Some(slope) = sample_slope(&function, &container)
        && slope > given * 1.01
    {
        it.warn(too_small(given, slope, span));
    }
    Ok(value)
}

/// `rtc::isosurface::max_gradient`: a given bound below a slope the function was seen to have.
fn too_small(given: f64, slope: f64, span: crate::source::Span) -> Diagnostic {
    Diagnostic::warning(
        "rtc::isosurface::max_gradient",
        span,
        format!(
            "`max_gradient` {} is below the slope {} sampled in the container: the search may step over the surface",
            number(given),
            suggested(slope)
        ),
    )
    .with_label("too small for this function")
    .with_help(format!(
        "write `max_gradient: {}` ({SAFETY} times the sampled slope), or leave it out for rtc to estimate it",
        suggested(SAFETY * slope)
    ))
}
