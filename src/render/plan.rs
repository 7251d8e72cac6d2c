//! The render plan: everything prepared once per render (world, camera, textures, lights, the
//! effects the scene calls for) and shared read-only by every tile.

use glam::DVec3;

use super::camera::Camera;
use super::sampler::PixelSampler;
use super::texture::{self, Loaded};
use crate::diag::{Diagnostic, Severity};
use crate::geometry::World;
use crate::ir::limits::{
    MAX_DEPTH, MAX_LIGHT_SAMPLES_PER_AXIS, MAX_PIXEL_SAMPLES_PER_AXIS, MAX_PIXELS,
};
use crate::ir::{
    AmbientConvention, Color, LightKind, Material, MaterialId, RenderMode, Sampling, Scene,
    ShadingModel,
};
use crate::opt::Effects;

/// Relative size of the offset along the normal that starts shadow, reflected and refracted rays,
/// so they do not re-hit the surface they leave: `EPS_REL · max(|P|∞, scene extent)`. Scaling with
/// the coordinates keeps it above the rounding error of a hit point (about 1e-16·|P|) at any scale,
/// from millimetre scenes to the astronomical blue-earth scene (|P| ≈ 1.5e8 → 15 units).
pub const EPS_REL: f64 = 1e-9;

/// A light prepared for shading: sample positions are generated per shading point.
#[derive(Clone, Copy, Debug)]
pub struct LightPlan {
    /// The IR geometry.
    pub kind: LightKind,
    /// RGB intensity.
    pub color: Color,
    /// Number of shadow/shading samples (1 for a point light).
    pub samples: u32,
}

/// Everything a tile needs, prepared once.
pub struct Plan<'a> {
    /// The scene being rendered.
    pub scene: &'a Scene,
    /// Intersection structure.
    pub world: World,
    /// Primary rays.
    pub camera: Camera,
    /// Which costly effects are in use.
    pub effects: Effects,
    /// The scene's materials plus the fallback for objects that name none.
    pub materials: Vec<Material>,
    /// Decoded textures by `TextureId`.
    pub textures: Vec<Loaded>,
    /// The lights.
    pub lights: Vec<LightPlan>,
    /// Pixel sampling.
    pub sampler: PixelSampler,
    /// Image mode.
    pub mode: RenderMode,
    /// Scene-wide shading model.
    pub shading: ShadingModel,
    /// Phong ambient convention.
    pub ambient: AmbientConvention,
    /// Reflection/refraction bounces.
    pub max_depth: u32,
    /// Colour of rays that miss (shaded mode only; buffers use black).
    pub background: Color,
    /// Whether anything draws random numbers (a lens or an area light).
    pub random: bool,
    /// Ray offset scale: `EPS_REL · scene extent`.
    eps_floor: f64,
}

impl<'a> Plan<'a> {
    /// Prepares a scene for rendering.
    pub fn new(scene: &'a Scene) -> Result<Plan<'a>, Diagnostic> {
        let s = &scene.settings;
        let mut materials = scene.materials.clone();
        let fallback = match s.default_material {
            Some(id) if (id.0 as usize) < materials.len() => id,
            _ => {
                materials.push(Material::default());
                MaterialId((materials.len() - 1) as u32)
            }
        };
        for o in &scene.objects {
            if let Some(id) = o
                .material
                .filter(|id| id.0 as usize >= scene.materials.len())
            {
                return Err(Diagnostic::error(
                    "rtc::render::material",
                    o.span,
                    format!("this object names material #{} which does not exist", id.0),
                )
                .with_label("this object"));
            }
        }
        for m in &scene.materials {
            let bad_texture = |t: Option<crate::ir::TextureId>| {
                t.is_some_and(|t| t.0 as usize >= scene.textures.len())
            };
            if bad_texture(m.texture) || bad_texture(m.bump.map(|b| b.texture)) {
                return Err(Diagnostic::error(
                    "rtc::render::texture",
                    m.span,
                    "this material names a texture that does not exist",
                )
                .with_label("this material"));
            }
        }
        check_limits(scene)?;
        let mut world = World::build(scene, fallback)?;
        // Mesh MTL materials get ids from `first_extra_material` on; line them up with ours.
        let base = world.first_extra_material().0 as usize;
        materials.resize_with(base.max(materials.len()), Material::default);
        materials.extend_from_slice(world.extra_materials());
        let camera = Camera::new(&scene.camera)?;
        let effects = Effects::of(scene);
        world.need_uv(effects.textures || effects.bump || effects.hatching);
        let textures = if effects.textures || effects.bump {
            texture::load_all(scene)?
        } else {
            Vec::new()
        };
        let lights = scene
            .lights
            .iter()
            .map(|l| LightPlan {
                kind: l.kind,
                color: l.color,
                samples: match l.kind {
                    LightKind::Point { .. } => 1,
                    // Both at most MAX_LIGHT_SAMPLES_PER_AXIS (check_limits), so no overflow.
                    LightKind::Area { samples, .. } => samples[0].max(1) * samples[1].max(1),
                },
            })
            .collect();
        let b = world.bounds();
        let extent = if b.is_empty() || !b.is_finite() {
            0.0
        } else {
            b.min.abs().max(b.max.abs()).max_element()
        };
        let extent = extent.max(scene.camera.eye.abs().max_element());
        Ok(Plan {
            scene,
            world,
            camera,
            effects,
            materials,
            textures,
            lights,
            sampler: PixelSampler::new(s.sampling),
            mode: s.mode,
            shading: s.shading,
            ambient: s.ambient,
            max_depth: s.max_depth,
            background: s.background,
            eps_floor: EPS_REL * extent,
            random: camera.has_lens()
                || scene
                    .lights
                    .iter()
                    .any(|l| matches!(l.kind, LightKind::Area { .. })),
        })
    }

    /// The offset along the normal for rays leaving point `p`.
    pub fn eps(&self, p: DVec3) -> f64 {
        (EPS_REL * p.abs().max_element())
            .max(self.eps_floor)
            .max(1e-300)
    }
}

/// Rejects settings that would overflow counters, exhaust memory or never finish.
fn check_limits(scene: &Scene) -> Result<(), Diagnostic> {
    let s = &scene.settings;
    let too_big = |what: String, help: String| {
        Err(Diagnostic::new(Severity::Error, "rtc::render::limit", None, what).with_help(help))
    };
    let pixels = u64::from(scene.camera.width) * u64::from(scene.camera.height);
    if pixels > MAX_PIXELS {
        return Err(Diagnostic::error(
            "rtc::render::limit",
            scene.camera.span,
            format!("the image has {pixels} pixels, more than the {MAX_PIXELS} rtc renders"),
        )
        .with_label("this camera")
        .with_help("render a smaller image, e.g. 4096×4096"));
    }
    if s.max_depth > MAX_DEPTH {
        return too_big(
            format!(
                "a recursion depth of {} is more than {MAX_DEPTH}",
                s.max_depth
            ),
            format!("use a max_depth of at most {MAX_DEPTH}"),
        );
    }
    let factor = match s.sampling {
        Sampling::Grid { factor } => factor,
        Sampling::Adaptive { min, max, .. } => min.max(max),
    };
    if factor > MAX_PIXEL_SAMPLES_PER_AXIS {
        return too_big(
            format!("{factor} samples per axis is more than {MAX_PIXEL_SAMPLES_PER_AXIS}"),
            format!("use at most {MAX_PIXEL_SAMPLES_PER_AXIS} samples per axis"),
        );
    }
    for l in &scene.lights {
        if let LightKind::Area { samples, .. } = l.kind
            && samples.iter().any(|n| *n > MAX_LIGHT_SAMPLES_PER_AXIS)
        {
            return Err(Diagnostic::error(
                "rtc::render::limit",
                l.span,
                format!(
                    "more than {MAX_LIGHT_SAMPLES_PER_AXIS} samples along an edge of this area light"
                ),
            )
            .with_label("this light")
            .with_help(format!(
                "use at most {MAX_LIGHT_SAMPLES_PER_AXIS} samples per edge"
            )));
        }
    }
    Ok(())
}
