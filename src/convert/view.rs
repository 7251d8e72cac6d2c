//! The scene's view and how it is rendered, as rtc source: the camera (its projection, lens,
//! shutter and motion), the lights and the `render { ... }` record.

use crate::num::Norm;
use std::fmt::Write as _;

use super::shapes;
use super::text::{color, direction, number, string, vector};
use crate::ir::{
    AmbientConvention, Camera, DepthRange, Encoding, Flare, Fog, Integrator, Light, LightKind,
    LightSampling, PathTracing, Projection, RenderMode, RenderSettings, Sampling,
};

/// The camera. With `course_fov`, the course camera (|up| = the size of a pixel at `center`)
/// becomes the field of view that makes a pixel at `center` exactly |up| wide where an angle
/// does that to the last bit; otherwise it stays `course: true` (the language's course camera).
/// `up` keeps its length either way.
pub(crate) fn camera(c: &Camera, course_fov: bool) -> String {
    let mut out = String::new();
    let view = match c.projection {
        Projection::Perspective { fov_y } => format!("fov: {}rad", number(fov_y)),
        Projection::Orthographic { height } => {
            format!("projection: \"orthographic\", height: {}", number(height))
        }
        Projection::Equirectangular => "projection: \"equirectangular\"".to_string(),
        Projection::Fisheye { fov } => format!("projection: \"fisheye\", fov: {}rad", number(fov)),
        Projection::Cylindrical { fov } => {
            format!("projection: \"cylindrical\", fov: {}rad", number(fov))
        }
        Projection::Course if !course_fov => "course: true".to_string(),
        Projection::Course => {
            let size = c.up.norm();
            let width = if size == 1.0 {
                "one unit".to_string()
            } else {
                format!("|up| = {} units", number(size))
            };
            let _ = writeln!(
                out,
                "// The course camera: {}×{} pixels {width} wide on the plane through `center` (COURSE.md §2.4).",
                c.width, c.height
            );
            match course_fov_of(c) {
                Some(fov) => {
                    out.push_str(
                        "// The field of view 2·atan(h·|up| / (2·distance(eye, center))) gives the same rays.\n",
                    );
                    format!("fov: {fov}")
                }
                None => {
                    out.push_str(
                        "// No field of view gives this pixel size to the last bit, so `course: true` keeps it.\n",
                    );
                    "course: true".to_string()
                }
            }
        }
    };
    let _ = writeln!(
        out,
        "camera {{\n  eye: {}, center: {}, up: {}\n  {view}, resolution: [{}, {}]",
        vector(c.eye),
        vector(c.center),
        direction(c.up),
        c.width,
        c.height
    );
    // The language's focus defaults to the distance to `center`; the IR keeps it either way.
    let default_focus = (c.center - c.eye).norm();
    if c.aperture > 0.0 || c.focus_distance != default_focus {
        let _ = writeln!(
            out,
            "  aperture: {}, focus: {}",
            number(c.aperture),
            number(c.focus_distance)
        );
    }
    if let Some(s) = c.shutter {
        let _ = writeln!(out, "  shutter: [{}, {}]", number(s.open), number(s.close));
    }
    if let Some(m) = c.motion {
        let _ = writeln!(
            out,
            "  eye_close: {}, center_close: {}",
            vector(m.eye),
            vector(m.center)
        );
    }
    out.push_str("}\n");
    out
}

/// The `fov` of a course camera, `2 * atan(a / d)` with a = h·|up|/2 and d = |center − eye|,
/// when the renderer's pixel for it (`render::camera`: 2·d·tan(fov/2)/h, with `libm` as here)
/// is |up| to the bit.
fn course_fov_of(c: &Camera) -> Option<String> {
    let size = c.up.norm();
    let d = (c.center - c.eye).norm();
    let h = f64::from(c.height);
    let a = h * size / 2.0;
    let fov = 2.0 * libm::atan(a / d);
    let pixel = 2.0 * d * libm::tan(0.5 * fov) / h;
    (pixel == size).then(|| format!("2 * atan({} / {})", number(a), number(d)))
}

/// A light as its constructor.
pub(crate) fn light(l: &Light) -> String {
    let (name, mut fields) = match (l.kind, l.spot) {
        (LightKind::Point { position }, Some(spot)) => (
            "spot_light",
            vec![
                format!("position: {}", vector(position)),
                format!("target: {}", vector(spot.target)),
                format!("radius: {}rad", number(spot.radius)),
                format!("falloff: {}rad", number(spot.falloff)),
                format!("tightness: {}", number(spot.tightness)),
            ],
        ),
        (LightKind::Point { position }, None) => (
            "point_light",
            vec![format!("position: {}", vector(position))],
        ),
        (
            LightKind::Area {
                corner,
                u,
                v,
                samples,
                circular,
                orient,
            },
            _,
        ) => {
            let mut fields = vec![
                format!("corner: {}", vector(corner)),
                format!("u: {}", vector(u)),
                format!("v: {}", vector(v)),
                format!("samples: [{}, {}]", samples[0], samples[1]),
            ];
            if circular {
                fields.push("circular: true".into());
            }
            if orient {
                fields.push("orient: true".into());
            }
            ("area_light", fields)
        }
        (
            LightKind::Cylinder {
                position,
                target,
                radius,
                falloff,
                tightness,
                ..
            },
            _,
        ) => (
            "cylinder_light",
            vec![
                format!("position: {}", vector(position)),
                format!("target: {}", vector(target)),
                format!("radius: {}", number(radius)),
                format!("falloff: {}", number(falloff)),
                format!("tightness: {}", number(tightness)),
            ],
        ),
        (LightKind::Parallel { direction }, _) => (
            "parallel_light",
            vec![format!("direction: {}", vector(direction))],
        ),
    };
    fields.push(format!("color: {}", color(l.color)));
    if let Some(fade) = l.fade {
        fields.push(format!("fade_distance: {}", number(fade.distance)));
        fields.push(format!("fade_power: {}", number(fade.power)));
    }
    if !l.shadows {
        fields.push("shadows: false".into());
    }
    format!("{name} {{ {} }}", fields.join(", "))
}

/// What the `render { ... }` record needs besides the settings.
pub(crate) struct RenderDoc {
    /// A course scene: its settings are all written, with a comment on why.
    pub(crate) course: bool,
    /// The name of the default material (`render { material: ... }`), if the scene has one.
    pub(crate) material: Option<String>,
    /// How the output file is referred to from the rtc file's directory.
    pub(crate) output: Option<String>,
    /// The sky's texture as rtc source, if the scene has a sky.
    pub(crate) sky: Option<String>,
    /// The fog's pattern as rtc source, if its fog has one.
    pub(crate) fog_pattern: Option<String>,
}

/// The `render { ... }` record: every setting that differs from the language's defaults, and
/// for a course scene those the course gives (shadows, bounces, encoding, cut-off), so the file
/// says what it renders. An empty record is left out.
pub(crate) fn render(s: &RenderSettings, doc: &RenderDoc) -> String {
    let lang = RenderSettings::language_defaults();
    let mut fields = Vec::new();
    if doc.course || s.shadows != lang.shadows {
        fields.push(format!("shadows: {}", s.shadows));
    }
    if doc.course || s.max_depth != lang.max_depth {
        fields.push(format!("max_depth: {}", s.max_depth));
    }
    match s.sampling {
        Sampling::Grid { factor: 1 } => {}
        Sampling::Grid { factor } => fields.push(format!("supersampling: {factor}")),
        Sampling::Adaptive {
            min,
            max,
            threshold,
        } => fields.push(format!(
            "supersampling: adaptive(min: {min}, max: {max}, threshold: {})",
            number(threshold)
        )),
    }
    if let Integrator::Path(p) = s.integrator {
        fields.push(format!("integrator: {}", path_tracing(&p)));
    }
    // A mode without parameters is written by its name in the language's table.
    match s.mode {
        RenderMode::Shaded => {}
        RenderMode::Depth(DepthRange::Auto) => fields.push("mode: depth".into()),
        RenderMode::Depth(DepthRange::Fixed { near, far }) => fields.push(format!(
            "mode: depth(near: {}, far: {})",
            number(near),
            number(far)
        )),
        named => {
            if let Some((name, _)) = RenderMode::NAMED.iter().find(|(_, m)| *m == named) {
                fields.push(format!("mode: {name}"));
            }
        }
    }
    if s.shading != lang.shading {
        fields.push(format!("shading: {}", shapes::shading(s.shading)));
    }
    if s.ambient == AmbientConvention::Once {
        fields.push("ambient: once".into());
    }
    if s.background != glam::DVec3::ZERO {
        fields.push(format!("background: {}", color(s.background)));
    }
    if let (Some(sky), Some(text)) = (s.sky, &doc.sky) {
        fields.push(format!("sky: {text}"));
        if sky.rotation != 0.0 {
            fields.push(format!("sky_rotation: {}rad", number(sky.rotation)));
        }
        if sky.strength.to_bits() != 1f64.to_bits() {
            fields.push(format!("sky_strength: {}", number(sky.strength)));
        }
    }
    if let Some(f) = s.fog {
        fields.push(format!("fog: {}", fog(&f, doc.fog_pattern.as_deref())));
    }
    if s.alpha {
        fields.push("alpha: true".into());
    }
    if s.seed != 0 {
        fields.push(format!("seed: {}", s.seed));
    }
    if let Some(m) = &doc.material {
        fields.push(format!("material: {m}"));
    }
    if let Some(o) = &doc.output {
        fields.push(format!("output: {}", string(o)));
    }
    if s.glass_shadows {
        fields.push("glass_shadows: true".into());
    }
    if let Some(f) = s.flare {
        fields.push(format!("flare: {}", flare(&f)));
    }
    if s.light_samples == LightSampling::Spread {
        fields.push("spread_light_samples: true".into());
    }
    if doc.course || s.encoding != lang.encoding {
        let encoding = match s.encoding {
            Encoding::Linear => "linear",
            Encoding::Srgb => "srgb",
        };
        fields.push(format!("encoding: {encoding}"));
    }
    if doc.course || s.cutoff.to_bits() != lang.cutoff.to_bits() {
        fields.push(format!("cutoff: {}", number(s.cutoff)));
    }
    if fields.is_empty() {
        return String::new();
    }
    let why = if doc.course {
        "// The course's settings, written out where the language's defaults differ (shadows on,\n\
         // 5 bounces, sRGB output, a cut-off): `encoding: linear` writes trunc(255·c) like the\n\
         // course and `cutoff: 0` traces every ray.\n"
    } else {
        ""
    };
    let one_line = format!("render {{ {} }}", fields.join(", "));
    if one_line.len() <= 100 {
        format!("{why}{one_line}\n")
    } else {
        format!("{why}render {{\n  {}\n}}\n", fields.join("\n  "))
    }
}

/// Fog: its colour and distance, and the fields that differ from their defaults.
fn fog(f: &Fog, pattern: Option<&str>) -> String {
    let mut fields = vec![
        format!("color: {}", color(f.color)),
        format!("distance: {}", number(f.distance)),
    ];
    if f.filter != 0.0 {
        fields.push(format!("filter: {}", number(f.filter)));
    }
    if f.transmit != 0.0 {
        fields.push(format!("transmit: {}", number(f.transmit)));
    }
    if let Some(g) = f.ground {
        if g.offset != 0.0 {
            fields.push(format!("offset: {}", number(g.offset)));
        }
        fields.push(format!("altitude: {}", number(g.altitude)));
    }
    if let (Some(fp), Some(text)) = (f.pattern, pattern) {
        fields.push(format!("pattern: {text}"));
        if fp.depth.to_bits() != 0.5f64.to_bits() {
            fields.push(format!("pattern_depth: {}", number(fp.depth)));
        }
    }
    format!("fog {{ {} }}", fields.join(", "))
}

/// The path tracer: `path` for the defaults, else every setting.
fn path_tracing(p: &PathTracing) -> String {
    if *p == PathTracing::DEFAULT {
        "path".into()
    } else {
        format!(
            "path(samples: {}, bounces: {}, roulette: {})",
            p.samples, p.bounces, p.roulette
        )
    }
}

/// A lens flare: `flare` for the defaults, else the fields that differ from them.
fn flare(f: &Flare) -> String {
    let d = Flare::default();
    let mut fields = Vec::new();
    if f.ghosts != d.ghosts {
        fields.push(format!("ghosts: {}", f.ghosts));
    }
    if f.dispersal.to_bits() != d.dispersal.to_bits() {
        fields.push(format!("dispersal: {}", number(f.dispersal)));
    }
    if f.halo.to_bits() != d.halo.to_bits() {
        fields.push(format!("halo: {}", number(f.halo)));
    }
    if f.streaks != d.streaks {
        fields.push(format!("streaks: {}", f.streaks));
    }
    if f.threshold.to_bits() != d.threshold.to_bits() {
        fields.push(format!("threshold: {}", number(f.threshold)));
    }
    if f.intensity.to_bits() != d.intensity.to_bits() {
        fields.push(format!("intensity: {}", number(f.intensity)));
    }
    if fields.is_empty() {
        "flare".into()
    } else {
        format!("flare {{ {} }}", fields.join(", "))
    }
}
