//! Camera, lights, render settings and the small enumerations they use.

use crate::num::Norm;
use std::rc::Rc;

use glam::DVec3;

use crate::eval::args::{ArgVal, CallSite};
use crate::eval::args::{Params, check, positive, unit_interval};
use crate::eval::error::{R, error};
use crate::eval::host::BuiltinFn;
use crate::eval::host::Host;
use crate::eval::types;
use crate::eval::value::{RenderVal, Value};
use crate::ir;
use crate::ir::limits::{
    MAX_DEPTH, MAX_IMAGE_SIDE, MAX_LIGHT_SAMPLES_PER_AXIS, MAX_PIXEL_SAMPLES_PER_AXIS,
};
use crate::source::Span;

/// Scene-level constructors.
pub const FNS: &[(&str, BuiltinFn)] = &[
    ("camera", camera),
    ("point_light", point_light),
    ("area_light", area_light),
    ("render", render),
    ("gooch", gooch),
    ("adaptive", adaptive),
    ("depth", depth),
    ("flare", flare),
];

/// Named enumeration values.
pub fn constants() -> Vec<(&'static str, Value)> {
    let modes = ir::RenderMode::NAMED
        .iter()
        .map(|(name, mode)| (*name, Value::Mode(*mode)));
    vec![
        ("phong", Value::Shading(ir::ShadingModel::Phong)),
        ("hatching", Value::Shading(ir::ShadingModel::Hatching)),
        ("per_light", Value::Ambient(ir::AmbientConvention::PerLight)),
        ("once", Value::Ambient(ir::AmbientConvention::Once)),
        ("linear", Value::Encoding(ir::Encoding::Linear)),
        ("uv", Value::Mapping(ir::Mapping::Uv)),
        ("planar", Value::Mapping(ir::Mapping::Planar)),
        ("spherical", Value::Mapping(ir::Mapping::Spherical)),
        ("cylindrical", Value::Mapping(ir::Mapping::Cylindrical)),
    ]
    .into_iter()
    .chain(modes)
    .collect()
}

fn int_in(it: &dyn Host, v: &Value, sp: Span, name: &str, lo: i64, hi: i64) -> R<i64> {
    let i = types::int(it, v, sp)?;
    check(
        i >= lo && i <= hi,
        name,
        &format!("in {lo}..={hi}"),
        i as f64,
        sp,
    )?;
    Ok(i)
}

fn camera(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(
        s,
        &[
            "eye",
            "center",
            "up",
            "fov",
            "resolution",
            "aperture",
            "focus",
            "shutter",
            "eye_close",
            "center_close",
            "course",
        ],
        a,
    )?;
    let (eye, es) = p.vec3(it, "eye")?;
    let center = p.vec3_or(it, "center", DVec3::ZERO)?;
    let up_arg = p.get("up");
    // `course: true` is the course camera (COURSE.md §2.4), |up| = the pixel size at `center`:
    // what `rtc convert` writes where no field of view gives that pixel to the last bit.
    let course = p.bool_or(it, "course", false)?;
    let fov_given = p.get("fov");
    if course && let Some((_, fs)) = &fov_given {
        return Err(error(
            "rtc::camera::conflict",
            *fs,
            "`fov` and `course: true` both size the view",
        )
        .with_label("not used by the course camera")
        .with_help("remove `fov`, or `course: true` to size the view by the field of view")
        .into());
    }
    let (fov, fs) = match fov_given {
        Some((v, s)) => (types::angle(it, &v, s)?, s),
        None => (40f64.to_radians(), s.span),
    };
    let shown = format!("{}deg", crate::eval::value::fmt_f(fov.to_degrees()));
    crate::eval::args::check_shown(
        fov > 0.0 && fov < std::f64::consts::PI,
        "fov",
        "in (0deg, 180deg)",
        &shown,
        fs,
    )?;
    let (width, height) = match p.get("resolution") {
        None => (640, 480),
        Some((v, sp)) => match &v {
            Value::List(l) if l.len() == 2 => (
                int_in(it, &l[0], sp, "resolution", 1, MAX_IMAGE_SIDE.into())?,
                int_in(it, &l[1], sp, "resolution", 1, MAX_IMAGE_SIDE.into())?,
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
    let (aperture, aps) = p.num_or(it, "aperture", 0.0)?;
    check(aperture >= 0.0, "aperture", ">= 0", aperture, aps)?;
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
    let (up, us) = match up_arg {
        Some((v, sp)) => (types::vec3(it, &v, sp)?, sp),
        None => (DVec3::Y, s.span),
    };
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
    let (focus, fcs) = p.num_or(it, "focus", view.norm())?;
    positive("focus", focus, fcs)?;
    let shutter = crate::eval::motion::shutter(&mut p)?;
    let motion = crate::eval::motion::camera_motion(it, &mut p, eye, center, up)?;
    Ok(Value::Camera(Rc::new(ir::Camera {
        eye,
        center,
        up,
        width: width as u32,
        height: height as u32,
        projection: if course {
            ir::Projection::Course
        } else {
            ir::Projection::Perspective { fov_y: fov }
        },
        aperture,
        focus_distance: focus,
        shutter,
        motion,
        span: s.span,
    })))
}

fn light_color(it: &dyn Host, p: &mut Params) -> R<DVec3> {
    p.color_or(it, "color", DVec3::ONE)
}

fn point_light(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["position", "color"], a)?;
    let (position, _) = p.vec3(it, "position")?;
    let color = light_color(it, &mut p)?;
    Ok(Value::Light(Rc::new(ir::Light {
        kind: ir::LightKind::Point { position },
        color,
        span: s.span,
    })))
}

fn area_light(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["corner", "u", "v", "samples", "color"], a)?;
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
        None => [4, 4],
        Some((Value::List(l), sp)) if l.len() == 2 => [
            int_in(
                it,
                &l[0],
                sp,
                "samples",
                1,
                MAX_LIGHT_SAMPLES_PER_AXIS.into(),
            )? as u32,
            int_in(
                it,
                &l[1],
                sp,
                "samples",
                1,
                MAX_LIGHT_SAMPLES_PER_AXIS.into(),
            )? as u32,
        ],
        Some((Value::Int(n), sp)) => {
            let n = int_in(
                it,
                &Value::Int(n),
                sp,
                "samples",
                1,
                MAX_LIGHT_SAMPLES_PER_AXIS.into(),
            )? as u32;
            [n, n]
        }
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
    let color = light_color(it, &mut p)?;
    Ok(Value::Light(Rc::new(ir::Light {
        kind: ir::LightKind::Area {
            corner,
            u,
            v,
            samples,
        },
        color,
        span: s.span,
    })))
}

fn gooch(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["b", "y", "alpha", "beta"], a)?;
    let d = ir::GoochParams::default();
    let mut g = d;
    for (name, slot) in [
        ("b", &mut g.b),
        ("y", &mut g.y),
        ("alpha", &mut g.alpha),
        ("beta", &mut g.beta),
    ] {
        let def = *slot;
        let (v, sp) = p.num_or(it, name, def)?;
        unit_interval(name, v, sp)?;
        *slot = v;
    }
    Ok(Value::Shading(ir::ShadingModel::Gooch(g)))
}

/// `flare { ghosts:, dispersal:, halo:, streaks:, threshold:, intensity: }`: lens flare
/// parameters, each defaulted and range-checked ([`ir::Flare::RANGES`]).
fn flare(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    const NAMES: [&str; 6] = [
        "ghosts",
        "dispersal",
        "halo",
        "streaks",
        "threshold",
        "intensity",
    ];
    let mut p = Params::new(s, &NAMES, a)?;
    let mut f = ir::Flare::default();
    let range = |name: &str| {
        let (_, lo, hi) = ir::Flare::RANGES
            .into_iter()
            .find(|(n, _, _)| *n == name)
            .expect("every flare parameter has a range");
        (lo, hi)
    };
    for (name, slot) in [("ghosts", &mut f.ghosts), ("streaks", &mut f.streaks)] {
        if let Some((v, sp)) = p.get(name) {
            let (lo, hi) = range(name);
            *slot = int_in(it, &v, sp, name, lo as i64, hi as i64)? as u32;
        }
    }
    for (name, slot) in [
        ("dispersal", &mut f.dispersal),
        ("halo", &mut f.halo),
        ("threshold", &mut f.threshold),
        ("intensity", &mut f.intensity),
    ] {
        let def = *slot;
        let (v, sp) = p.num_or(it, name, def)?;
        let (lo, hi) = range(name);
        check(v >= lo && v <= hi, name, &format!("in {lo}..={hi}"), v, sp)?;
        *slot = v;
    }
    Ok(Value::Flare(f))
}

fn adaptive(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["min", "max", "threshold"], a)?;
    let min = match p.get("min") {
        Some((v, sp)) => int_in(it, &v, sp, "min", 1, MAX_PIXEL_SAMPLES_PER_AXIS.into())?,
        None => 1,
    };
    let max = match p.get("max") {
        Some((v, sp)) => int_in(it, &v, sp, "max", min, MAX_PIXEL_SAMPLES_PER_AXIS.into())?,
        None => (min * 4).min(MAX_PIXEL_SAMPLES_PER_AXIS.into()),
    };
    let (threshold, ts) = p.num_or(it, "threshold", 0.02)?;
    positive("threshold", threshold, ts)?;
    Ok(Value::Sampling(ir::Sampling::Adaptive {
        min: min as u32,
        max: max as u32,
        threshold,
    }))
}

fn depth(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &["near", "far"], a)?;
    let (near, ns) = p.num(it, "near")?;
    let (far, fs) = p.num(it, "far")?;
    check(near >= 0.0, "near", ">= 0", near, ns)?;
    check(
        far > near,
        "far",
        &format!("> near ({})", crate::eval::value::fmt_f(near)),
        far,
        fs,
    )?;
    Ok(Value::Mode(ir::RenderMode::Depth(ir::DepthRange::Fixed {
        near,
        far,
    })))
}

fn render(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let names = &[
        "shading",
        "mode",
        "shadows",
        "max_depth",
        "supersampling",
        "ambient",
        "background",
        "seed",
        "output",
        "material",
        "encoding",
        "glass_shadows",
        "flare",
        "cutoff",
        "spread_light_samples",
    ];
    let mut p = Params::new(s, names, a)?;
    let mut st = ir::RenderSettings::language_defaults();
    if let Some((v, sp)) = p.get("shading") {
        st.shading = match v {
            Value::Shading(m) => m,
            Value::Builtin(b) if b.name == "gooch" => {
                ir::ShadingModel::Gooch(ir::GoochParams::default())
            }
            other => {
                return Err(enum_mismatch(
                    it,
                    "Shading",
                    &other,
                    sp,
                    "`phong`, `gooch { ... }` or `hatching`",
                ));
            }
        };
    }
    if let Some((v, sp)) = p.get("mode") {
        st.mode = match v {
            Value::Mode(m) => m,
            Value::Builtin(b) if b.name == "depth" => ir::RenderMode::Depth(ir::DepthRange::Auto),
            other => {
                return Err(enum_mismatch(
                    it,
                    "Mode",
                    &other,
                    sp,
                    "`shaded`, `normal` or `depth`",
                ));
            }
        };
    }
    st.shadows = p.bool_or(it, "shadows", st.shadows)?;
    st.glass_shadows = p.bool_or(it, "glass_shadows", st.glass_shadows)?;
    if let Some((v, sp)) = p.get("flare") {
        st.flare = match v {
            Value::Flare(f) => Some(f),
            Value::Builtin(b) if b.name == "flare" => Some(ir::Flare::default()),
            Value::Bool(on) => on.then(ir::Flare::default),
            other => {
                return Err(enum_mismatch(
                    it,
                    "Flare",
                    &other,
                    sp,
                    "`flare`, `flare { ghosts: 6 }` or `false`",
                ));
            }
        };
    }
    if let Some((v, sp)) = p.get("max_depth") {
        st.max_depth = int_in(it, &v, sp, "max_depth", 0, MAX_DEPTH.into())? as u32;
    }
    if let Some((v, sp)) = p.get("supersampling") {
        st.sampling = match v {
            Value::Sampling(x) => x,
            Value::Int(_) => ir::Sampling::Grid {
                factor: int_in(
                    it,
                    &v,
                    sp,
                    "supersampling",
                    1,
                    MAX_PIXEL_SAMPLES_PER_AXIS.into(),
                )? as u32,
            },
            other => {
                return Err(enum_mismatch(
                    it,
                    "Int",
                    &other,
                    sp,
                    "a factor such as `4`, or `adaptive(min: 1, max: 16, threshold: 0.02)`",
                ));
            }
        };
    }
    if let Some((v, sp)) = p.get("ambient") {
        st.ambient = match v {
            Value::Ambient(x) => x,
            other => {
                return Err(enum_mismatch(
                    it,
                    "Ambient",
                    &other,
                    sp,
                    "`per_light` or `once`",
                ));
            }
        };
    }
    if let Some((v, sp)) = p.get("encoding") {
        st.encoding = match v {
            Value::Encoding(e) => e,
            Value::Builtin(b) if b.name == "srgb" => ir::Encoding::Srgb,
            other => {
                return Err(enum_mismatch(
                    it,
                    "Encoding",
                    &other,
                    sp,
                    "`srgb` or `linear`",
                ));
            }
        };
    }
    st.background = p.color_or(it, "background", DVec3::ZERO)?;
    let (cutoff, cs) = p.num_or(it, "cutoff", st.cutoff)?;
    unit_interval("cutoff", cutoff, cs)?;
    st.cutoff = cutoff;
    if p.bool_or(it, "spread_light_samples", false)? {
        st.light_samples = ir::LightSampling::Spread;
    }
    if let Some((v, sp)) = p.get("seed") {
        st.seed = int_in(it, &v, sp, "seed", 0, i64::MAX)? as u64;
    }
    if let Some((v, sp)) = p.get("output") {
        let rel = types::string(it, &v, sp)?;
        st.output = Some(crate::eval::modules::resolve(it.dir(), &rel));
        st.output_span = Some(sp);
    }
    let mut rv = RenderVal {
        s: st,
        span: s.span,
        material: None,
    };
    if let Some((v, sp)) = p.get("material") {
        match v {
            Value::Material(m) => rv.material = Some(m),
            other => return Err(types::mismatch(it, "Material", &other, sp).into()),
        }
    }
    Ok(Value::Render(Rc::new(rv)))
}

fn enum_mismatch(
    it: &dyn Host,
    want: &str,
    v: &Value,
    sp: Span,
    choices: &str,
) -> crate::eval::error::EvalError {
    types::mismatch(it, want, v, sp)
        .with_help(format!("write {choices}"))
        .into()
}
