//! A mesh's BVH: built over its triangles, or, for a large mesh, over clusters of four
//! triangles that lie next to each other along a Morton curve ([`Bvh::build_clustered`]: a
//! quarter of the boxes to build over, where the build dominates the time to first ray).
//!
//! Either tree is exact for every ray: a leaf's box holds its triangles (padded for the f32
//! slab test), so which triangles a ray may meet never depends on how they were grouped; only
//! the order of tests, and so which of two triangles at exactly the same `t` is reported, does.

use glam::Vec3A;
use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb as BAabb;
use rayon::prelude::*;

use crate::geometry::bvh::{BLOCK, Bvh};
use crate::geometry::mesh::MeshParts;

/// Above this many triangles a mesh's BVH is built over clusters of [`BLOCK`] triangles
/// (a quarter of the boxes) instead of one box per triangle, because there the build dominates
/// the time to first ray and the process's peak memory (bunny-x16, 1.1M triangles: BVH
/// 0.28 → 0.10 s, peak RSS 325 → 132 MB, tracing 19% slower).
const LARGE_MESH: usize = 300_000;

/// Most triangles in one BVH leaf (one 4-wide test).
const LEAF_TRIANGLES: u32 = BLOCK as u32;

/// The BVH of a mesh's triangles (ids are indices into `parts.triangles`), each triangle's box
/// widened by `pad`.
pub(crate) fn build(parts: &MeshParts<'_>, pad: Vec3A) -> Bvh {
    if parts.triangles.len() <= LARGE_MESH {
        per_triangle(parts, pad)
    } else {
        clustered(parts, pad)
    }
}

/// The padded f32 box of triangle `t`.
fn triangle_box(parts: &MeshParts<'_>, t: &[u32; 3], pad: Vec3A) -> BAabb {
    let corners = t.map(|i| Vec3A::from(parts.vertices[i as usize]));
    let b = BAabb::from_points(&corners);
    BAabb::new(b.min - pad, b.max + pad)
}

/// One box per triangle, a quality build (PLOC with reinsertion): better trees pay off until
/// the build itself dominates the time to first ray.
pub(crate) fn per_triangle(parts: &MeshParts<'_>, pad: Vec3A) -> Bvh {
    let boxes: Vec<_> = parts
        .triangles
        .par_iter()
        .map(|t| triangle_box(parts, t, pad))
        .collect();
    Bvh::build(
        &boxes,
        (0..boxes.len() as u32).collect(),
        BvhBuildParams {
            max_prims_per_leaf: LEAF_TRIANGLES,
            ..BvhBuildParams::medium_build()
        },
    )
}

/// One box per cluster of [`BLOCK`] triangles consecutive in the Morton order of their
/// boxes (the last cluster may be short), each cluster one leaf. The fast build: over a quarter
/// of the boxes the medium build's reinsertion passes would still cost more than they save
/// on the rays of one frame.
pub(crate) fn clustered(parts: &MeshParts<'_>, pad: Vec3A) -> Bvh {
    let ids: Vec<u32> = (0..parts.triangles.len() as u32).collect();
    Bvh::build_clustered(
        parts.triangles.len(),
        |i| triangle_box(parts, &parts.triangles[i], pad),
        &ids,
        BLOCK,
        BvhBuildParams::fast_build(),
    )
}
