//! BVHs built over clusters: runs of a few primitives that lie next to each other along a
//! Morton curve, each run one box for the builder and one leaf of the tree.
//!
//! Why: above a few hundred thousand primitives the build is most of the time to the first
//! ray, and its transient arrays (obvhs's PLOC keeps binary nodes for the current and next
//! cluster lists and the output tree, ~230 bytes per box) set the process's peak memory. The
//! leaves of a large tree hold a few primitives anyway (four triangles for one 4-wide test,
//! up to four objects in a large world), so building over runs of that many neighbours gives
//! the same kind of leaves from a fraction of the boxes: time and memory of the build fall
//! about as many times. The tree is a little looser than one built primitive by primitive (a
//! run is fixed before the builder sees it), which costs some tracing speed, worth it only
//! where the build dominates.
//!
//! The tree is exact for every ray all the same: a leaf's box is the union of its primitives'
//! boxes, so which primitives a ray is offered never depends on the grouping; only the order
//! of the tests does (and with it which of two primitives at exactly the same distance wins).

use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb as BAabb;
use rayon::prelude::*;

use crate::geometry::bvh::{Bvh, MAX_LEAF, MAX_PRIMITIVES};

/// Bits per axis of the Morton code: 4096 cells a side (far finer than needed to keep a few
/// neighbours together), so that the code and a primitive's index fit one `u64` sort key.
const MORTON_BITS: u32 = 12;

/// Bits of a primitive's index below the code in a sort key.
const INDEX_BITS: u32 = 64 - 3 * MORTON_BITS;

const _: () = assert!(MAX_PRIMITIVES <= 1 << INDEX_BITS);

impl Bvh {
    /// A tree over `count` primitives (`box_of(i)` the box of primitive `i`, `ids[i]` what
    /// the tree reports for it) whose leaves are runs of `cluster` primitives consecutive in
    /// the Morton order of their boxes' centres (the last run may be shorter). `params` is the
    /// build over the runs' boxes (its leaf size is ignored: one run a leaf). Deterministic:
    /// ties in the order fall to the lower index, whatever the thread count.
    pub(crate) fn build_clustered(
        count: usize,
        box_of: impl Fn(usize) -> BAabb + Sync,
        ids: &[u32],
        cluster: usize,
        params: BvhBuildParams,
    ) -> Bvh {
        // One cluster a leaf: at most a leaf's worth.
        let cluster = cluster.clamp(1, MAX_LEAF as usize);
        if count == 0 || count > MAX_PRIMITIVES {
            return Bvh::build(&[], Vec::new(), params);
        }
        let order = morton_order(count, &box_of);
        let boxes: Vec<BAabb> = order
            .par_chunks(cluster)
            .map(|run| {
                run.iter()
                    .fold(BAabb::empty(), |a, &i| a.union(&box_of(i as usize)))
            })
            .collect();
        let tree = Bvh::build(
            &boxes,
            (0..boxes.len() as u32).collect(),
            BvhBuildParams {
                max_prims_per_leaf: 1,
                ..params
            },
        );
        drop(boxes);
        let members: Vec<u32> = order
            .iter()
            .map(|&i| ids.get(i as usize).copied().unwrap_or(u32::MAX))
            .collect();
        drop(order);
        tree.expand_clusters(|c| {
            let first = c as usize * cluster;
            members
                .get(first..(first + cluster).min(members.len()))
                .unwrap_or(&[])
        })
    }
}

/// The indices `0..count` sorted by the Morton code of their boxes' centres within the
/// centres' bounds (ties by index).
fn morton_order(count: usize, box_of: &(impl Fn(usize) -> BAabb + Sync)) -> Vec<u32> {
    let centres = (0..count)
        .into_par_iter()
        .fold(BAabb::empty, |b, i| {
            let mut b = b;
            b.extend(box_of(i).center());
            b
        })
        .reduce(BAabb::empty, |a, b| a.union(&b));
    let (lo, size) = (centres.min, centres.max - centres.min);
    let cells = (1u32 << MORTON_BITS) as f32;
    // Cells per unit along each axis; a flat axis (size 0) puts every centre in cell 0.
    let scale = size
        .to_array()
        .map(|s| if s > 0.0 { cells / s } else { 0.0 });
    let mut keys: Vec<u64> = (0..count)
        .into_par_iter()
        .map(|i| {
            let c = box_of(i).center();
            let cell = |axis: usize| {
                let x = (c[axis] - lo[axis]) * scale[axis];
                // NaN (a non-finite box) and the top edge clamp into the grid.
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

    /// Neighbours in space are neighbours in the order: points on a line come out sorted
    /// along it, and equal boxes by index.
    #[test]
    fn morton_order_follows_space() {
        use glam::Vec3A;
        let at = |i: usize| {
            let x = [5.0, 1.0, 3.0, 1.0, 9.0][i];
            BAabb::new(Vec3A::new(x, 0.0, 0.0), Vec3A::new(x, 1.0, 1.0))
        };
        assert_eq!(morton_order(5, &at), vec![1, 3, 2, 0, 4]);
    }
}
