//! Render settings and their parts: `render { .. }`, `gooch`, `adaptive`, `depth`, `flare`
//! (`fog` has its own file), and the named values of their enumerations.

use std::rc::Rc;

use crate::eval::args::Params;
use crate::eval::args::{ArgVal, CallSite, check};
use crate::eval::error::{R, error};
use crate::eval::host::BuiltinFn;
use crate::eval::host::Host;
use crate::eval::schema::{Group, Lit, Param, Range, Sig, Ty, Unit};
use crate::eval::types;
use crate::eval::value::{RenderVal, Value};
use crate::ir;
use crate::ir::limits::{MAX_DEPTH, MAX_PIXEL_SAMPLES_PER_AXIS};
use crate::source::Span;

/// The render settings' constructors with their schemas.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[
    (&RENDER, render),
    (&GOOCH, gooch),
    (&ADAPTIVE, adaptive),
    (&DEPTH, depth),
    (&FLARE, flare),
];

/// Named enumeration values.
pub(crate) fn constants() -> Vec<(&'static str, Value)> {
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

/// A Gooch parameter in [0, 1].
const fn gooch_param(name: &'static str, doc: &'static str, default: f64) -> Param {
    Param::new(name, Ty::Float, doc)
        .range(Range::UnitInterval)
        .or(Lit::Float(default))
}

/// `gooch(b, y, alpha, beta)` (the defaults are `ir::GoochParams::default()`'s).
pub(super) static GOOCH: Sig = Sig::new(
    "gooch",
    Group::Render,
    "The cool-to-warm shading model: `kCool = (0, 0, b) + alpha·kd·C`, `kWarm = (y, y, 0) + beta·kd·C`.",
    &[
        gooch_param("b", "the blue of the cool tone", 0.55),
        gooch_param("y", "the yellow of the warm tone", 0.3),
        gooch_param(
            "alpha",
            "how much of the surface colour the cool tone takes",
            0.25,
        ),
        gooch_param(
            "beta",
            "how much of the surface colour the warm tone takes",
            0.5,
        ),
    ],
    "Shading",
)
.examples(&["gooch(b: 0.55, y: 0.3, alpha: 0.25, beta: 0.5)"]);
fn gooch(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &GOOCH, a)?;
    let g = ir::GoochParams {
        b: p.float(it, "b")?.0,
        y: p.float(it, "y")?.0,
        alpha: p.float(it, "alpha")?.0,
        beta: p.float(it, "beta")?.0,
    };
    Ok(Value::Shading(ir::ShadingModel::Gooch(g)))
}

/// A flare parameter of `Float` in `lo..=hi` (the ranges are `ir::Flare::RANGES`, the defaults
/// `ir::Flare::default()`'s).
const fn flare_float(
    name: &'static str,
    doc: &'static str,
    lo: f64,
    hi: f64,
    default: f64,
) -> Param {
    Param::new(name, Ty::Float, doc)
        .range(Range::Between(lo, hi))
        .or(Lit::Float(default))
}

/// A flare parameter of `Int` in `0..=hi`.
const fn flare_count(name: &'static str, doc: &'static str, hi: i64, default: i64) -> Param {
    Param::new(name, Ty::Int, doc)
        .range(Range::Ints(0, hi))
        .or(Lit::Int(default))
}

/// `flare { ghosts:, dispersal:, halo:, streaks:, threshold:, intensity: }`: lens flare
/// parameters, each defaulted and range-checked.
pub(super) static FLARE: Sig = Sig::new(
    "flare",
    Group::Render,
    "Lens flare parameters (docs/looks.md has a picture of each).",
    &[
        flare_count(
            "ghosts",
            "ghost discs along the line through the image centre",
            16,
            4,
        ),
        flare_float(
            "dispersal",
            "the ghosts' spacing, as a fraction of the light-to-centre vector",
            0.0,
            2.0,
            0.4,
        ),
        flare_float(
            "halo",
            "the halo ring's radius, as a fraction of the image diagonal (0: none)",
            0.0,
            1.0,
            0.15,
        ),
        flare_count("streaks", "star streaks through the light (0: none)", 32, 6),
        flare_float(
            "threshold",
            "lights seen dimmer than this flare not",
            0.0,
            1000.0,
            0.1,
        ),
        flare_float("intensity", "the flare's brightness", 0.0, 10.0, 0.5),
    ],
    "Flare",
)
.examples(&[
    "flare { ghosts: 6, dispersal: 0.4, halo: 0.15, streaks: 8, threshold: 0.1, intensity: 0.5 }",
]);
fn flare(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &FLARE, a)?;
    let ghosts = p.int(it, "ghosts")?.0 as u32;
    let streaks = p.int(it, "streaks")?.0 as u32;
    Ok(Value::Flare(ir::Flare {
        ghosts,
        streaks,
        dispersal: p.float(it, "dispersal")?.0,
        halo: p.float(it, "halo")?.0,
        threshold: p.float(it, "threshold")?.0,
        intensity: p.float(it, "intensity")?.0,
    }))
}

/// `adaptive(min, max, threshold)`.
static ADAPTIVE: Sig = Sig::new(
    "adaptive",
    Group::Render,
    "Adaptive supersampling: from `min` to `max` samples per axis where neighbours differ.",
    &[
        Param::new("min", Ty::Int, "the samples per axis of every pixel")
            .unit(Unit::Samples)
            .range(Range::Ints(1, MAX_PIXEL_SAMPLES_PER_AXIS as i64))
            .or(Lit::Int(1)),
        Param::new("max", Ty::Int, "the most samples per axis (at least `min`)")
            .unit(Unit::Samples)
            .range(Range::Ints(1, MAX_PIXEL_SAMPLES_PER_AXIS as i64))
            .checked_by_builtin()
            .computed("min(4·min, 64)"),
        Param::new(
            "threshold",
            Ty::Float,
            "the difference between neighbours that refines",
        )
        .range(Range::Positive)
        .or(Lit::Float(0.02)),
    ],
    "Sampling",
)
.examples(&["adaptive(min: 1, max: 8, threshold: 0.02)"]);
fn adaptive(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &ADAPTIVE, a)?;
    let (min, _) = p.int(it, "min")?;
    let most = i64::from(MAX_PIXEL_SAMPLES_PER_AXIS);
    let max = match p.int_opt(it, "max")? {
        // At least `min`: a rule of two parameters, checked here.
        Some((max, sp)) => {
            check(
                max >= min && max <= most,
                "max",
                &format!("in {min}..={most}"),
                max as f64,
                sp,
            )?;
            max
        }
        None => (min * 4).min(most),
    };
    let (threshold, _) = p.float(it, "threshold")?;
    Ok(Value::Sampling(ir::Sampling::Adaptive {
        min: min as u32,
        max: max as u32,
        threshold,
    }))
}

/// `depth(near, far)`.
static DEPTH: Sig = Sig::new(
    "depth",
    Group::Render,
    "The depth image over a fixed range (the mode `depth` alone takes the image's own range).",
    &[
        Param::new("near", Ty::Float, "the distance shown white")
            .unit(Unit::Length)
            .range(Range::NonNegative),
        Param::new(
            "far",
            Ty::Float,
            "the distance shown black (> near, checked here)",
        )
        .unit(Unit::Length),
    ],
    "Mode",
)
.examples(&["depth(near: 1, far: 20)"]);
fn depth(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &DEPTH, a)?;
    let (near, _) = p.float(it, "near")?;
    let (far, fs) = p.float(it, "far")?;
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

/// `render { .. }`'s fields, in positional order (the defaults are
/// `ir::RenderSettings::language_defaults()`'s).
pub(super) static RENDER: Sig = Sig::new(
    "render",
    Group::Render,
    "How the image is made; at most one per scene.",
    &[
        Param::new("shading", Ty::Shading, "the shading model").or(Lit::Name("phong")),
        Param::new("mode", Ty::Mode, "what the image shows").or(Lit::Name("shaded")),
        Param::new("shadows", Ty::Bool, "cast shadow rays").or(Lit::Bool(true)),
        Param::new("max_depth", Ty::Int, "reflection and refraction bounces")
            .range(Range::Ints(0, MAX_DEPTH as i64))
            .or(Lit::Int(5)),
        Param::new(
            "supersampling",
            Ty::OneOf(&[Ty::Int, Ty::Sampling]),
            "an f × f grid per pixel, or `adaptive(..)`",
        )
        .unit(Unit::Samples)
        .range(Range::Ints(1, MAX_PIXEL_SAMPLES_PER_AXIS as i64))
        .or(Lit::Int(1)),
        Param::new(
            "ambient",
            Ty::Ambient,
            "`ka·C·Lc` for every light, or `ka·C` once",
        )
        .or(Lit::Name("per_light")),
        Param::new(
            "background",
            Ty::Color,
            "the colour of rays that hit nothing",
        )
        .or(Lit::Color([0.0, 0.0, 0.0])),
        Param::new(
            "seed",
            Ty::Int,
            "the seed of the renderer's random decisions",
        )
        .range(Range::Ints(0, i64::MAX))
        .or(Lit::Int(0)),
        Param::new(
            "output",
            Ty::String,
            "the image path, relative to the scene file",
        )
        .optional(),
        Param::new(
            "material",
            Ty::Material,
            "the material of objects without one",
        )
        .computed("the default material"),
        Param::new("encoding", Ty::Encoding, "how colours become 8-bit values")
            .or(Lit::Name("srgb")),
        Param::new(
            "glass_shadows",
            Ty::Bool,
            "shadow rays pass through refractive surfaces",
        )
        .or(Lit::Bool(false)),
        Param::new(
            "flare",
            Ty::OneOf(&[Ty::Flare, Ty::Bool]),
            "the lens flare post stage",
        )
        .or(Lit::Bool(false)),
        Param::new(
            "cutoff",
            Ty::Float,
            "reflected or refracted rays of less weight are not traced",
        )
        .range(Range::UnitInterval)
        .or(Lit::Float(ir::LANGUAGE_CUTOFF)),
        Param::new(
            "spread_light_samples",
            Ty::Bool,
            "deal an area light's cells out over a pixel's samples",
        )
        .or(Lit::Bool(false)),
        Param::new(
            "sky",
            Ty::Texture,
            "what rays that hit nothing see: a pattern read at the ray's direction, or an `image(..)` (PNG, HDR, EXR) as a latitude–longitude map",
        )
        .optional(),
        Param::new(
            "sky_rotation",
            Ty::Angle,
            "the sky turned about +Y (counter-clockwise seen from above)",
        )
        .unit(Unit::Angle)
        .or(Lit::Degrees(0.0)),
        Param::new(
            "sky_strength",
            Ty::Float,
            "the sky's colour is multiplied by this",
        )
        .range(Range::NonNegative)
        .or(Lit::Float(1.0)),
        Param::new("fog", Ty::Fog, "fog along the rays, `fog { .. }`").optional(),
        Param::new(
            "alpha",
            Ty::Bool,
            "an alpha channel in PNG and EXR output: the share of a pixel's camera samples that meet something",
        )
        .or(Lit::Bool(false)),
        Param::new(
            "integrator",
            Ty::Integrator,
            "how a camera ray's light is found: `whitted` or the path tracer `path(..)` (docs/gi.md)",
        )
        .or(Lit::Name("whitted")),
    ],
    "Render",
)
.examples(&["render { shading: gooch, mode: normal, shadows: false, max_depth: 2, supersampling: 4, ambient: once, background: srgb(0.1, 0.1, 0.15), seed: 42 }", "render { output: \"out.png\", material: material { kd: 0.5 }, encoding: linear, glass_shadows: true, flare: flare { ghosts: 6 }, cutoff: 0, spread_light_samples: true }", "render { sky: gradient(axis: Y).colors([rgb(1, 1, 1), rgb(0.2, 0.4, 0.9)]), sky_rotation: 90deg, sky_strength: 1.5, fog: fog { color: rgb(0.8, 0.8, 0.8), distance: 30 } }"]);
fn render(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &RENDER, a)?;
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
    st.shadows = p.bool(it, "shadows")?;
    st.glass_shadows = p.bool(it, "glass_shadows")?;
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
    st.max_depth = p.int(it, "max_depth")?.0 as u32;
    if let Some((v, sp)) = p.get("supersampling") {
        st.sampling = match v {
            Value::Sampling(x) => x,
            Value::Int(_) => ir::Sampling::Grid {
                factor: p.int_in(it, "supersampling", &v, sp)? as u32,
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
    if let Some((v, sp)) = p.get("integrator") {
        st.integrator = super::integrator::integrator_of(it, v, sp)?;
        super::integrator::check_paths_per_pixel(st.integrator, st.sampling, sp)?;
    }
    st.background = p.color(it, "background")?.0;
    st.alpha = p.bool(it, "alpha")?;
    st.cutoff = p.float(it, "cutoff")?.0;
    if p.bool(it, "spread_light_samples")? {
        st.light_samples = ir::LightSampling::Spread;
    }
    st.seed = p.int(it, "seed")?.0 as u64;
    if let Some((v, sp)) = p.get("output") {
        let rel = types::string(it, &v, sp)?;
        st.output = Some(crate::eval::modules::resolve(it.dir(), &rel));
        st.output_span = Some(sp);
    }
    let mut fog_pattern = None;
    if let Some((v, sp)) = p.get("fog") {
        st.fog = match v {
            Value::Fog(f) => {
                fog_pattern = f.pattern.clone();
                Some(f.fog)
            }
            other => return Err(types::mismatch(it, "Fog", &other, sp).into()),
        };
    }
    let rotation = p.angle(it, "sky_rotation")?.0;
    let strength = p.float(it, "sky_strength")?.0;
    let sky = match p.get("sky") {
        Some((Value::Texture(t), sp)) => {
            sky_readable(&t.t, sp)?;
            Some((t, rotation, strength))
        }
        Some((other, sp)) => return Err(types::mismatch(it, "Texture", &other, sp).into()),
        None => None,
    };
    let mut rv = RenderVal {
        s: st,
        span: s.span,
        material: None,
        sky,
        fog_pattern,
    };
    if let Some((v, sp)) = p.get("material") {
        match v {
            Value::Material(m) => rv.material = Some(m),
            other => return Err(types::mismatch(it, "Material", &other, sp).into()),
        }
    }
    Ok(Value::Render(Rc::new(rv)))
}

/// A sky is read along directions: a texture that needs a surface's coordinates (a normal map,
/// a pattern read in uv space) has nothing to read there.
fn sky_readable(t: &ir::Texture, sp: Span) -> R<()> {
    let what = match t {
        ir::Texture::NormalMap { .. } => "a normal map",
        ir::Texture::Pattern(p) if p.space == ir::PatternSpace::Uv => "a pattern read in uv space",
        _ => return Ok(()),
    };
    Err(error(
        "rtc::render::sky",
        sp,
        format!("{what} cannot be a sky: a sky has no surface coordinates"),
    )
    .with_label("read along the ray's direction")
    .with_help("use a pattern in its own space (without `.uv()`), or `image(..)` for a latitude–longitude picture")
    .into())
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
