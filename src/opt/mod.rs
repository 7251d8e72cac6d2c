//! The preparation stage: IR scene → [`Prepared`] scene, once per scene, before any ray.
//!
//! It validates the scene once (ids, camera, limits, every shape by `geometry::shape`, CSG
//! operands, transforms), loads assets through the asset service (meshes, their MTL materials,
//! textures), shares each mesh file between the objects that place it (instancing), builds the
//! whole material table (the scene's, the fallback, then MTL materials), prepares lights,
//! computes the [`Effects`] the scene calls for, and builds the [`World`] with its BVH. The
//! renderer reads only the [`Prepared`] scene; `rtc check` runs the same preparation, so a clean
//! check means the render will start.

pub mod effects;
pub mod fingerprint;
pub mod objects;
pub mod prepared;
pub mod textures;
pub mod validate;

use std::time::Instant;

use crate::diag::Diagnostics;
use crate::geometry::{World, world::instanced_triangles};
use crate::ir::{LightKind, Material, MaterialId, Scene};

pub use effects::{Content, Effects};
pub use prepared::{Prepared, PreparedLight, Quality, Stats};
pub use textures::{Picture, TextureMap};

/// Prepares `scene` for rendering; on failure, every problem found (errors and warnings).
pub fn prepare(scene: &Scene) -> Result<Prepared, Diagnostics> {
    let start = Instant::now();
    let mut diags = Diagnostics::default();
    validate::scene(scene, &mut diags);
    // Objects are checked even after a scene-level error, so one run shows every problem.
    let mut materials = scene.materials.clone();
    let fallback = match scene.settings.default_material {
        Some(id) if (id.0 as usize) < materials.len() => id,
        _ => {
            materials.push(Material::default());
            MaterialId((materials.len() - 1) as u32)
        }
    };
    let mut b = objects::Builder::new(materials.len() as u32);
    let mut nodes = Vec::with_capacity(scene.objects.len());
    let mut object_of = Vec::with_capacity(scene.objects.len());
    for (i, o) in scene.objects.iter().enumerate() {
        if let Some(n) = b.object(o, fallback) {
            nodes.push(n);
            object_of.push(i as u32);
        }
    }
    let textures = textures::load_all(&scene.textures, &mut diags);
    let mesh_stats = b.stats();
    materials.extend(std::mem::take(&mut b.extra_materials));
    diags.extend(std::mem::take(&mut b.diagnostics));
    let textures = match textures {
        Some(t) if !diags.has_errors() => t,
        _ => return Err(diags),
    };
    let instanced = nodes.iter().map(instanced_triangles).sum();
    let mut world = World::new(nodes, object_of);
    let content = Content::of(scene);
    let effects = Effects::new(&content, &scene.settings, &scene.camera);
    world.need_uv(effects.textures || effects.bump || effects.hatching);
    let lights = scene
        .lights
        .iter()
        .map(|l| PreparedLight {
            kind: l.kind,
            color: l.color,
            samples: match l.kind {
                LightKind::Point { .. } => 1,
                // Both at most MAX_LIGHT_SAMPLES_PER_AXIS (validated), so no overflow.
                LightKind::Area { samples, .. } => samples[0].max(1) * samples[1].max(1),
            },
        })
        .collect();
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
        settings: scene.settings.clone(),
        content,
        effects,
        warnings: diags.items,
        stats,
    })
}

/// Every problem preparing `scene` finds (errors and warnings), without keeping the result:
/// what `rtc check` adds to the front end's and the lints' findings.
pub fn validate(scene: &Scene) -> Diagnostics {
    match prepare(scene) {
        Ok(p) => Diagnostics { items: p.warnings },
        Err(d) => d,
    }
}
