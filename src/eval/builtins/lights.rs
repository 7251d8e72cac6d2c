//! The light constructors: point, area, spot, parallel and cylinder lights, each with the modifiers every
//! light takes (fading with distance, shadows or none), after POV-Ray 3.7's `light_source`.

use std::rc::Rc;

use glam::DVec3;

use crate::eval::args::Params;
use crate::eval::args::{ArgVal, CallSite};
use crate::eval::error::{R, error};
use crate::eval::host::BuiltinFn;
use crate::eval::host::Host;
use crate::eval::schema::{Group, Lit, Param, Range, Sig, Ty, Unit};
use crate::eval::types;
use crate::eval::value::{LightVal, Value};
use crate::ir;
use crate::ir::limits::MAX_LIGHT_SAMPLES_PER_AXIS;
use crate::num::Norm;
use crate::source::Span;

/// The light constructors with their schemas.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[
    (&POINT_LIGHT, point_light),
    (&AREA_LIGHT, area_light),
    (&SPOT_LIGHT, spot_light),
    (&PARALLEL_LIGHT, parallel_light),
    (&CYLINDER_LIGHT, cylinder_light),
];

/// A light's intensity.
const LIGHT_COLOR: Param = Param::new(
    "color",
    Ty::Color,
    "the light's RGB intensity (may exceed 1)",
)
.or(Lit::Color([1.0, 1.0, 1.0]));

/// `point_light { position, color }`.
static POINT_LIGHT: Sig = Sig::new(
    "point_light",
    Group::Light,
    "A point light.",
    &[
        Param::new("position", Ty::Vec3, "where the light is").unit(Unit::Length),
        LIGHT_COLOR,
        FADE_DISTANCE,
        FADE_POWER,
        SHADOWS,
        LOOKS_LIKE,
    ],
    "Light",
)
.examples(&["point_light { position: [5, 8, 5], color: rgb(1, 0.95, 0.9) }"]);
fn point_light(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &POINT_LIGHT, a)?;
    let (position, _) = p.vec3(it, "position")?;
    let (color, _) = p.color(it, "color")?;
    let kind = ir::LightKind::Point { position };
    shaped(it, &mut p, kind, color, s)
}

/// `area_light { corner, u, v, samples, color }`.
static AREA_LIGHT: Sig = Sig::new(
    "area_light",
    Group::Light,
    "The parallelogram `corner + s·u + t·v`, sampled on a stratified grid: soft shadows.",
    &[
        Param::new("corner", Ty::Vec3, "one corner").unit(Unit::Length),
        Param::new("u", Ty::Vec3, "one edge").unit(Unit::Length),
        Param::new("v", Ty::Vec3, "the other edge (u × v ≠ 0)").unit(Unit::Length),
        Param::new(
            "samples",
            Ty::OneOf(&[Ty::Pair(&Ty::Int), Ty::Int]),
            "the grid, `[n, m]` or `n` (n × n)",
        )
        .unit(Unit::Samples)
        .range(Range::Ints(1, MAX_LIGHT_SAMPLES_PER_AXIS as i64))
        .or(Lit::Ints([4, 4])),
        Param::new("circular", Ty::Bool, "the light is the ellipse inscribed in the parallelogram, not the parallelogram (POV-Ray's `circular`)")
            .or(Lit::Bool(false)),
        Param::new("orient", Ty::Bool, "a circular light turns to face each point it lights, both radii `|u| / 2` (POV-Ray's `orient`: a round light seen from anywhere, e.g. a sphere's glow)")
            .or(Lit::Bool(false)),
        LIGHT_COLOR,
        FADE_DISTANCE,
        FADE_POWER,
        SHADOWS,
        LOOKS_LIKE,
    ],
    "Light",
)
.examples(&["area_light { corner: [-1, 6, -1], u: [2, 0, 0], v: [0, 0, 2], samples: [3, 3], color: rgb(0.4, 0.4, 0.5) }", "area_light { corner: [-1, 6, -1], u: [2, 0, 0], v: [0, 0, 2], samples: 5, circular: true, orient: true }"]);
fn area_light(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &AREA_LIGHT, a)?;
    let (corner, _) = p.vec3(it, "corner")?;
    let (u, _) = p.vec3(it, "u")?;
    let (v, vs) = p.vec3(it, "v")?;
    if u.cross(v).length_squared() == 0.0 {
        return Err(
            error("rtc::light::degenerate", vs, "the area light has zero area")
                .with_label("`u` and `v` are parallel or zero")
                .with_help(
                    "use two edges that span a parallelogram, e.g. `u: [1, 0, 0], v: [0, 0, 1]`",
                )
                .into(),
        );
    }
    let samples = match p.get("samples") {
        None => p.default_ints("samples").map(|n| n as u32),
        Some((Value::List(l), sp)) if l.len() == 2 => [
            p.int_in(it, "samples", &l[0], sp)? as u32,
            p.int_in(it, "samples", &l[1], sp)? as u32,
        ],
        Some((n @ Value::Int(_), sp)) => [p.int_in(it, "samples", &n, sp)? as u32; 2],
        Some((other, sp)) => {
            return Err(error(
                "rtc::type::mismatch",
                sp,
                format!("expected `[n, m]`, found `{}`", other.type_name()),
            )
            .with_label("not a sample count")
            .with_help("write `samples: [4, 4]`")
            .into());
        }
    };
    let circular = p.bool(it, "circular")?;
    let orient = p.bool(it, "orient")?;
    if orient && !circular {
        let at = p.given("orient").unwrap_or(s.span);
        return Err(error(
            "rtc::light::orient",
            at,
            "only a circular area light can be oriented",
        )
        .with_label("this area light is a parallelogram")
        .with_help("add `circular: true` (the light becomes a disk facing each point it lights), or remove `orient`")
        .into());
    }
    let (color, _) = p.color(it, "color")?;
    let kind = ir::LightKind::Area {
        corner,
        u,
        v,
        samples,
        circular,
        orient,
    };
    shaped(it, &mut p, kind, color, s)
}

/// Where a light fades (`fade_distance`).
const FADE_DISTANCE: Param = Param::new(
    "fade_distance",
    Ty::Float,
    "the distance at which the light has its colour: `2 / (1 + (d / fade_distance)^fade_power)` of it at distance d (no fading when absent)",
)
.unit(Unit::Length)
.range(Range::Positive)
.optional();

/// How a light fades (`fade_power`).
const FADE_POWER: Param = Param::new(
    "fade_power",
    Ty::Float,
    "how fast it fades beyond `fade_distance`: 1 linear, 2 the inverse square",
)
.range(Range::Positive)
.or(Lit::Float(2.0));

/// Whether a light casts shadows.
const SHADOWS: Param = Param::new(
    "shadows",
    Ty::Bool,
    "whether objects cast shadows from it (`false`: a fill light, POV-Ray's `shadowless`)",
)
.or(Lit::Bool(true));

/// The object that shows a light.
const LOOKS_LIKE: Param = Param::new(
    "looks_like",
    Ty::Object,
    "an object drawn at the light's centre (made about the origin), which casts no shadow: the bulb of a lamp (POV-Ray's `looks_like`)",
)
.optional();

/// A light of `kind` and `color` with the modifiers every light at a place takes, read from
/// `p`: fading, shadows and the object that shows it.
fn shaped(
    it: &mut dyn Host,
    p: &mut Params,
    kind: ir::LightKind,
    color: DVec3,
    s: CallSite,
) -> R<Value> {
    let mut light = ir::Light::new(kind, color, s.span);
    let power_given = p.given("fade_power");
    let (power, _) = p.float(it, "fade_power")?;
    match p.float_opt(it, "fade_distance")? {
        Some((distance, _)) => light.fade = Some(ir::Fade { distance, power }),
        None => {
            if let Some(sp) = power_given {
                return Err(error(
                    "rtc::light::fade",
                    sp,
                    "`fade_power` without a `fade_distance`",
                )
                .with_label("this light does not fade")
                .with_help("add `fade_distance: 10` (where the light has its colour), or remove `fade_power`")
                .into());
            }
        }
    }
    light.shadows = p.bool(it, "shadows")?;
    let looks_like = match p.get("looks_like") {
        None => None,
        Some((Value::Object(o), _)) => Some((*o).clone()),
        Some((other, sp)) => return Err(types::mismatch(it, "Object", &other, sp).into()),
    };
    Ok(Value::Light(Rc::new(LightVal { light, looks_like })))
}

/// `spot_light { position, target, radius, falloff, tightness, color, .. }`.
static SPOT_LIGHT: Sig = Sig::new(
    "spot_light",
    Group::Light,
    "A spot light: a point light shining in a cone from `position` towards `target` (POV-Ray's `spotlight`).",
    &[
        Param::new("position", Ty::Vec3, "where the light is").unit(Unit::Length),
        Param::new("target", Ty::Vec3, "the point the cone's axis goes through (not `position`)")
            .unit(Unit::Length),
        Param::new("radius", Ty::Angle, "the half-angle of full strength")
            .unit(Unit::Angle)
            .range(Range::Open(0.0, std::f64::consts::FRAC_PI_2))
            .or(Lit::Degrees(30.0)),
        Param::new("falloff", Ty::Angle, "the half-angle where the light ends (≥ `radius`), reached along a smoothstep of the cosine")
            .unit(Unit::Angle)
            .range(Range::Open(0.0, std::f64::consts::FRAC_PI_2))
            .or(Lit::Degrees(45.0)),
        Param::new("tightness", Ty::Float, "the exponent of the angle's cosine over the whole cone (0: none)")
            .range(Range::NonNegative)
            .or(Lit::Float(0.0)),
        LIGHT_COLOR,
        FADE_DISTANCE,
        FADE_POWER,
        SHADOWS,
        LOOKS_LIKE,
    ],
    "Light",
)
.examples(&["spot_light { position: [0, 8, 0], target: [0, 0, 0], radius: 15deg, falloff: 25deg }"]);
fn spot_light(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &SPOT_LIGHT, a)?;
    let (position, target, axis) = aim(it, &mut p, "spot")?;
    let (radius, _) = p.angle(it, "radius")?;
    let (falloff, fs) = p.angle(it, "falloff")?;
    ends_outside(radius, falloff, fs, "spot", "radius: 20deg, falloff: 30deg")?;
    let (tightness, _) = p.float(it, "tightness")?;
    let (color, _) = p.color(it, "color")?;
    let spot = ir::Spot {
        target,
        axis,
        radius,
        falloff,
        tightness,
    };
    let mut made = shaped(it, &mut p, ir::LightKind::Point { position }, color, s)?;
    if let Value::Light(l) = &mut made {
        Rc::make_mut(l).light.spot = Some(spot);
    }
    Ok(made)
}

/// `parallel_light { direction, color, .. }`.
static PARALLEL_LIGHT: Sig = Sig::new(
    "parallel_light",
    Group::Light,
    "A parallel light (a sun): light travelling along `direction` everywhere, from infinitely far away.",
    &[
        Param::new("direction", Ty::Vec3, "the direction the light travels in, e.g. `[-1, -2, -1]` (down and away)")
            .range(Range::NonZero),
        LIGHT_COLOR,
        SHADOWS,
    ],
    "Light",
)
.examples(&["parallel_light { direction: [-1, -2, -1], color: rgb(1, 0.95, 0.85) }"]);
fn parallel_light(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &PARALLEL_LIGHT, a)?;
    let (written, ds) = p.vec3(it, "direction")?;
    let Some(direction) = written.try_unit() else {
        return Err(
            error("rtc::light::aim", ds, "the parallel light has no direction")
                .with_label("a zero vector")
                .with_help("give the direction the light travels in, e.g. `direction: [0, -1, 0]`")
                .into(),
        );
    };
    // A direction of unit length to rounding is kept bit for bit: normalising it again would
    // move its last bits, and `rtc convert` writes the unit direction back out.
    let direction = if (written.length_squared() - 1.0).abs() <= 4.0 * f64::EPSILON {
        written
    } else {
        direction
    };
    let (color, _) = p.color(it, "color")?;
    let mut light = ir::Light::new(ir::LightKind::Parallel { direction }, color, s.span);
    light.shadows = p.bool(it, "shadows")?;
    Ok(Value::Light(Rc::new(LightVal {
        light,
        looks_like: None,
    })))
}

/// `cylinder_light { position, target, radius, falloff, tightness, color, .. }`.
static CYLINDER_LIGHT: Sig = Sig::new(
    "cylinder_light",
    Group::Light,
    "A cylinder light: parallel beams from the plane through `position` towards `target`, within a cylinder about that axis (POV-Ray's `cylinder` light, a laser or a shaft of light).",
    &[
        Param::new("position", Ty::Vec3, "a point on the axis, where the light starts").unit(Unit::Length),
        Param::new("target", Ty::Vec3, "the point the axis goes through (not `position`)")
            .unit(Unit::Length),
        Param::new("radius", Ty::Float, "the distance from the axis within which the light has full strength")
            .unit(Unit::Length)
            .range(Range::Positive)
            .or(Lit::Float(0.75)),
        Param::new("falloff", Ty::Float, "the distance from the axis where the light ends (≥ `radius`), reached along a smoothstep")
            .unit(Unit::Length)
            .range(Range::Positive)
            .or(Lit::Float(1.0)),
        Param::new("tightness", Ty::Float, "the exponent of `1 − distance / falloff` over the whole beam (0: none)")
            .range(Range::NonNegative)
            .or(Lit::Float(0.0)),
        LIGHT_COLOR,
        FADE_DISTANCE,
        FADE_POWER,
        SHADOWS,
        LOOKS_LIKE,
    ],
    "Light",
)
.examples(&["cylinder_light { position: [0, 10, 0], target: [0, 0, 0], radius: 0.5, falloff: 0.8 }"]);
fn cylinder_light(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &CYLINDER_LIGHT, a)?;
    let (position, target, axis) = aim(it, &mut p, "cylinder")?;
    let (radius, _) = p.float(it, "radius")?;
    let (falloff, fs) = p.float(it, "falloff")?;
    ends_outside(radius, falloff, fs, "cylinder", "radius: 0.5, falloff: 0.8")?;
    let (tightness, _) = p.float(it, "tightness")?;
    let (color, _) = p.color(it, "color")?;
    let kind = ir::LightKind::Cylinder {
        position,
        target,
        axis,
        radius,
        falloff,
        tightness,
    };
    shaped(it, &mut p, kind, color, s)
}

/// A beam light's `position`, `target` and the unit axis between them; `rtc::light::aim` when
/// they coincide (`what` names the light: "spot", "cylinder").
fn aim(it: &mut dyn Host, p: &mut Params, what: &str) -> R<(DVec3, DVec3, DVec3)> {
    let (position, _) = p.vec3(it, "position")?;
    let (target, ts) = p.vec3(it, "target")?;
    let Some(axis) = (target - position).try_unit() else {
        return Err(error(
            "rtc::light::aim",
            ts,
            format!("the {what} light is aimed at itself"),
        )
        .with_label("`target` is the light's `position`")
        .with_help("aim it at a point away from the light, e.g. `target: [0, 0, 0]`")
        .into());
    };
    Ok((position, target, axis))
}

/// `rtc::light::falloff` (at `fs`) when a beam's `falloff` is inside its `radius`; `example`
/// is a fix that works.
fn ends_outside(radius: f64, falloff: f64, fs: Span, what: &str, example: &str) -> R<()> {
    if falloff >= radius {
        return Ok(());
    }
    Err(error(
        "rtc::light::falloff",
        fs,
        format!("the {what} light's `falloff` is inside its `radius`"),
    )
    .with_label("the light would end before its full-strength part does")
    .with_help(format!(
        "make `falloff` at least `radius`, e.g. `{example}`"
    ))
    .into())
}
