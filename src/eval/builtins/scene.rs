//! The camera and the lights.

use crate::num::Norm;
use std::rc::Rc;

use crate::eval::args::Params;
use crate::eval::args::{ArgVal, CallSite};
use crate::eval::error::{R, error};
use crate::eval::host::BuiltinFn;
use crate::eval::host::Host;
use crate::eval::schema::{Group, Lit, Param, Range, Sig, Ty, Unit};
use crate::eval::value::Value;
use crate::ir;
use crate::ir::limits::MAX_IMAGE_SIDE;

/// The camera constructor with its schema.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[(&CAMERA, camera)];

/// `camera { .. }`'s fields, in positional order.
static CAMERA: Sig = Sig::new(
    "camera",
    Group::Camera,
    "A pinhole or thin-lens camera; a scene needs exactly one.",
    &[
        Param::new("eye", Ty::Vec3, "where the camera is (not at `center`)").unit(Unit::Length),
        Param::new("center", Ty::Vec3, "the point looked at")
            .unit(Unit::Length)
            .or(Lit::Vec3([0.0, 0.0, 0.0])),
        Param::new("up", Ty::Vec3, "up on the image (not along `center - eye`)")
            .or(Lit::Vec3([0.0, 1.0, 0.0])),
        Param::new(
            "fov",
            Ty::Angle,
            "the vertical field of view; a fisheye's angle across its circle (default 180deg) or a cylinder's across the image (default 360deg), up to 360deg",
        )
        .unit(Unit::Angle)
        .range(Range::Open(0.0, std::f64::consts::PI))
        .checked_by_builtin()
        .or(Lit::Degrees(40.0)),
        Param::new(
            "resolution",
            Ty::Pair(&Ty::Int),
            "width and height of the image",
        )
        .unit(Unit::Pixels)
        .range(Range::Ints(1, MAX_IMAGE_SIDE as i64))
        .or(Lit::Ints([640, 480])),
        Param::new("aperture", Ty::Float, "the lens radius (0: a pinhole)")
            .unit(Unit::Length)
            .range(Range::NonNegative)
            .or(Lit::Float(0.0)),
        Param::new(
            "focus",
            Ty::Float,
            "the distance that is sharp when `aperture > 0`",
        )
        .unit(Unit::Length)
        .range(Range::Positive)
        .computed("distance(eye, center)"),
        Param::new(
            "shutter",
            Ty::Pair(&Ty::Float),
            "`[open, close]`: when the shutter is open",
        )
        .unit(Unit::Frame)
        .range(Range::UnitInterval)
        .checked_by_builtin()
        .optional(),
        Param::new(
            "eye_close",
            Ty::Vec3,
            "where the eye is when the shutter closes",
        )
        .unit(Unit::Length)
        .computed("eye"),
        Param::new(
            "center_close",
            Ty::Vec3,
            "what it looks at when the shutter closes",
        )
        .unit(Unit::Length)
        .computed("center"),
        Param::new(
            "course",
            Ty::Bool,
            "the course camera: a pixel at `center` is |up| wide",
        )
        .or(Lit::Bool(false)),
        Param::new(
            "projection",
            Ty::String,
            "\"perspective\", \"orthographic\", \"equirectangular\", \"fisheye\" or \"cylindrical\"",
        )
        .checked_by_builtin()
        .or(Lit::Name("\"perspective\"")),
        Param::new(
            "height",
            Ty::Float,
            "the orthographic view's height (the width follows the image's shape)",
        )
        .unit(Unit::Length)
        .range(Range::Positive)
        .checked_by_builtin()
        .computed("2 * distance(eye, center) * tan(fov / 2)"),
    ],
    "Camera",
)
.examples(&["camera { eye: [0, 2, 8], center: [0, 1, 0], up: Y, fov: 40deg, resolution: [640, 480], aperture: 0.05, focus: 7 }", "camera { eye: [0, 2, 8], shutter: [0, 0.5], eye_close: [0.2, 2, 8], center_close: [0, 1, 0] }", "camera { eye: [200, 200, 1000], center: [200, 200, 0], up: [0, 2, 0], course: true }", "camera { eye: [0, 2, 8], center: [0, 1, 0], projection: \"orthographic\", height: 4 }", "camera { eye: [0, 1, 0], center: [0, 1, -1], projection: \"equirectangular\", resolution: [720, 360] }", "camera { eye: [0, 1, 0], center: [0, 2, 0], up: Z, projection: \"fisheye\", fov: 180deg, resolution: [480, 480] }"]);
fn camera(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &CAMERA, a)?;
    let (eye, es) = p.vec3(it, "eye")?;
    let (center, _) = p.vec3(it, "center")?;
    // `course: true` is the course camera (COURSE.md §2.4), |up| = the pixel size at `center`:
    // what `rtc convert` writes where no field of view gives that pixel to the last bit.
    let course = p.bool(it, "course")?;
    if course && let Some(fs) = p.given("fov") {
        return Err(error(
            "rtc::camera::conflict",
            fs,
            "`fov` and `course: true` both size the view",
        )
        .with_label("not used by the course camera")
        .with_help("remove `fov`, or `course: true` to size the view by the field of view")
        .into());
    }
    // Which fields were written (read before the values are taken).
    let given = (p.given("fov").is_some(), p.given("aperture"));
    let (fov, fov_span) = p.angle(it, "fov")?;
    let (width, height) = match p.get("resolution") {
        None => p.default_ints("resolution").into(),
        Some((v, sp)) => match &v {
            Value::List(l) if l.len() == 2 => (
                p.int_in(it, "resolution", &l[0], sp)?,
                p.int_in(it, "resolution", &l[1], sp)?,
            ),
            _ => {
                return Err(error(
                    "rtc::type::mismatch",
                    sp,
                    format!("expected `[width, height]`, found `{}`", v.type_name()),
                )
                .with_label("not a pair of integers")
                .with_help("write `resolution: [640, 480]`")
                .into());
            }
        },
    };
    let (aperture, _) = p.float(it, "aperture")?;
    let view = center - eye;
    if view.length_squared() == 0.0 {
        return Err(error(
            "rtc::camera::degenerate",
            es,
            "the camera's `eye` equals its `center`",
        )
        .with_label("looks at itself")
        .with_help("move `center` to the point the camera should look at")
        .into());
    }
    let (up, us) = p.vec3(it, "up")?;
    if up.cross(view).length_squared() <= 1e-12 * up.length_squared() * view.length_squared() {
        return Err(error(
            "rtc::camera::degenerate",
            us,
            "`up` is parallel to the view direction",
        )
        .with_label("no way to tell up from down")
        .with_help("use an `up` that is not along `center - eye`, e.g. `up: Y` or `up: Z`")
        .into());
    }
    let focus = match p.float_opt(it, "focus")? {
        Some((f, _)) => f,
        None => {
            let d = view.norm();
            p.in_range("focus", d, s.span)?;
            d
        }
    };
    let projection = super::projection::projection(
        it,
        &mut p,
        course,
        (fov, fov_span),
        view,
        (aperture, given),
    )?;
    let shutter = crate::eval::motion::shutter(&mut p)?;
    let motion = crate::eval::motion::camera_motion(it, &mut p, eye, center, up)?;
    Ok(Value::Camera(Rc::new(ir::Camera {
        eye,
        center,
        up,
        width: width as u32,
        height: height as u32,
        projection,
        aperture,
        focus_distance: focus,
        shutter,
        motion,
        span: s.span,
    })))
}
