//! A mesh's BVH: built over its triangles, or, for a large mesh, over clusters of four
//! triangles that lie next to each other along a Morton curve.
//!
//! Why clusters: above [`LARGE_MESH`] triangles the build is most of the time to the first ray
//! and its transient arrays (obvhs's binary nodes for the cluster lists and the output tree,
//! ~230 bytes per box) set the process's peak memory. A BVH leaf holds four triangles anyway
//! (one 4-wide test), so building over groups of four that are already close in space gives
//! the same kind of leaves from a quarter of the boxes: the build's time and memory fall about
//! fourfold. The tree is a little looser than one built triangle by triangle (a cluster is
//! fixed before the build sees it), which costs some tracing speed on the largest meshes only.
//!
//! Either tree is exact for every ray: a leaf's box holds its triangles (padded for the f32
//! slab test), so which triangles a ray may meet never depends on how they were grouped; only
//! the order of tests, and so which of two triangles at exactly the same `t` is reported, does.

use glam::Vec3A;
use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb as BAabb;
use rayon::prelude::*;

use super::Aabb;
use super::bvh::{BLOCK, Bvh};
use super::mesh::MeshParts;
use crate::ir::limits::MAX_TRIANGLES;

/// Above this many triangles a mesh's BVH is built over clusters of [`BLOCK`] triangles
/// (quarter the boxes) instead of one box per triangle, because there the build dominates the
/// time to first ray and the process's peak memory (1.1M triangles: 0.28 s and 255 MB of
/// transient build arrays per triangle, against a tenth of a second of tracing).
pub const LARGE_MESH: usize = 300_000;

/// Most triangles in one BVH leaf (one 4-wide test).
const LEAF_TRIANGLES: u32 = BLOCK as u32;

/// Bits per axis of the Morton code that orders triangles into clusters: 4096 cells a side
/// (finer than needed to keep four neighbours together), so that the code and a triangle's
/// index fit one `u64` sort key.
const MORTON_BITS: u32 = 12;

/// Bits of a triangle's index below the code in a sort key.
const INDEX_BITS: u32 = 64 - 3 * MORTON_BITS;

const _: () = assert!(MAX_TRIANGLES <= 1 << INDEX_BITS);

/// The BVH of a mesh's triangles (ids are indices into `parts.triangles`), each triangle's box
/// widened by `pad`; `bounds` holds every corner.
pub(super) fn build(parts: &MeshParts<'_>, bounds: Aabb, pad: Vec3A) -> Bvh {
    if parts.triangles.len() <= LARGE_MESH {
        per_triangle(parts, bounds, pad)
    } else {
        clustered(parts, bounds, pad)
    }
}

/// The padded f32 box of triangle `t`.
fn triangle_box(parts: &MeshParts<'_>, t: &[u32; 3], pad: Vec3A) -> BAabb {
    let corners = t.map(|i| Vec3A::from(parts.vertices[i as usize]));
    let b = BAabb::from_points(&corners);
    BAabb::new(b.min - pad, b.max + pad)
}

/// One box per triangle, a quality build (PLOC with reinsertion): better trees pay off until
/// the build itself dominates the time to first ray. (`bounds` is unused: the signature is
/// [`clustered`]'s, so either can be handed to the mesh's build.)
pub(super) fn per_triangle(parts: &MeshParts<'_>, _bounds: Aabb, pad: Vec3A) -> Bvh {
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
/// centroids (the last cluster may be short), each cluster one leaf.
pub(super) fn clustered(parts: &MeshParts<'_>, bounds: Aabb, pad: Vec3A) -> Bvh {
    let order = morton_order(parts, bounds);
    let boxes: Vec<BAabb> = order
        .par_chunks(BLOCK)
        .map(|ids| {
            ids.iter()
                .map(|&i| triangle_box(parts, &parts.triangles[i as usize], pad))
                .fold(BAabb::empty(), |a, b| a.union(&b))
        })
        .collect();
    let tree = Bvh::build(
        &boxes,
        (0..boxes.len() as u32).collect(),
        // One cluster per leaf: a leaf is then one block of the 4-wide test, as in the
        // per-triangle tree. A cheaper build: over a quarter of the boxes the medium build's
        // reinsertion passes would still cost more than they save on the rays of one frame.
        BvhBuildParams {
            max_prims_per_leaf: 1,
            ..BvhBuildParams::fast_build()
        },
    );
    drop(boxes);
    tree.expand_clusters(|c| {
        let first = c as usize * BLOCK;
        order
            .get(first..(first + BLOCK).min(order.len()))
            .unwrap_or(&[])
    })
}

/// The triangles' indices sorted by the Morton code of their centroids within `bounds`
/// (ties, such as repeated triangles, by index, so the order is the same on every run and
/// thread count).
fn morton_order(parts: &MeshParts<'_>, bounds: Aabb) -> Vec<u32> {
    let (lo, size) = (bounds.min, bounds.max - bounds.min);
    let cells = (1u32 << MORTON_BITS) as f64;
    // Cells per unit along each axis; a flat axis (size 0) puts every centroid in cell 0.
    let scale = size
        .to_array()
        .map(|s| if s > 0.0 { cells / s } else { 0.0 });
    let mut keys: Vec<u64> = parts
        .triangles
        .par_iter()
        .enumerate()
        .map(|(i, t)| {
            let c = t.iter().fold(glam::DVec3::ZERO, |s, &v| {
                s + parts.vertices[v as usize].as_dvec3()
            }) / 3.0;
            let cell = |axis: usize| {
                let x = (c[axis] - lo[axis]) * scale[axis];
                // NaN (a non-finite corner) and out-of-range values clamp into the grid.
                (x.max(0.0) as u64).min((1 << MORTON_BITS) - 1)
            };
            let code = spread(cell(0)) | spread(cell(1)) << 1 | spread(cell(2)) << 2;
            code << INDEX_BITS | i as u64
        })
        .collect();
    keys.par_sort_unstable();
    let index = (1u64 << INDEX_BITS) - 1;
    keys.into_iter().map(|k| (k & index) as u32).collect()
}

/// The low [`MORTON_BITS`] bits of `x` spread to every third bit (bit k to bit 3k).
fn spread(x: u64) -> u64 {
    let mut x = x & ((1 << MORTON_BITS) - 1);
    // The classic 21-bit spread (any input below 2^21), on the masked input.
    x = (x | x << 32) & 0x001f_0000_0000_ffff;
    x = (x | x << 16) & 0x001f_0000_ff00_00ff;
    x = (x | x << 8) & 0x100f_00f0_0f00_f00f;
    x = (x | x << 4) & 0x10c3_0c30_c30c_30c3;
    (x | x << 2) & 0x1249_2492_4924_9249
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every bit of the input lands three times as high, nothing else is set.
    #[test]
    fn spread_moves_bit_k_to_bit_3k() {
        for k in 0..MORTON_BITS {
            assert_eq!(spread(1 << k), 1 << (3 * k), "bit {k}");
        }
        let every_third = (0..MORTON_BITS).fold(0, |m, k| m | 1 << (3 * k));
        assert_eq!(
            spread(u64::MAX),
            every_third,
            "bits above the code are dropped"
        );
    }
}
