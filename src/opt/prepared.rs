//! The prepared scene: what the preparation stage hands the renderer. It owns everything a
//! render reads (the world, the whole material table, decoded textures, lights, camera,
//! settings and the effects they call for), so one preparation serves any number of renders.

use std::time::Duration;

use super::effects::{Content, Effects};
use super::emitters::Emitter;
use super::textures::TextureMap;
use super::validate;
use crate::diag::Diagnostic;
use crate::geometry::shapes::isosurface::Watch;
use crate::geometry::{Ray, SurfaceHit, World};
use crate::ir::{
    Camera, Color, Fade, Integrator, LightKind, Material, MaterialId, RenderSettings, Sampling,
    Spot, Visibility,
};

/// A light prepared for shading: sample positions are generated per shading point.
#[derive(Clone, Copy, Debug)]
pub struct PreparedLight {
    /// The IR geometry.
    pub kind: LightKind,
    /// RGB intensity.
    pub(crate) color: Color,
    /// Number of shadow/shading samples (1 for a point light).
    pub samples: u32,
    /// A spot light's cone.
    pub(crate) spot: Option<Spot>,
    /// Fading with distance.
    pub(crate) fade: Option<Fade>,
    /// Whether objects cast shadows from it.
    pub(crate) shadows: bool,
}

impl PreparedLight {
    /// Whether it is a plain point light: no cone, no fading, casting shadows (what the packet
    /// shader handles).
    pub(crate) fn is_plain_point(&self) -> bool {
        matches!(self.kind, LightKind::Point { .. })
            && self.spot.is_none()
            && self.fade.is_none()
            && self.shadows
    }
}

/// What preparing took (`rtc render --stats`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stats {
    /// Top-level objects.
    pub objects: usize,
    /// Objects outside the BVH (unbounded).
    pub unbounded: usize,
    /// Distinct mesh files placed.
    pub meshes: usize,
    /// Triangles stored (each file once).
    pub unique_triangles: usize,
    /// Triangles in the scene counting every instance.
    pub instanced_triangles: usize,
    /// Time the whole preparation took (mesh loading included).
    pub build_time: Duration,
    /// Time spent building BVHs (top level and meshes).
    pub bvh_build_time: Duration,
    /// Time mesh files took to read and their BVHs to build, wherever it happened: a mesh
    /// whose `.bounds` the scene asked for was read while evaluating it.
    pub mesh_load_time: Duration,
    /// Approximate heap bytes of the geometry and BVHs.
    pub memory_bytes: usize,
}

/// A scene ready to render (made by [`super::prepare`]).
pub struct Prepared {
    pub(super) camera: Camera,
    pub(super) world: World,
    pub(super) materials: Vec<Material>,
    pub(super) textures: Vec<TextureMap>,
    pub(super) lights: Vec<PreparedLight>,
    pub(super) emitters: Vec<Emitter>,
    pub(super) settings: RenderSettings,
    pub(super) content: Content,
    pub(super) effects: Effects,
    pub(super) warnings: Vec<Diagnostic>,
    /// Every isosurface's gradient bound and search counts, by its object's span.
    pub(super) isosurfaces: Vec<(crate::source::Span, Watch)>,
    pub(super) stats: Stats,
    /// Which rays see each top-level object, by its index; empty when every ray sees every
    /// object (the common case costs nothing).
    pub(super) visibility: Vec<Visibility>,
    /// Each material's own `gloss_samples`, what [`Quality::gloss_samples`] `None` restores.
    pub(super) own_gloss_samples: Vec<u32>,
}

/// The settings a render may change on a prepared scene: how many samples and bounces, the
/// insignificance cut-off and the rays of every glossy lobe.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quality {
    /// Pixel sampling.
    pub sampling: Sampling,
    /// Reflection/refraction bounces.
    pub max_depth: u32,
    /// The insignificance cut-off (`render { cutoff }`).
    pub cutoff: f64,
    /// Rays per glossy lobe of every material; `None` keeps each material's own.
    pub gloss_samples: Option<u32>,
    /// How a camera ray's light is found (the path tracer's samples and bounces).
    pub integrator: Integrator,
}

impl Quality {
    /// The scene's own quality (each material keeping its own `gloss_samples`).
    pub fn of(settings: &RenderSettings) -> Quality {
        Quality {
            sampling: settings.sampling,
            max_depth: settings.max_depth,
            cutoff: settings.cutoff,
            gloss_samples: None,
            integrator: settings.integrator,
        }
    }
}

impl Prepared {
    /// The validated camera.
    pub fn camera(&self) -> &Camera {
        &self.camera
    }

    /// The intersection structure.
    pub fn world(&self) -> &World {
        &self.world
    }

    /// The nearest hit along `ray` in (`t_min`, `t_max`) on an object rays of the kind `kind`
    /// see (objects hidden from them are passed through, POV-Ray's `no_image` and
    /// `no_reflection`); [`World::intersect`] when no object is hidden.
    pub fn seen_hit(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        kind: Visibility,
    ) -> Option<SurfaceHit> {
        let mut hit = self.world.intersect(ray, t_min, t_max)?;
        while self.hides(&hit, kind) {
            let next = self.world.intersect(ray, hit.t, t_max)?;
            // The interval is open, so `t` grows; a hit that did not move would loop forever.
            if next.t <= hit.t {
                return None;
            }
            hit = next;
        }
        Some(hit)
    }

    /// Whether anything that casts shadows lies in (`t_min`, `t_max`) along `ray`.
    pub fn shadowed(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        if self.visibility.is_empty() {
            self.world.occluded(ray, t_min, t_max)
        } else {
            self.seen_hit(ray, t_min, t_max, Visibility::NO_SHADOW)
                .is_some()
        }
    }

    /// Whether the object of `hit` is hidden from rays of the kind `kind`.
    pub fn hides(&self, hit: &SurfaceHit, kind: Visibility) -> bool {
        !self.visibility.is_empty()
            && self
                .visibility
                .get(self.world.object(hit) as usize)
                .is_some_and(|v| v.hides(kind))
    }

    /// The material behind a hit's id: the scene's, the fallback for objects that name none,
    /// then every placed mesh's MTL materials.
    pub fn material(&self, id: MaterialId) -> &Material {
        &self.materials[id.0 as usize]
    }

    /// The whole material table.
    pub fn materials(&self) -> &[Material] {
        &self.materials
    }

    /// Decoded textures by `TextureId`.
    pub(crate) fn textures(&self) -> &[TextureMap] {
        &self.textures
    }

    /// The lights.
    pub fn lights(&self) -> &[PreparedLight] {
        &self.lights
    }

    /// The glowing spheres and quads the path tracer samples (empty for a Whitted scene).
    pub fn emitters(&self) -> &[Emitter] {
        &self.emitters
    }

    /// The render settings.
    pub fn settings(&self) -> &RenderSettings {
        &self.settings
    }

    /// Which costly effects the scene and its settings call for.
    pub fn effects(&self) -> Effects {
        self.effects
    }

    /// Warnings found while preparing (a mesh whose MTL file is missing).
    pub fn warnings(&self) -> &[Diagnostic] {
        &self.warnings
    }

    /// What the renders of this scene so far found about its isosurfaces: steps where a
    /// function changed faster than its `max_gradient`, and searches stopped by the budget of
    /// evaluations per ray (docs/language.md §13.9). Empty when all went well.
    pub fn render_warnings(&self) -> Vec<Diagnostic> {
        self.isosurfaces
            .iter()
            .flat_map(|(span, w)| w.report(*span))
            .collect()
    }

    /// What preparing took.
    pub fn stats(&self) -> Stats {
        self.stats
    }

    /// Whether anything draws random numbers (a lens, an area light, an open shutter, a
    /// glossy lobe or the path tracer).
    pub fn random(&self) -> bool {
        self.effects.global_illumination
            || self.camera.aperture > 0.0
            || self.effects.motion_blur
            || self.effects.glossy
            || self
                .lights
                .iter()
                .any(|l| matches!(l.kind, LightKind::Area { .. }))
    }

    /// Renders from now on with other samples, bounces, cut-off and glossy rays (`rtc
    /// accuracy` prepares once and renders at many qualities); the effects follow. Errors when
    /// past `ir::limits` or out of range (nothing changes then).
    pub fn set_quality(&mut self, q: Quality) -> Result<(), Diagnostic> {
        let settings = RenderSettings {
            sampling: q.sampling,
            max_depth: q.max_depth,
            cutoff: q.cutoff,
            integrator: q.integrator,
            ..self.settings.clone()
        };
        validate::settings(&settings)?;
        if let Some(n) = q.gloss_samples {
            validate::gloss_samples(n)?;
        }
        for (m, &own) in self.materials.iter_mut().zip(&self.own_gloss_samples) {
            m.gloss_samples = q.gloss_samples.unwrap_or(own);
        }
        self.effects = Effects::new(&self.content, &settings, &self.camera);
        self.settings = settings;
        Ok(())
    }

    /// Replaces the camera (a coarser preview of the same view, `rtc watch`): validated like
    /// the scene's, and the effects follow it.
    pub fn set_camera(&mut self, camera: Camera) -> Result<(), Diagnostic> {
        validate::camera(&camera)?;
        self.effects = Effects::new(&self.content, &self.settings, &camera);
        self.camera = camera;
        Ok(())
    }
}

impl Prepared {
    /// Each light's samples per edge (`[1, 1]` for a point light), in light order.
    pub(crate) fn light_samples(&self) -> Vec<[u32; 2]> {
        self.lights
            .iter()
            .map(|l| match l.kind {
                LightKind::Area { samples, .. } => samples,
                LightKind::Point { .. }
                | LightKind::Parallel { .. }
                | LightKind::Cylinder { .. } => [1, 1],
            })
            .collect()
    }

    /// Renders from now on with `samples[i]` samples per edge on area light `i` (point lights
    /// ignore theirs; `rtc accuracy` sweeps this). Errors when past `ir::limits` or when the
    /// list does not have one entry per light.
    pub(crate) fn set_light_samples(&mut self, samples: &[[u32; 2]]) -> Result<(), Diagnostic> {
        if samples.len() != self.lights.len() {
            return Err(Diagnostic::new(
                crate::diag::Severity::Error,
                "rtc::render::limit",
                None,
                format!(
                    "{} light sample counts for {} lights",
                    samples.len(),
                    self.lights.len()
                ),
            ));
        }
        for (light, &want) in self.lights.iter_mut().zip(samples) {
            if let LightKind::Area { samples, .. } = &mut light.kind {
                validate::light_samples(want)?;
                *samples = want;
                light.samples = want[0].max(1) * want[1].max(1);
            }
        }
        Ok(())
    }

    /// Renders from now on with another seed (`rtc accuracy` measures noise from two).
    pub(crate) fn set_seed(&mut self, seed: u64) {
        self.settings.seed = seed;
    }
}
