//! The quality knobs `rtc accuracy` sweeps, their ladders, the reference setting and how a
//! setting reads as a `render { ... }` block.
//!
//! Adding a knob is one
//! variant of [`Knob`] with its arm in [`Knob::name`], [`Knob::key`], [`Knob::ladder`] and
//! [`used_knobs`], one field of [`Setting`] (with its arm in [`Setting::apply`],
//! [`Setting::render_block`] and [`reference_setting`]); the sweep, the joint product, the
//! report and the plot take every knob the same way.

use crate::diag::Diagnostic;
use crate::ir::limits::MAX_BOUNCES;
use crate::ir::limits::{
    MAX_DEPTH, MAX_GLOSS_SAMPLES, MAX_LIGHT_SAMPLES_PER_AXIS, MAX_PIXEL_SAMPLES_PER_AXIS,
};
use crate::ir::{Integrator, LANGUAGE_CUTOFF, PathTracing, Sampling};
use crate::opt::{Effects, Prepared, Quality};

/// A quality knob: one dimension of the sweep.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Knob {
    /// Pixel samples: a regular f×f grid per pixel (antialiasing; with a lens, the lens samples).
    PixelSamples,
    /// The threshold of adaptive supersampling, between the scene's `min` and `max`; a scene
    /// on a uniform f×f grid is offered `adaptive(min: 1, max: f + 1)` (docs/convergence.md: a
    /// grid finer than the uniform one where it refines is what makes adaptive pay).
    AdaptiveThreshold,
    /// Samples per edge of every area light (soft shadows).
    LightSamples,
    /// Rays per glossy lobe at a camera ray's hit (`gloss_samples` of every glossy material).
    GlossSamples,
    /// Reflection/refraction bounces.
    MaxDepth,
    /// The insignificance cut-off: secondary rays lighter than it are not traced.
    Cutoff,
    /// The path tracer's paths per camera ray (`path(samples: n)`).
    PathSamples,
    /// The path tracer's bounces (`path(bounces: n)`).
    Bounces,
    /// The bounce from which the path tracer's Russian roulette may end a path.
    Roulette,
}

impl Knob {
    /// Every knob, in report order.
    const ALL: [Knob; 9] = [
        Knob::PixelSamples,
        Knob::AdaptiveThreshold,
        Knob::LightSamples,
        Knob::GlossSamples,
        Knob::MaxDepth,
        Knob::Cutoff,
        Knob::PathSamples,
        Knob::Bounces,
        Knob::Roulette,
    ];

    /// The name in tables and plot legends.
    pub fn name(self) -> &'static str {
        match self {
            Knob::PixelSamples => "pixel samples",
            Knob::AdaptiveThreshold => "adaptive threshold",
            Knob::LightSamples => "light samples",
            Knob::GlossSamples => "gloss samples",
            Knob::MaxDepth => "max depth",
            Knob::Cutoff => "cut-off",
            Knob::PathSamples => "path samples",
            Knob::Bounces => "bounces",
            Knob::Roulette => "roulette",
        }
    }

    /// The name in JSON.
    pub(crate) fn key(self) -> &'static str {
        match self {
            Knob::PixelSamples => "pixel_samples",
            Knob::AdaptiveThreshold => "adaptive_threshold",
            Knob::LightSamples => "light_samples",
            Knob::GlossSamples => "gloss_samples",
            Knob::MaxDepth => "max_depth",
            Knob::Cutoff => "cutoff",
            Knob::PathSamples => "path_samples",
            Knob::Bounces => "bounces",
            Knob::Roulette => "roulette",
        }
    }

    /// The ladder: `base` (the scene's own setting) with this knob alone stepped from cheap to
    /// dear. Every rung costs less than the reference (see the `REFERENCE_*` constants).
    pub(crate) fn ladder(self, base: &Setting) -> Vec<Setting> {
        match self {
            Knob::PixelSamples => PIXEL_LADDER
                .iter()
                .map(|&factor| Setting {
                    sampling: Sampling::Grid { factor },
                    ..*base
                })
                .collect(),
            Knob::AdaptiveThreshold => {
                let (min, max) = match base.sampling {
                    Sampling::Adaptive { min, max, .. } => (min, max),
                    Sampling::Grid { factor } => (1, (factor + 1).min(MAX_PIXEL_SAMPLES_PER_AXIS)),
                };
                THRESHOLD_LADDER
                    .iter()
                    .map(|&threshold| Setting {
                        sampling: Sampling::Adaptive {
                            min,
                            max,
                            threshold,
                        },
                        ..*base
                    })
                    .collect()
            }
            Knob::LightSamples => LIGHT_LADDER
                .iter()
                .map(|&n| Setting {
                    light_samples: Some(n),
                    ..*base
                })
                .collect(),
            Knob::GlossSamples => GLOSS_LADDER
                .iter()
                .map(|&n| Setting {
                    gloss_samples: Some(n),
                    ..*base
                })
                .collect(),
            Knob::MaxDepth => DEPTH_LADDER
                .iter()
                .map(|&max_depth| Setting { max_depth, ..*base })
                .collect(),
            Knob::Cutoff => CUTOFF_LADDER
                .iter()
                .map(|&cutoff| Setting { cutoff, ..*base })
                .collect(),
            Knob::PathSamples => PATH_SAMPLES_LADDER
                .iter()
                .filter_map(|&samples| base.with_path(|p| PathTracing { samples, ..p }))
                .collect(),
            Knob::Bounces => BOUNCES_LADDER
                .iter()
                .filter_map(|&bounces| base.with_path(|p| PathTracing { bounces, ..p }))
                .collect(),
            Knob::Roulette => ROULETTE_LADDER
                .iter()
                .filter_map(|&roulette| base.with_path(|p| PathTracing { roulette, ..p }))
                .collect(),
        }
    }
}

/// Pixel grid factors swept (samples per axis); the reference uses [`REFERENCE_PIXEL_SAMPLES`].
pub const PIXEL_LADDER: [u32; 6] = [1, 2, 3, 4, 6, 8];
/// Adaptive thresholds swept (the scene's `min` and `max` kept), coarse to fine.
const THRESHOLD_LADDER: [f64; 6] = [0.2, 0.1, 0.05, 0.02, 0.01, 0.005];
/// Area-light samples per edge swept; the reference uses [`REFERENCE_LIGHT_SAMPLES`].
const LIGHT_LADDER: [u32; 5] = [1, 2, 3, 4, 6];
/// Bounces swept; the reference uses [`REFERENCE_MAX_DEPTH`].
const DEPTH_LADDER: [u32; 7] = [0, 1, 2, 3, 4, 6, 8];
/// Rays per glossy lobe swept; the reference uses [`REFERENCE_GLOSS_SAMPLES`].
const GLOSS_LADDER: [u32; 5] = [1, 2, 4, 8, 16];
/// Cut-offs swept, from cheap (large: more rays dropped) to 0 (every ray traced, the
/// reference's): about three steps per decade, with the language's default
/// [`LANGUAGE_CUTOFF`] (≈ 3.0e-4, half an sRGB level at black) among them.
pub const CUTOFF_LADDER: [f64; 7] = [0.1, 0.03, 0.01, 0.003, 0.001, LANGUAGE_CUTOFF, 0.0];

/// The path tracer's paths per camera ray swept; the reference uses [`REFERENCE_PATH_SAMPLES`].
const PATH_SAMPLES_LADDER: [u32; 6] = [1, 2, 4, 8, 16, 32];
/// The path tracer's bounces swept; the reference uses [`REFERENCE_BOUNCES`].
const BOUNCES_LADDER: [u32; 6] = [1, 2, 3, 4, 6, 8];
/// Roulette starts swept, from early (cheap, noisier) to late; the reference plays none.
const ROULETTE_LADDER: [u32; 5] = [0, 1, 2, 3, 5];
/// The reference's paths per camera ray, or the scene's own if more (at most 256, so that the
/// reference's 16×16 grid stays within the 2^16 paths a pixel may take).
const REFERENCE_PATH_SAMPLES: u32 = 16;
/// The reference's bounces, or the scene's own if more: Russian roulette ends most paths long
/// before, so the last bounces cost little.
const REFERENCE_BOUNCES: u32 = 64;

/// The reference's pixel grid: 16×16 = 256 samples per pixel (twice the ladder's top per axis),
/// or the scene's own if finer.
const REFERENCE_PIXEL_SAMPLES: u32 = 16;
/// The reference's area-light samples per edge, or the scene's own if more. Every camera sample
/// draws its own light samples, so with 16×16 pixel samples each reference pixel averages
/// 256 × 16 = 4096 shadow samples per light: 7× the ladder's dearest rung at the scene's own
/// 4×4 pixel grid (16 × 36). More costs minutes per reference on a soft-shadow scene.
const REFERENCE_LIGHT_SAMPLES: u32 = 4;
/// The reference's rays per glossy lobe, or the scene's own if more: the ladder's top. Each of
/// the reference's 256 camera samples per pixel draws its own lobe, so a reference pixel
/// averages 256 × 16 = 4096 lobe rays: 16× the top rung at the scene's 4×4 grid.
const REFERENCE_GLOSS_SAMPLES: u32 = 16;
/// The reference's bounces: twice the ladder's top (a 16th bounce weighs at most the product of
/// 16 reflect/refract coefficients), or the scene's own if more.
const REFERENCE_MAX_DEPTH: u32 = 16;

/// One point of a sweep: every knob's value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Setting {
    /// Pixel sampling.
    pub(crate) sampling: Sampling,
    /// Bounces.
    pub(crate) max_depth: u32,
    /// Samples per edge of every area light; `None` keeps each light's own.
    pub light_samples: Option<u32>,
    /// Rays per glossy lobe of every material; `None` keeps each material's own.
    pub gloss_samples: Option<u32>,
    /// The insignificance cut-off.
    pub cutoff: f64,
    /// The integrator, with the path tracer's samples and bounces.
    pub(crate) integrator: Integrator,
}

impl Setting {
    /// The scene's own setting (as prepared).
    pub(crate) fn of(scene: &Prepared) -> Setting {
        Setting {
            sampling: scene.settings().sampling,
            max_depth: scene.settings().max_depth,
            light_samples: None,
            gloss_samples: None,
            cutoff: scene.settings().cutoff,
            integrator: scene.settings().integrator,
        }
    }

    /// This setting with the path tracer's settings changed by `f`; `None` for Whitted.
    fn with_path(&self, f: impl Fn(PathTracing) -> PathTracing) -> Option<Setting> {
        match self.integrator {
            Integrator::Path(p) => Some(Setting {
                integrator: Integrator::Path(f(p)),
                ..*self
            }),
            Integrator::Whitted => None,
        }
    }

    /// Renders `scene` from now on with this setting; `own_lights` holds each light's own
    /// samples per edge (what `light_samples: None` keeps).
    pub(crate) fn apply(
        &self,
        scene: &mut Prepared,
        own_lights: &[[u32; 2]],
    ) -> Result<(), Diagnostic> {
        scene.set_quality(Quality {
            sampling: self.sampling,
            max_depth: self.max_depth,
            cutoff: self.cutoff,
            gloss_samples: self.gloss_samples,
            integrator: self.integrator,
        })?;
        match self.light_samples {
            Some(n) => scene.set_light_samples(&vec![[n, n]; own_lights.len()]),
            None => scene.set_light_samples(own_lights),
        }
    }

    /// Camera samples per pixel at most (adaptive: its `max` grid).
    pub fn pixel_samples(&self) -> u32 {
        self.sampling.max_per_pixel()
    }

    /// A short label: `grid 4, depth 2, light 3, gloss 8, cutoff 1.0e-2` (the cut-off only
    /// when it is not the language's default).
    pub fn label(&self) -> String {
        let mut parts = vec![match self.sampling {
            Sampling::Grid { factor } => format!("grid {factor}"),
            Sampling::Adaptive {
                min,
                max,
                threshold,
            } => format!("adaptive {min}-{max} t{threshold}"),
        }];
        match self.integrator {
            Integrator::Path(p) if p.roulette >= p.bounces => parts.push(format!(
                "paths {}, bounces {}, no roulette",
                p.samples, p.bounces
            )),
            Integrator::Path(p) => parts.push(format!(
                "paths {}, bounces {}, roulette {}",
                p.samples, p.bounces, p.roulette
            )),
            Integrator::Whitted => parts.push(format!("depth {}", self.max_depth)),
        }
        if let Some(n) = self.light_samples {
            parts.push(format!("light {n}"));
        }
        if let Some(n) = self.gloss_samples {
            parts.push(format!("gloss {n}"));
        }
        // The cut-off is Whitted's: the path tracer ignores it.
        if self.cutoff != LANGUAGE_CUTOFF && self.integrator == Integrator::Whitted {
            parts.push(format!("cutoff {:.1e}", self.cutoff));
        }
        parts.join(", ")
    }

    /// The setting as the fields of a `render { ... }` block (docs/language.md §19), `cutoff`
    /// only when it is not the language's default, with the area lights' `samples:` and the
    /// glossy materials' `gloss_samples:` in a comment when the setting changes them (they are
    /// fields of each `area_light` and `material`, not of `render`).
    pub fn render_block(&self) -> String {
        let sampling = match self.sampling {
            Sampling::Grid { factor } => format!("supersampling: {factor}"),
            Sampling::Adaptive {
                min,
                max,
                threshold,
            } => format!("supersampling: adaptive(min: {min}, max: {max}, threshold: {threshold})"),
        };
        let cutoff = if self.cutoff == LANGUAGE_CUTOFF {
            String::new()
        } else {
            format!(", cutoff: {}", self.cutoff)
        };
        let mut block = match self.integrator {
            Integrator::Path(p) => format!(
                "render {{ {sampling}, integrator: path(samples: {}, bounces: {}, roulette: {}) }}",
                p.samples, p.bounces, p.roulette
            ),
            Integrator::Whitted => format!(
                "render {{ {sampling}, max_depth: {}{cutoff} }}",
                self.max_depth
            ),
        };
        let mut also = Vec::new();
        if let Some(n) = self.light_samples {
            also.push(format!("every area_light {{ samples: {n} }}"));
        }
        if let Some(n) = self.gloss_samples {
            also.push(format!("every glossy material {{ gloss_samples: {n} }}"));
        }
        if !also.is_empty() {
            block += &format!("  // and {}", also.join(", "));
        }
        block
    }
}

/// The knobs `effects` says the scene uses: pixel samples and adaptive sampling always (every
/// image has edges; with a lens they are also the lens samples), light samples with soft shadows, gloss samples with a glossy material, bounces
/// and the cut-off with reflection or refraction. Under the path tracer gloss samples, bounces
/// and the cut-off are Whitted's and change nothing, so they are not swept (pixel samples then
/// multiply the paths per pixel).
pub(crate) fn used_knobs(effects: &Effects) -> Vec<Knob> {
    let whitted = !effects.global_illumination;
    Knob::ALL
        .into_iter()
        .filter(|k| match k {
            Knob::PixelSamples => true,
            Knob::AdaptiveThreshold => true,
            Knob::LightSamples => effects.soft_shadows,
            Knob::GlossSamples => whitted && effects.glossy,
            Knob::MaxDepth | Knob::Cutoff => whitted && (effects.reflection || effects.refraction),
            Knob::PathSamples | Knob::Bounces | Knob::Roulette => !whitted,
        })
        .collect()
}

/// The converged setting the sweep is measured against: every used knob set high (the
/// `REFERENCE_*` constants, or the scene's own where it is higher; the cut-off at 0), the rest
/// at the scene's. `own_light_samples` and `own_gloss_samples` are the scene's largest.
pub(crate) fn reference_setting(
    knobs: &[Knob],
    own: &Setting,
    own_light_samples: u32,
    own_gloss_samples: u32,
) -> Setting {
    let mut r = *own;
    for k in knobs {
        match k {
            Knob::PixelSamples | Knob::AdaptiveThreshold => {
                let factor = REFERENCE_PIXEL_SAMPLES
                    .max(own.pixel_samples().isqrt())
                    .min(MAX_PIXEL_SAMPLES_PER_AXIS);
                r.sampling = Sampling::Grid { factor };
            }
            Knob::LightSamples => {
                r.light_samples = Some(
                    REFERENCE_LIGHT_SAMPLES
                        .max(own_light_samples)
                        .min(MAX_LIGHT_SAMPLES_PER_AXIS),
                );
            }
            Knob::GlossSamples => {
                r.gloss_samples = Some(
                    REFERENCE_GLOSS_SAMPLES
                        .max(own_gloss_samples)
                        .min(MAX_GLOSS_SAMPLES),
                );
            }
            Knob::MaxDepth => r.max_depth = REFERENCE_MAX_DEPTH.max(own.max_depth).min(MAX_DEPTH),
            Knob::Cutoff => r.cutoff = 0.0,
            Knob::PathSamples => {
                if let Some(s) = r.with_path(|p| PathTracing {
                    samples: REFERENCE_PATH_SAMPLES.max(p.samples).min(256),
                    ..p
                }) {
                    r = s;
                }
            }
            Knob::Bounces => {
                if let Some(s) = r.with_path(|p| PathTracing {
                    bounces: REFERENCE_BOUNCES.max(p.bounces).min(MAX_BOUNCES),
                    ..p
                }) {
                    r = s;
                }
            }
            // No roulette: the reference's paths end only at its bounces.
            Knob::Roulette => {
                if let Some(s) = r.with_path(|p| PathTracing {
                    roulette: MAX_BOUNCES,
                    ..p
                }) {
                    r = s;
                }
            }
        }
    }
    r
}

/// The joint sweep: the product of three rungs (cheapest, middle, dearest) of each knob's
/// ladder, the sampling knobs sharing one dimension; the cut-off and the gloss samples stay at
/// the scene's own (two more dimensions would make the product nine times longer; their
/// ladders are measured alone). Its points with the ladders' give the Pareto front.
pub(crate) fn joint_settings(knobs: &[Knob], own: &Setting) -> Vec<Setting> {
    let three = |ladder: Vec<Setting>| -> Vec<Setting> {
        if ladder.len() <= 3 {
            return ladder;
        }
        vec![
            ladder[0],
            ladder[ladder.len() / 2],
            ladder[ladder.len() - 1],
        ]
    };
    let mut sampling: Vec<Sampling> = Vec::new();
    for k in [Knob::PixelSamples, Knob::AdaptiveThreshold] {
        if knobs.contains(&k) {
            sampling.extend(three(k.ladder(own)).iter().map(|s| s.sampling));
        }
    }
    let lights: Vec<Option<u32>> = if knobs.contains(&Knob::LightSamples) {
        three(Knob::LightSamples.ladder(own))
            .iter()
            .map(|s| s.light_samples)
            .collect()
    } else {
        vec![own.light_samples]
    };
    let depths: Vec<u32> = if knobs.contains(&Knob::MaxDepth) {
        three(Knob::MaxDepth.ladder(own))
            .iter()
            .map(|s| s.max_depth)
            .collect()
    } else {
        vec![own.max_depth]
    };
    let mut out = Vec::new();
    for &sampling in &sampling {
        for &light_samples in &lights {
            for &max_depth in &depths {
                out.push(Setting {
                    sampling,
                    max_depth,
                    light_samples,
                    ..*own
                });
            }
        }
    }
    out
}

#[cfg(test)]
mod used_tests {
    use super::*;

    #[test]
    fn the_path_tracer_is_not_offered_whitteds_knobs() {
        let whitted = Effects {
            reflection: true,
            glossy: true,
            soft_shadows: true,
            ..Effects::default()
        };
        assert_eq!(used_knobs(&whitted), Knob::ALL[..6].to_vec());
        let path = Effects {
            global_illumination: true,
            ..whitted
        };
        assert_eq!(
            used_knobs(&path),
            vec![
                Knob::PixelSamples,
                Knob::AdaptiveThreshold,
                Knob::LightSamples,
                Knob::PathSamples,
                Knob::Bounces,
                Knob::Roulette
            ]
        );
    }

    #[test]
    fn the_path_ladders_step_samples_and_bounces_and_only_under_the_path_tracer() {
        let whitted = Setting {
            sampling: Sampling::Grid { factor: 2 },
            max_depth: 5,
            light_samples: None,
            gloss_samples: None,
            cutoff: 0.0,
            integrator: Integrator::Whitted,
        };
        assert!(Knob::PathSamples.ladder(&whitted).is_empty());
        assert!(Knob::Bounces.ladder(&whitted).is_empty());
        let path = Setting {
            integrator: Integrator::Path(PathTracing::DEFAULT),
            ..whitted
        };
        let samples: Vec<u32> = Knob::PathSamples
            .ladder(&path)
            .iter()
            .map(|s| match s.integrator {
                Integrator::Path(p) => p.samples,
                Integrator::Whitted => 0,
            })
            .collect();
        assert_eq!(samples, PATH_SAMPLES_LADDER.to_vec());
        let knobs = [Knob::PathSamples, Knob::Bounces, Knob::Roulette];
        let r = reference_setting(&knobs, &path, 1, 1);
        assert_eq!(
            r.integrator,
            Integrator::Path(PathTracing {
                samples: REFERENCE_PATH_SAMPLES,
                bounces: REFERENCE_BOUNCES,
                roulette: MAX_BOUNCES,
            })
        );
        assert_eq!(Knob::Roulette.ladder(&path).len(), ROULETTE_LADDER.len());
        assert_eq!(
            path.render_block(),
            "render { supersampling: 2, integrator: path(samples: 16, bounces: 16, roulette: 3) }"
        );
    }
}
