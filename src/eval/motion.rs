//! Motion in the language: `obj.moving(translate:, rotate:, scale:)`, the camera's `shutter:`,
//! `eye_close:` and `center_close:`, and `obj.look_at(target)` / `look_at(from:, to:, up:)`.

use crate::num::Norm;
use std::rc::Rc;

use glam::{DAffine3, DMat3, DQuat, DVec3};

use super::args::{ArgVal, CallSite};
use super::args::{Params, check_shown};
use super::error::{R, error};
use super::host::Host;
use super::schema::{Group, Lit, Param, Range, Sig, Ty, Unit};
use super::types;
use super::value::{Obj, ObjShape, Value};
use crate::diag::Diagnostic;
use crate::ir::{self, Motion};
use crate::source::Span;

/// `.moving(..)`'s parameters.
pub(crate) static MOVING: Sig = Sig::new(
    "moving",
    Group::Method,
    "The object moving while the shutter is open, to where these changes put it at close.",
    &[
        Param::new("translate", Ty::Vec3, "the move")
            .unit(Unit::Length)
            .or(Lit::Vec3([0.0, 0.0, 0.0])),
        Param::new(
            "rotate",
            Ty::Transform,
            "a rotation about the origin (the shorter arc)",
        )
        .optional(),
        Param::new(
            "scale",
            Ty::OneOf(&[Ty::Float, Ty::Vec3]),
            "factors (> 0 in every axis)",
        )
        .range(Range::Positive)
        .checked_by_builtin()
        .or(Lit::Float(1.0)),
        Param::new(
            "spin",
            Ty::Angle,
            "a turn about `axis` by any angle (needs `axis`)",
        )
        .unit(Unit::Angle)
        .optional(),
        Param::new(
            "axis",
            Ty::Vec3,
            "the axis of `spin`, through the origin (needs `spin`)",
        )
        .range(Range::NonZero)
        .checked_by_builtin()
        .optional(),
    ],
    "Object",
)
.examples(&[
    "sphere().moving(translate: [1, 0, 0], rotate: rotate(y: 45deg), scale: 1.2)",
    "box().moving(spin: 720deg, axis: Y)",
]);

/// `obj.moving(translate:, rotate:, scale:, spin:, axis:)`: the change of the object's
/// placement from shutter open to shutter close, applied after its placement (as a
/// `.translate(...)` would be); `spin:` turns it about `axis:` by any angle, whole turns too.
pub(crate) fn moving(
    it: &mut dyn Host,
    mut o: Rc<Obj>,
    site: CallSite,
    args: Vec<ArgVal>,
) -> R<Value> {
    let mut p = Params::new(site, &MOVING, args)?;
    let (translate, _) = p.vec3(it, "translate")?;
    let rotate = match p.get("rotate") {
        None => DQuat::IDENTITY,
        Some((v, sp)) => {
            let q = rotation(it, &v, sp)?;
            if let Some(deg) = written_turn(it.snippet(sp)) {
                it.warn(
                    Diagnostic::warning(
                        "rtc::motion::short_arc",
                        sp,
                        format!(
                            "a motion turns by at most half a turn: {}° is turned the shorter way, by {}°",
                            super::value::fmt_f(deg),
                            super::value::fmt_f(short_arc(deg))
                        ),
                    )
                    .with_label("the rotation at shutter close; the motion takes the shorter arc to it")
                    .with_help("for a turn of more than 180deg, spin about an axis: `.moving(spin: 270deg, axis: Z)`"),
                );
            }
            q
        }
    };
    let scale = match p.get("scale") {
        None => DVec3::ONE,
        Some((v, sp)) => {
            let s = match v.as_f64() {
                Some(x) => DVec3::splat(x),
                None => types::vec3(it, &v, sp)?,
            };
            let shown = format!("[{}, {}, {}]", s.x, s.y, s.z);
            check_shown(
                s.min_element() > 0.0 && s.is_finite(),
                "scale",
                "> 0 in every axis",
                &shown,
                sp,
            )?;
            s
        }
    };
    let spin = spin(it, &mut p)?;
    if let Some(inner) = already_moving(&o) {
        let mut d = error(
            "rtc::motion::nested",
            site.span,
            "this object already moves",
        )
        .with_label("a second motion")
        .with_help("give the object one `.moving(...)` with the whole change (translate, rotate and scale together)");
        if inner != o.span {
            d = d.with_secondary(inner, "this member moves on its own");
        }
        return Err(d.into());
    }
    let o2 = Rc::make_mut(&mut o);
    let motion = Motion::new(translate, rotate, scale);
    o2.motion = Some(match spin {
        Some((axis, angle)) => motion.with_spin(axis, angle),
        None => motion,
    });
    o2.origin = it.derive(o2.origin);
    Ok(Value::Object(o))
}

/// `spin:` and `axis:` of `.moving`: the axis and the angle (radians, any size), or `None`
/// without a spin. Each needs the other; the axis must not be zero.
fn spin(it: &dyn Host, p: &mut Params) -> R<Option<(DVec3, f64)>> {
    let angle = p.get("spin");
    let axis = p.get("axis");
    match (angle, axis) {
        (None, None) => Ok(None),
        (Some((a, sp)), Some((x, xs))) => {
            let angle = types::angle(it, &a, sp)?;
            let axis = types::vec3(it, &x, xs)?;
            let shown = format!("[{}, {}, {}]", axis.x, axis.y, axis.z);
            check_shown(axis.norm() > 0.0 && axis.is_finite(), "axis", "a direction (not zero)", &shown, xs)?;
            check_shown(angle.is_finite(), "spin", "a finite angle", &format!("{angle}"), sp)?;
            Ok(Some((axis, angle)))
        }
        (Some((_, sp)), None) => Err(error("rtc::motion::spin_axis", sp, "a spin needs an axis")
            .with_label("no `axis:` to turn about")
            .with_help("add the axis it turns about, e.g. `.moving(spin: 720deg, axis: Y)`")
            .into()),
        (None, Some((_, xs))) => Err(error("rtc::motion::spin_axis", xs, "an axis without a spin")
            .with_label("nothing turns about this axis")
            .with_help("say how far it turns, e.g. `.moving(spin: 720deg, axis: Y)`, or remove `axis:`")
            .into()),
    }
}

/// The span of the object itself, or of a member of its group, that already has a motion. CSG
/// operands may move inside a moving CSG node (each level moves rays by its own motion); a
/// group is flattened, so its members cannot.
fn already_moving(o: &Obj) -> Option<Span> {
    if o.motion.is_some() {
        return Some(o.span);
    }
    match &o.shape {
        ObjShape::Group(ch) => ch.iter().find_map(already_moving),
        _ => None,
    }
}

/// The largest angle, in degrees, written in the text of a `rotate:` argument when it is more
/// than half a turn (`rotate(z: 270deg)`, `0.75turn`): the motion cannot take that arc.
fn written_turn(text: &str) -> Option<f64> {
    let b = text.as_bytes();
    let mut best: Option<f64> = None;
    let mut i = 0;
    while i < b.len() {
        let starts = b[i].is_ascii_digit()
            && (i == 0
                || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'.' || b[i - 1] == b'_'));
        if !starts {
            i += 1;
            continue;
        }
        let end = (i..b.len())
            .find(|&j| !(b[j].is_ascii_digit() || b[j] == b'.'))
            .unwrap_or(b.len());
        let value: f64 = text[i..end].parse().unwrap_or(0.0);
        let unit = &text[end..];
        let deg = if unit.starts_with("deg") || unit.starts_with('°') {
            value
        } else if unit.starts_with("turn") {
            value * 360.0
        } else if unit.starts_with("rad") {
            value.to_degrees()
        } else {
            0.0
        };
        if deg > 180.0 && best.is_none_or(|b| deg > b) {
            best = Some(deg);
        }
        i = end;
    }
    best
}

/// The signed angle, in degrees, the shorter arc turns for a written `deg` (270 → −90).
fn short_arc(deg: f64) -> f64 {
    let r = deg.rem_euclid(360.0);
    if r > 180.0 { r - 360.0 } else { r }
}

/// A rotation transform (`rotate(y: 90deg)`) as a unit quaternion.
fn rotation(it: &dyn Host, v: &Value, sp: Span) -> R<DQuat> {
    if let Value::Angle(a) = v {
        // `moving(rotate: 45deg)`: an angle alone names no axis.
        let deg = super::value::fmt_f(a.to_degrees());
        return Err(types::mismatch(it, "Transform", v, sp)
            .with_help(format!(
                "an angle alone has no axis: write `rotate: rotate(y: {deg}deg)` (or `x:`, `z:`)"
            ))
            .into());
    }
    let Value::Transform(t) = v else {
        return Err(types::mismatch(it, "Transform", v, sp).into());
    };
    let m = t.matrix3;
    let orthonormal = (m.transpose() * m - DMat3::IDENTITY)
        .to_cols_array()
        .iter()
        .all(|x| x.abs() < 1e-9);
    if !orthonormal || m.determinant() <= 0.0 || t.translation.norm() > 1e-9 {
        return Err(error(
            "rtc::motion::not_rotation",
            sp,
            "`rotate:` must be a rotation about the origin",
        )
        .with_label("this transform scales, shears, mirrors or moves")
        .with_help("write the rotation alone, e.g. `rotate: rotate(y: 90deg)`; put moves in `translate:` and sizes in `scale:`")
        .into());
    }
    Ok(DQuat::from_mat3(&m).normalize())
}

/// The camera's `shutter: [open, close]` (fractions of a frame, 0 ≤ open ≤ close ≤ 1).
pub(crate) fn shutter(p: &mut Params) -> R<Option<ir::Shutter>> {
    let Some((v, sp)) = p.get("shutter") else {
        return Ok(None);
    };
    let pair = match &v {
        Value::List(l) if l.len() == 2 => Some((l[0].as_f64(), l[1].as_f64())),
        _ => None,
    };
    let Some((Some(open), Some(close))) = pair else {
        return Err(error(
            "rtc::type::mismatch",
            sp,
            format!("expected `[open, close]`, found `{}`", v.type_name()),
        )
        .with_label("not a pair of numbers")
        .with_help("write `shutter: [0, 0.5]` (fractions of a frame)")
        .into());
    };
    if close < open {
        return Err(error(
            "rtc::camera::shutter",
            sp,
            format!("the shutter closes ({close}) before it opens ({open})"),
        )
        .with_label("`close` is less than `open`")
        .with_help(format!("swap them: `shutter: [{close}, {open}]`"))
        .into());
    }
    let shown = format!("[{open}, {close}]");
    check_shown(
        open >= 0.0 && close <= 1.0,
        "shutter",
        "within [0, 1] (fractions of a frame)",
        &shown,
        sp,
    )?;
    Ok(Some(ir::Shutter { open, close }))
}

/// `eye_close:` and `center_close:`: where the camera is and looks when the shutter closes.
pub(crate) fn camera_motion(
    it: &dyn Host,
    p: &mut Params,
    eye: DVec3,
    center: DVec3,
    up: DVec3,
) -> R<Option<ir::CameraMotion>> {
    let eye_arg = p.vec3_opt(it, "eye_close")?;
    let center_arg = p.vec3_opt(it, "center_close")?;
    let span = eye_arg.or(center_arg).map(|(_, s)| s);
    let Some(span) = span else {
        return Ok(None);
    };
    let m = ir::CameraMotion {
        eye: eye_arg.map_or(eye, |(v, _)| v),
        center: center_arg.map_or(center, |(v, _)| v),
    };
    let view = m.center - m.eye;
    if view.length_squared() == 0.0
        || up.cross(view).length_squared() <= 1e-12 * up.length_squared() * view.length_squared()
    {
        return Err(error(
            "rtc::camera::degenerate",
            span,
            "at shutter close the camera looks at itself or along `up`",
        )
        .with_label("the view at shutter close")
        .with_help("keep `center_close` away from `eye_close` and off the `up` line through it")
        .into());
    }
    Ok((m.eye != eye || m.center != center).then_some(m))
}

/// `look_at(from:, to:, up:)`'s parameters.
pub(crate) static LOOK_AT: Sig = Sig::new(
    "look_at",
    Group::Transform,
    "Places an object made at the origin at `from`, its +Z axis towards `to`, +Y towards `up`.",
    &[
        Param::new("from", Ty::Vec3, "where the origin goes")
            .unit(Unit::Length)
            .or(Lit::Vec3([0.0, 0.0, 0.0])),
        TO,
        UP,
    ],
    "Transform",
)
.examples(&["look_at(from: [2, 0, 0], to: [2, 3, 0], up: Z)"]);
/// The point `look_at` turns +Z towards.
const TO: Param = Param::new("to", Ty::Vec3, "the point +Z turns towards").unit(Unit::Length);
/// Where `look_at` turns +Y.
const UP: Param =
    Param::new("up", Ty::Vec3, "+Y turns as close to it as it can").or(Lit::Vec3([0.0, 1.0, 0.0]));
/// `look_at(from:, to:, up:)`: places an object made at the origin at `from`, its +Z axis
/// turned towards `to` and its +Y axis towards `up`.
pub(crate) fn look_at_fn(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &LOOK_AT, a)?;
    let (from, _) = p.vec3(it, "from")?;
    let (to, ts) = p.vec3(it, "to")?;
    let (up, _) = p.vec3(it, "up")?;
    let r = aim(to - from, up, ts)?;
    Ok(Value::Transform(Rc::new(
        DAffine3::from_translation(from) * r,
    )))
}

/// `.look_at(to, up)`'s parameters.
pub(crate) static LOOK_AT_METHOD: Sig = Sig::new(
    "look_at",
    Group::Method,
    "The object turned about its own origin so that its +Z axis points at `to`.",
    &[TO, UP],
    "Object",
)
.examples(&["cone(base_radius: 0.2).look_at(to: [0, 0, 10], up: Y)"]);

/// `obj.look_at(to, up:)`: turns the object about its own origin so that what was its +Z axis
/// points at `to` (and +Y towards `up`).
pub(crate) fn look_at_method(
    it: &mut dyn Host,
    site: CallSite,
    args: Vec<ArgVal>,
) -> R<(DVec3, DVec3, Span)> {
    let mut p = Params::new(site, &LOOK_AT_METHOD, args)?;
    let (to, ts) = p.vec3(it, "to")?;
    let (up, _) = p.vec3(it, "up")?;
    Ok((to, up, ts))
}

/// The transform `obj.look_at(to, up)` applies to an object whose origin is at `origin`.
pub(crate) fn look_at_about(origin: DVec3, to: DVec3, up: DVec3, span: Span) -> R<DAffine3> {
    let r = aim(to - origin, up, span)?;
    Ok(DAffine3::from_translation(origin) * r * DAffine3::from_translation(-origin))
}

/// The rotation taking +Z to `dir` and +Y as close to `up` as it can.
fn aim(dir: DVec3, up: DVec3, span: Span) -> R<DAffine3> {
    let z = dir.unit_or(Default::default());
    let x = up.cross(z).unit_or(Default::default());
    if z == DVec3::ZERO || x == DVec3::ZERO || !x.is_finite() {
        return Err(error(
            "rtc::param::degenerate",
            span,
            "`look_at` has no direction to turn to",
        )
        .with_label("the target is at the object's origin, or straight along `up`")
        .with_help("move the target away from the origin, or pass another `up:` (e.g. `up: Z`)")
        .into());
    }
    let y = z.cross(x);
    Ok(DAffine3::from_mat3(DMat3::from_cols(x, y, z)))
}
