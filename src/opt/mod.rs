//! The preparation stage: IR scene → [`Prepared`] scene, once per scene, before any ray.
//!
//! It validates the scene once (ids, camera, limits, every shape by `geometry::shapes`, CSG
//! operands, transforms), loads assets through the asset service (meshes, their MTL materials,
//! textures), shares each mesh file between the objects that place it (instancing), builds the
//! whole material table (the scene's, the fallback, then MTL materials), prepares lights,
//! computes the [`Effects`] the scene calls for, and builds the [`World`] with its BVH. The
//! renderer reads only the [`Prepared`] scene; `rtc check` runs the same preparation, so a clean
//! check means the render will start.

mod effects;
mod emitters;
pub mod fingerprint;
pub(crate) mod objects;
mod prepared;
pub(crate) mod textures;
mod validate;

use std::time::Instant;

use crate::diag::Diagnostics;
use crate::geometry::world::balls::WorldParts;
use crate::geometry::{World, world::instanced_triangles};
use crate::ir::{LightKind, Material, MaterialId, Object, Scene, Visibility};

pub(crate) use effects::Content;
pub use effects::Effects;
pub use emitters::{Emitter, EmitterShape};
pub use prepared::{Prepared, Quality};
pub(crate) use prepared::{PreparedLight, Stats};
pub(crate) use textures::{PreparedPattern, TextureMap};

/// Prepares `scene` for rendering; on failure, every problem found (errors and warnings).
pub fn prepare(scene: &Scene) -> Result<Prepared, Diagnostics> {
    let start = Instant::now();
    prepare_objects(scene, &scene.objects, start)
}

/// [`prepare`] for a caller that no longer needs the scene (`rtc render`): each IR object is
/// freed once it is prepared, before the world's BVH is built, so the scene and the world are
/// never both whole in memory (a million spheres: 208 MB less at the peak).
pub fn prepare_owned(mut scene: Scene) -> Result<Prepared, Diagnostics> {
    let start = Instant::now();
    let objects = std::mem::take(&mut scene.objects);
    prepare_objects(&scene, objects, start)
}

/// [`prepare`] with `objects` the scene's (which `scene.objects` may no longer hold).
fn prepare_objects<O: std::borrow::Borrow<Object>>(
    scene: &Scene,
    objects: impl IntoIterator<Item = O>,
    start: Instant,
) -> Result<Prepared, Diagnostics> {
    // Objects are checked even after a scene-level error, so one run shows every problem.
    let mut diags = Diagnostics::default();
    let mut content = Content::without_objects(scene);
    let (mut materials, fallback) = material_table(scene);
    let mut b = objects::Builder::new(
        materials.len() as u32,
        scene.textures.len() as u32,
        scene.memory,
    );
    // Each object goes straight into the world's storage (a plain sphere into its compact
    // form), so a million spheres never exist as a million full primitives.
    let mut parts = WorldParts::default();
    let mut instanced = 0;
    // Filled once some object is hidden from some rays (earlier ones are seen by all).
    let mut visibility: Vec<Visibility> = Vec::new();
    // Glowing spheres and quads the path tracer aims at (none for a Whitted scene).
    let path_traced = matches!(scene.settings.integrator, crate::ir::Integrator::Path(_));
    let mut emitters = Vec::new();
    // One pass validates, surveys and prepares each object (and frees it, when owned).
    for (i, o) in objects.into_iter().enumerate() {
        let o = o.borrow();
        validate::object(scene, o, &mut diags);
        content.visit(o);
        if !o.visibility.is_all() || !visibility.is_empty() {
            visibility.resize(i, Visibility::ALL);
            visibility.push(o.visibility);
        }
        if path_traced && let Some(e) = emitters::of(o, i as u32, &materials, fallback) {
            emitters.push(e);
        }
        if let Some(ball) = b.ball(o, fallback, i as u32) {
            parts.push_ball(ball);
        } else if let Some(n) = b.object(o, fallback) {
            instanced += instanced_triangles(&n);
            parts.push(n, i as u32);
        }
    }
    validate::scene(scene, &mut diags);
    let mut textures = textures::load_all(&scene.textures, &mut diags, &mut b.memory);
    if !b.extra_textures.is_empty() {
        // The meshes' base colour images, numbered after the scene's textures.
        content.add_mesh_textures();
        let extra = textures::load_mesh_textures(&b.extra_textures, &mut diags, &mut b.memory);
        textures = textures.zip(extra).map(|(mut t, e)| {
            t.extend(e);
            t
        });
    }
    let mesh_stats = b.stats();
    materials.extend(std::mem::take(&mut b.extra_materials));
    diags.extend(std::mem::take(&mut b.diagnostics));
    let isosurfaces = std::mem::take(&mut b.isosurfaces);
    let textures = match textures {
        Some(t) if !diags.has_errors() => t,
        _ => return Err(diags),
    };
    let lights: Vec<PreparedLight> = scene
        .lights
        .iter()
        .map(|l| PreparedLight {
            kind: l.kind,
            color: l.color,
            spot: l.spot,
            fade: l.fade,
            shadows: l.shadows,
            samples: match l.kind {
                LightKind::Point { .. }
                | LightKind::Parallel { .. }
                | LightKind::Cylinder { .. } => 1,
                // Both at most MAX_LIGHT_SAMPLES_PER_AXIS (validated), so no overflow.
                LightKind::Area { samples, .. } => samples[0].max(1) * samples[1].max(1),
            },
        })
        .collect();
    let mut world = World::new(parts, expected_rays(scene, &lights));
    let effects = Effects::new(&content, &scene.settings, &scene.camera);
    world.need_uv(
        effects.textures || effects.bump || effects.hatching || scene.settings.mode.reads_uv(),
    );
    let w = world.stats();
    let stats = Stats {
        objects: w.objects,
        unbounded: w.unbounded,
        meshes: mesh_stats.meshes,
        unique_triangles: mesh_stats.unique_triangles,
        instanced_triangles: instanced,
        build_time: start.elapsed(),
        bvh_build_time: w.bvh_build_time + mesh_stats.bvh_build_time,
        mesh_load_time: mesh_stats.load_time,
        memory_bytes: w.memory_bytes + mesh_stats.memory_bytes,
    };
    let own_gloss_samples = materials.iter().map(|m| m.gloss_samples).collect();
    Ok(Prepared {
        camera: scene.camera.clone(),
        world,
        materials,
        own_gloss_samples,
        textures,
        lights,
        emitters,
        settings: scene.settings.clone(),
        content,
        effects,
        warnings: diags.items,
        isosurfaces,
        stats,
        visibility,
    })
}

/// About how many rays a frame of `scene` traces: camera samples (the most a pixel may take),
/// each with its shadow rays (every sample of every light) when shadows are on. An estimate
/// for choosing how much effort the world's BVH deserves, never a limit.
fn expected_rays(scene: &Scene, lights: &[PreparedLight]) -> u64 {
    let shadow_rays: u64 = match scene.settings.shadows {
        true => lights.iter().map(|l| u64::from(l.samples)).sum(),
        false => 0,
    };
    let pixels = u64::from(scene.camera.width) * u64::from(scene.camera.height);
    pixels
        .saturating_mul(u64::from(scene.settings.sampling.max_per_pixel()))
        .saturating_mul(1 + shadow_rays)
}

/// The scene's materials plus the fallback for objects that name none (the scene's default
/// material when it names one, else a default material appended), and the fallback's id.
fn material_table(scene: &Scene) -> (Vec<Material>, MaterialId) {
    let mut materials = scene.materials.clone();
    let fallback = match scene.settings.default_material {
        Some(id) if (id.0 as usize) < materials.len() => id,
        _ => {
            materials.push(Material::default());
            MaterialId((materials.len() - 1) as u32)
        }
    };
    (materials, fallback)
}

/// Every problem preparing `scene` finds (errors and warnings), in the order [`prepare`]
/// reports them: what `rtc check` adds to the front end's and the lints' findings. It runs
/// every step of [`prepare`] that can find a problem (scene checks, every object prepared,
/// meshes and textures loaded) but keeps no geometry and builds no world: building the world
/// and its BVH cannot fail, and for a million objects it was two thirds of `rtc check`.
pub fn validate(scene: &Scene) -> Diagnostics {
    let mut v = Validator::new(scene);
    for o in &scene.objects {
        v.object(o);
    }
    v.finish()
}

/// [`validate`] fed the scene's objects one at a time, in order (so `rtc check` walks them
/// once for the lints and this).
pub(crate) struct Validator<'a> {
    scene: &'a Scene,
    diags: Diagnostics,
    fallback: MaterialId,
    b: objects::Builder,
}

impl<'a> Validator<'a> {
    /// A validator of `scene`, before its objects.
    pub(crate) fn new(scene: &'a Scene) -> Validator<'a> {
        let (materials, fallback) = material_table(scene);
        Validator {
            scene,
            diags: Diagnostics::default(),
            fallback,
            b: objects::Builder::new(
                materials.len() as u32,
                scene.textures.len() as u32,
                scene.memory,
            ),
        }
    }

    /// Checks the next object of the scene.
    pub(crate) fn object(&mut self, o: &Object) {
        validate::object(self.scene, o, &mut self.diags);
        self.b.check(o, self.fallback);
    }

    /// The findings, once every object was given.
    pub(crate) fn finish(mut self) -> Diagnostics {
        validate::scene(self.scene, &mut self.diags);
        // `prepare` loads the textures even after an object's error, so the check does too.
        let _ = textures::load_all(&self.scene.textures, &mut self.diags, &mut self.b.memory);
        self.diags.extend(std::mem::take(&mut self.b.diagnostics));
        self.diags
    }
}
