//! The recording hook of the Whitted integrator and the shading models (`rtc why`): what a
//! traced ray met, how each light contributed and which secondary rays it spawned.
//!
//! The integrator is generic over a [`Recorder`]; an ordinary render passes [`NoRecord`], whose
//! `ON` is `false`, so every recording statement (guarded by `if R::ON`) is removed when the
//! code is monomorphised: the render path pays nothing, in time or in bytes.

use crate::geometry::{Ray, SurfaceHit};
use crate::ir::Color;

use super::path::Path;
use super::scatter::Lobe;

/// How a traced ray came about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Branch {
    /// From the camera.
    Camera,
    /// Mirror reflection (the material's `reflect`, plus `refract` under total internal
    /// reflection).
    Reflected,
    /// Refraction (the material's `refract`).
    Refracted,
}

impl Branch {
    /// The branch of a secondary ray drawn from `lobe`.
    pub(crate) fn of(lobe: &Lobe) -> Branch {
        if lobe.transmits() {
            Branch::Refracted
        } else {
            Branch::Reflected
        }
    }

    /// The word for it in explanations.
    pub fn name(self) -> &'static str {
        match self {
            Branch::Camera => "camera",
            Branch::Reflected => "reflected",
            Branch::Refracted => "refracted",
        }
    }
}

/// One light's share of a shaded point, summed over the light's samples (area lights).
///
/// Phong: `ambient = ka·C·Lc` (per light), `diffuse = kd·max(0,N·L)·C·Lc`, `specular =
/// ks·max(0,R·V)^n·Lc`. Gooch: `diffuse` is the cool-to-warm tone, `specular` the highlight.
/// Hatching: `ambient` and `diffuse` are the grey tone inputs (the stroke density follows
/// from their sum), `specular` is zero.
#[derive(Clone, Debug, PartialEq)]
pub struct LightTerm {
    /// Index of the light in the scene.
    pub light: usize,
    /// Ambient term.
    pub ambient: Color,
    /// Diffuse term (Gooch: the tone).
    pub diffuse: Color,
    /// Specular highlight.
    pub specular: Color,
    /// Samples taken of the light (1 for a point light).
    pub samples: u32,
    /// Samples that faced away from the surface (N·L ≤ 0): no diffuse, no highlight.
    pub behind: u32,
    /// Samples blocked by something opaque.
    pub blocked: u32,
    /// Samples that reached the surface through glass (`glass_shadows`), tinted.
    pub tinted: u32,
    /// The first opaque surface found blocking the light, if any sample was blocked.
    pub(crate) occluder: Option<SurfaceHit>,
}

impl LightTerm {
    /// An empty term for light `light`.
    pub(crate) fn new(light: usize) -> LightTerm {
        LightTerm {
            light,
            ambient: Color::ZERO,
            diffuse: Color::ZERO,
            specular: Color::ZERO,
            samples: 0,
            behind: 0,
            blocked: 0,
            tinted: 0,
            occluder: None,
        }
    }
}

/// Receives the events of one trace. Every method has an empty default; `ON` tells the
/// integrator whether to compute what only a recorder reads (it is `false` for [`NoRecord`]).
pub(crate) trait Recorder {
    /// Whether anything is recorded (guards the work that only feeds the recorder).
    const ON: bool;
    /// A ray is about to be traced for a path in state `path`.
    fn ray(&mut self, _ray: &Ray, _path: &Path) {}
    /// The ray hit `hit` (not called on a miss).
    fn hit(&mut self, _hit: &SurfaceHit) {}
    /// A light's contribution to the point just hit.
    fn light(&mut self, _term: LightTerm) {}
    /// The ambient term added once for the point (`ambient: once`).
    fn ambient(&mut self, _c: Color) {}
    /// The shading model's colour of the point (before reflection and refraction).
    fn local(&mut self, _c: Color) {}
    /// The next `rays` rays traced are this branch's, weighing `k` in total; `cut`: not traced
    /// because the path's weight fell under the cut-off.
    fn branch(&mut self, _b: Branch, _k: f64, _rays: u32, _cut: bool) {}
    /// Total internal reflection: the refracted share went to the reflected ray.
    fn total_internal_reflection(&mut self) {}
    /// The traced ray's colour (the last event of a ray).
    fn done(&mut self, _c: Color) {}
}

/// The recorder of ordinary renders: records nothing, costs nothing.
pub(crate) struct NoRecord;

impl Recorder for NoRecord {
    const ON: bool = false;
}
