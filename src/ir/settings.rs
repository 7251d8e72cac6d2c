//! Render settings: how a scene's pixels become colours (sampling, depth, shading model, encoding,
//! the render modes), and their defaults.

use std::path::PathBuf;

use glam::DVec3;

use super::{Color, Flare, Fog, MaterialId, Sky};

/// How pixels become colours.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderSettings {
    /// The scene-wide shading model (materials may override it).
    pub shading: ShadingModel,
    /// Image mode: shaded colour or a geometric buffer.
    pub mode: RenderMode,
    /// Cast shadow rays.
    pub shadows: bool,
    /// Maximum number of reflection/refraction bounces.
    pub max_depth: u32,
    /// Samples per pixel.
    pub sampling: Sampling,
    /// How Phong's ambient term is counted.
    pub ambient: AmbientConvention,
    /// Colour of rays that hit nothing (behind the sky's filter and transmit, if it has any).
    pub background: Color,
    /// What rays that hit nothing see instead of `background` (`None`: the background).
    pub sky: Option<Sky>,
    /// Fog along the rays (`None`: clear air).
    pub fog: Option<Fog>,
    /// The image gets an alpha channel, the share of a pixel's camera samples that meet
    /// something (POV-Ray's `+UA`); camera rays that meet nothing are transparent black.
    pub alpha: bool,
    /// Material for objects that name none.
    pub default_material: Option<MaterialId>,
    /// Seed for every random decision (area lights, lens, jitter); bytes depend only on it.
    pub seed: u64,
    /// Output file requested by the scene, resolved relative to it.
    pub output: Option<PathBuf>,
    /// Where the scene asked for `output` (the CLI's confinement error points there).
    pub output_span: Option<crate::source::Span>,
    /// How film colours become 8-bit values.
    pub encoding: Encoding,
    /// Shadow rays pass through refractive surfaces, attenuated by their `refract` and colour
    /// (off: glass casts an opaque shadow, as the course references do).
    pub glass_shadows: bool,
    /// The lens flare post stage, when asked.
    pub flare: Option<Flare>,
    /// The insignificance cut-off: a reflected or refracted ray whose weight (the product of
    /// the reflect/refract coefficients along its path) is below it is not traced. 0 traces all.
    pub cutoff: f64,
    /// How an area light's samples are shared among a pixel's samples.
    pub light_samples: LightSampling,
    /// How a camera ray's light is found: Whitted recursion or the path tracer.
    pub integrator: Integrator,
}

/// How a camera ray's light is found in a shaded image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Integrator {
    /// Whitted ray tracing: local shading plus mirror and refraction rays (the course's).
    Whitted,
    /// A unidirectional path tracer with next-event estimation (docs/gi.md).
    Path(PathTracing),
}

/// The path tracer's settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PathTracing {
    /// Paths traced per camera ray (a pixel gets `supersampling² · samples`).
    pub samples: u32,
    /// The most scattering events along a path.
    pub bounces: u32,
    /// The bounce from which Russian roulette may end a path (`bounces` or more: never).
    pub roulette: u32,
}

impl PathTracing {
    /// `path` without arguments.
    pub const DEFAULT: PathTracing = PathTracing {
        samples: 16,
        bounces: 16,
        roulette: 3,
    };

    /// The paths a pixel of `camera_samples` camera samples gets (each carries `samples`);
    /// the budget `limits::MAX_PIXEL_PATHS` bounds it.
    pub fn paths_per_pixel(&self, camera_samples: u32) -> u64 {
        u64::from(camera_samples) * u64::from(self.samples)
    }
}

/// The language's default insignificance cut-off: half of the smallest step of the sRGB curve
/// (its slope is steepest at black, 12.92, so one 8-bit level there is 1/(255·12.92) ≈ 3.0e-4 in
/// linear light). A dropped ray of weight below it changes a pixel of radiance ≤ 1 by less than
/// half a level: at most one level after rounding, usually none. POV-Ray's 1/255 was chosen for
/// linear output and would drop up to 13 sRGB levels near black.
pub(crate) const LANGUAGE_CUTOFF: f64 = 0.5 / (255.0 * 12.92);

/// How an area light's samples are shared among a pixel's samples.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LightSampling {
    /// Every pixel sample takes every cell of every area light (n² shadow rays per pixel
    /// sample): the course's rule and the default.
    #[default]
    PerSample,
    /// The cells are dealt out over the pixel's samples: with s pixel samples, each takes
    /// ⌈n²/s⌉ cells (at least one), so a pixel still covers every cell while a pixel sample
    /// casts fewer shadow rays.
    Spread,
}

/// How a linear film colour is quantised to 8 bits.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Encoding {
    /// `trunc(255·clamp(c))`: the course's convention, which its reference images use (the
    /// default of the IR, so the course front ends keep it).
    #[default]
    Linear,
    /// The sRGB transfer curve, rounded to the nearest level: what `.rtc` scenes get by default,
    /// so that an sRGB colour such as `#808080` comes out as the byte it names (128).
    Srgb,
}

impl RenderSettings {
    /// The course formats' defaults (COURSE.md): no shadows and no bounces unless the file asks,
    /// one sample per pixel, no insignificance cut-off (so the reference images stay exact). The same as [`RenderSettings::default`], the IR's neutral settings.
    pub fn course_defaults() -> RenderSettings {
        RenderSettings::default()
    }

    /// The scene language's defaults (docs/language.md, `render`): shadows on and up to five
    /// bounces, so a glass or mirror material shows without further settings, sRGB output and
    /// the cut-off [`LANGUAGE_CUTOFF`].
    pub(crate) fn language_defaults() -> RenderSettings {
        RenderSettings {
            shadows: true,
            max_depth: 5,
            encoding: Encoding::Srgb,
            cutoff: LANGUAGE_CUTOFF,
            ..RenderSettings::course_defaults()
        }
    }
}

/// The IR's neutral settings, which are the course defaults: nothing costly unless asked for.
impl Default for RenderSettings {
    fn default() -> RenderSettings {
        RenderSettings {
            shading: ShadingModel::Phong,
            mode: RenderMode::Shaded,
            shadows: false,
            max_depth: 0,
            sampling: Sampling::Grid { factor: 1 },
            ambient: AmbientConvention::PerLight,
            background: DVec3::ZERO,
            sky: None,
            fog: None,
            alpha: false,
            default_material: None,
            seed: 0,
            output: None,
            output_span: None,
            encoding: Encoding::Linear,
            glass_shadows: false,
            flare: None,
            cutoff: 0.0,
            light_samples: LightSampling::PerSample,
            integrator: Integrator::Whitted,
        }
    }
}

/// Shading model for colour images.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ShadingModel {
    /// Phong as COURSE.md §2.5.
    Phong,
    /// Gooch cool-to-warm shading (COURSE.md §2.5), no ambient term.
    Gooch(GoochParams),
    /// Pen-and-ink hatching (non-photorealistic).
    Hatching,
}

/// Parameters of the Gooch model: `kCool = (0,0,b) + alpha·kd·C`, `kWarm = (y,y,0) + beta·kd·C`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GoochParams {
    /// Blue of the cool colour.
    pub b: f64,
    /// Yellow of the warm colour.
    pub y: f64,
    /// Share of the object colour in the cool tone.
    pub alpha: f64,
    /// Share of the object colour in the warm tone.
    pub beta: f64,
}

impl Default for GoochParams {
    fn default() -> GoochParams {
        GoochParams {
            b: 0.55,
            y: 0.3,
            alpha: 0.25,
            beta: 0.5,
        }
    }
}

/// What a pixel shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RenderMode {
    /// The shading model's colour.
    Shaded,
    /// `(N + 1) / 2` of the first hit, background black.
    Normal,
    /// Distance along the ray mapped to grey: near white, far black.
    Depth(DepthRange),
    /// The first hit's surface coordinates as a colour: red = frac(u), green = frac(v), blue 0;
    /// misses black (for checking texture mappings and `.uv()` patterns).
    Uv,
}

impl RenderMode {
    /// Whether the mode reads surface coordinates (so the world computes them at every hit,
    /// as it does for textures).
    pub(crate) fn reads_uv(self) -> bool {
        matches!(self, RenderMode::Uv)
    }

    /// The modes a scene names without parameters, by their names in the language (`depth`
    /// takes a range and is a function of its own).
    pub(crate) const NAMED: &'static [(&'static str, RenderMode)] = &[
        ("shaded", RenderMode::Shaded),
        ("normal", RenderMode::Normal),
        ("uv", RenderMode::Uv),
    ];
}

/// The distance range of a depth image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DepthRange {
    /// The nearest and farthest hit distances in the image.
    Auto,
    /// Fixed distances: `near` is white, `far` is black.
    Fixed {
        /// Distance shown white.
        near: f64,
        /// Distance shown black.
        far: f64,
    },
}

/// Pixel sampling.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Sampling {
    /// A regular f×f grid at ((i+½)/f, (j+½)/f), averaged.
    Grid {
        /// Samples per axis (≥ 1).
        factor: u32,
    },
    /// Start with `min` samples per axis and refine to `max` where neighbours differ by > threshold.
    Adaptive {
        /// Initial samples per axis.
        min: u32,
        /// Maximum samples per axis.
        max: u32,
        /// Colour difference that triggers refinement.
        threshold: f64,
    },
}

impl Sampling {
    /// Camera samples a pixel takes at most (adaptive: its `max` grid).
    pub(crate) fn max_per_pixel(&self) -> u32 {
        match *self {
            Sampling::Grid { factor } => factor * factor,
            Sampling::Adaptive { max, .. } => max * max,
        }
    }
}

/// How Phong's ambient term is counted (COURSE.md §2.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AmbientConvention {
    /// `ka·C·Lc` for every light (convention A, the default).
    PerLight,
    /// `ka·C` once, without light colour (convention B).
    Once,
}
