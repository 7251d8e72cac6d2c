//! The mesh fuzz target's work: load, cast rays, test closedness, render.

use std::path::Path;

use glam::{DAffine3, DVec3};
use rtc::assets::MeshAsset;
use rtc::geometry::Ray;
use rtc::geometry::mesh::{Mesh, MeshParts};
use rtc::ir::{Object, Shape};
use rtc::num::Norm;

/// Loads the mesh (OBJ, STL or PLY) at `path` and uses it every way the renderer does.
pub fn exercise(path: &Path, smooth: bool, use_mtl: bool) {
    let Ok(asset) = MeshAsset::load(path, smooth) else {
        return;
    };
    let mesh = Mesh::build(MeshParts {
        vertices: &asset.vertices,
        triangles: &asset.triangles,
        normals: &asset.normals,
        uvs: &asset.uvs,
        colors: &asset.colors,
        material_of: &asset.material_of,
    });
    let b = mesh.bounds();
    let centre = 0.5 * (b.min + b.max);
    let reach = (b.max - b.min).norm().max(1.0);
    let mut hits = Vec::new();
    for dir in directions() {
        let ray = Ray::new(centre - 2.0 * reach * dir, dir);
        if let Some(h) = mesh.intersect(&ray, 0.0, f64::INFINITY) {
            assert!(h.t >= 0.0, "hit behind the ray: {}", h.t);
            assert!(mesh.occluded(&ray, 0.0, f64::INFINITY));
        }
        hits.clear();
        mesh.all_hits(&ray, &mut hits);
    }
    let _ = (asset.is_closed(), mesh.triangle_count(), mesh.memory());
    // As a scene object (through the asset cache, emptied so this file is read afresh).
    rtc::assets::clear_cache();
    let mut scene = crate::texture::one_object_scene(Object {
        shape: Shape::Mesh {
            source: rtc::ir::MeshSource::File(path.to_path_buf()),
            smooth,
            use_mtl,
        },
        transform: DAffine3::IDENTITY.into(),
        material: None,
        motion: None,
        span: Default::default(),
        visibility: Default::default(),
    });
    if centre.is_finite() && reach.is_finite() {
        scene.camera.center = centre;
        scene.camera.eye = centre + DVec3::new(0.3, 0.4, 1.0) * (2.0 * reach);
    }
    crate::later_stages(scene, &crate::synthetic_sources());
}

/// The 6 axis directions and the 8 diagonals.
fn directions() -> impl Iterator<Item = DVec3> {
    let axes = [DVec3::X, DVec3::Y, DVec3::Z]
        .into_iter()
        .flat_map(|a| [a, -a]);
    let diagonals = (0..8).map(|i| {
        let s = |bit: i32| if i & bit == 0 { 1.0 } else { -1.0 };
        DVec3::new(s(1), s(2), s(4)).unit()
    });
    axes.chain(diagonals)
}
