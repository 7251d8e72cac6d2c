//! BVHs over boxes: the top level over every bounded object, and one per mesh.
//!
//! obvhs builds a binary tree (PLOC with reinsertion); it is collapsed here into an 8-wide tree
//! whose child boxes are stored uncompressed as f32 structure-of-arrays, so one node test is a
//! handful of 8-lane operations the compiler vectorises (see `bvh_traverse.rs`). Collapsing is
//! linear in the node count, far cheaper than obvhs's own compressed-wide conversion, and the
//! uncompressed boxes need no decoding during traversal.

mod cluster;
pub mod packet;
mod ties;
mod traverse;

use std::time::{Duration, Instant};

use glam::{DVec3, Vec3A, Vec4};
use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb as BAabb;
use obvhs::bvh2::Bvh2;
use obvhs::bvh2::leaf_collapser::collapse as collapse_leaves;
use obvhs::bvh2::reinsertion::ReinsertionOptimizer;
use obvhs::ploc::PlocBuilder;

use crate::geometry::aabb::Aabb;

/// Children per node.
const WIDTH: usize = 8;

/// Child slot flag: a leaf (a range of primitive slots) rather than an inner node.
const LEAF: u32 = 1 << 31;
/// A child slot with nothing in it (its box is empty, so no ray enters it).
const EMPTY: u32 = u32::MAX;
/// Bits of a leaf's first primitive slot; the count (minus one) sits above them.
const LEAF_START_BITS: u32 = 26;
/// Most primitives a leaf can hold (the count field has five bits).
const MAX_LEAF: u32 = 32;
/// Most primitives one BVH can index (the leaf start field's range).
pub(crate) const MAX_PRIMITIVES: usize = 1 << LEAF_START_BITS;

/// One node: eight child boxes as structure-of-arrays and eight child references.
#[derive(Clone, Debug)]
struct WideNode {
    /// Child box planes: `planes[axis]` the minima and `planes[3 + axis]` the maxima, each as
    /// two 4-lane vectors (lanes 0–3 and 4–7), so the node test is plain SSE.
    planes: [[Vec4; 2]; 6],
    /// Inner node index, `LEAF | (count − 1) << 26 | first slot`, or [`EMPTY`].
    child: [u32; WIDTH],
}

impl WideNode {
    fn empty() -> WideNode {
        let (lo, hi) = (Vec4::splat(f32::INFINITY), Vec4::splat(f32::NEG_INFINITY));
        WideNode {
            planes: [[lo; 2], [lo; 2], [lo; 2], [hi; 2], [hi; 2], [hi; 2]],
            child: [EMPTY; WIDTH],
        }
    }

    fn set_box(&mut self, lane: usize, b: &BAabb) {
        for axis in 0..3 {
            self.planes[axis][lane / 4][lane % 4] = b.min[axis];
            self.planes[3 + axis][lane / 4][lane % 4] = b.max[axis];
        }
    }
}

/// Encodes a leaf child: `count` primitive slots from `start`.
fn leaf(start: u32, count: u32) -> u32 {
    debug_assert!((1..=MAX_LEAF).contains(&count) && (start as usize) < MAX_PRIMITIVES);
    LEAF | (count - 1) << LEAF_START_BITS | start
}

/// A leaf child's start field (its first slot, or its first block after [`Bvh::into_blocks`])
/// and its primitive count.
#[inline(always)]
fn leaf_parts(child: u32) -> (usize, usize) {
    let start = (child & ((1 << LEAF_START_BITS) - 1)) as usize;
    let count = ((child & !LEAF) >> LEAF_START_BITS) as usize + 1;
    (start, count)
}

/// Slots per block after [`Bvh::into_blocks`] (the lanes of one 4-wide triangle test).
pub(crate) const BLOCK: usize = 4;

/// A wide BVH over a list of boxes; primitive slots in callbacks index [`Bvh::order`].
#[derive(Clone, Debug)]
pub(crate) struct Bvh {
    nodes: Vec<WideNode>,
    /// The caller's primitive index for each BVH slot (leaves hold contiguous slot ranges).
    pub(crate) order: Vec<u32>,
    /// Time spent building.
    pub(crate) build_time: Duration,
}

/// An f32 box that contains the f64 box (rounded outward), or `None` if it does not fit in f32.
pub(crate) fn to_f32_box(b: &Aabb) -> Option<BAabb> {
    let lo = b.min.as_vec3a();
    let hi = b.max.as_vec3a();
    let down = |v: Vec3A| Vec3A::new(v.x.next_down(), v.y.next_down(), v.z.next_down());
    let up = |v: Vec3A| Vec3A::new(v.x.next_up(), v.y.next_up(), v.z.next_up());
    let out = BAabb::new(down(lo), up(hi));
    (out.min.is_finite() && out.max.is_finite() && !b.is_empty()).then_some(out)
}

/// A ray prepared for traversal in f32: origin, safe reciprocal direction and a `t` range.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct BvhRay {
    /// Origin, one axis splatted per vector.
    origin: [Vec4; 3],
    /// Safe reciprocal direction, splatted likewise.
    inv: [Vec4; 3],
    /// Per axis, the index into [`WideNode::planes`] of the slab the ray enters by (the minimum
    /// for a forward axis, the maximum for a backward one); the exit slab is the other.
    entry_plane: [usize; 3],
    t_min: f32,
    pub(crate) t_max: f32,
}

impl BvhRay {
    /// The f32 ray for `origin + t·dir`, `t` in `[t_min, t_max]`, or `None` when it cannot be
    /// represented (non-finite or zero direction).
    pub(crate) fn new(origin: DVec3, dir: DVec3, t_min: f64, t_max: f64) -> Option<BvhRay> {
        Self::with_inverse(origin, dir, dir.recip(), t_min, t_max)
    }

    /// Like [`BvhRay::new`] with the f64 reciprocal direction already known.
    #[inline]
    pub(crate) fn with_inverse(
        origin: DVec3,
        dir: DVec3,
        inv: DVec3,
        t_min: f64,
        t_max: f64,
    ) -> Option<BvhRay> {
        let (o, d) = (origin.as_vec3a(), dir.as_vec3a());
        if !o.is_finite() || !d.is_finite() || d == Vec3A::ZERO {
            return None;
        }
        // A component too small for f32 inverts to a huge finite value of the right sign, so
        // slab products never become 0·∞ = NaN.
        let safe = |x: f32, i: f64| {
            let i = i as f32;
            if i.is_finite() {
                i
            } else if x.is_sign_negative() {
                -f32::MAX
            } else {
                f32::MAX
            }
        };
        let inv = [safe(d.x, inv.x), safe(d.y, inv.y), safe(d.z, inv.z)];
        let lo = if t_min.is_finite() {
            (t_min as f32).next_down()
        } else {
            f32::NEG_INFINITY
        };
        let hi = if t_max.is_finite() {
            (t_max as f32).next_up()
        } else {
            f32::INFINITY
        };
        let entry_plane = [0, 1, 2].map(|axis| if inv[axis] < 0.0 { 3 + axis } else { axis });
        Some(BvhRay {
            origin: o.to_array().map(Vec4::splat),
            inv: inv.map(Vec4::splat),
            entry_plane,
            t_min: lo,
            t_max: hi,
        })
    }
}

impl Bvh {
    /// Builds over `boxes`; `ids[i]` is reported for `boxes[i]`. Leaves hold up to
    /// `quality.max_prims_per_leaf` primitives. Callers keep `boxes` within [`MAX_PRIMITIVES`]
    /// (mesh and object budgets); beyond it the tree is left empty rather than corrupt.
    pub(crate) fn build(boxes: &[BAabb], ids: Vec<u32>, quality: BvhBuildParams) -> Bvh {
        Self::build_grouped(boxes, ids, quality, 1)
    }

    /// [`Bvh::build`], then every subtree of at most `group` primitives (≤ [`MAX_LEAF`])
    /// becomes one leaf while collapsing: a cheap linear pass (obvhs's SAH leaf collapser cost
    /// as much as the rest of the build for a million spheres) that shrinks the wide tree
    /// about fourfold. The leaves hold the same primitives the subtrees held, so the boxes a
    /// ray passes and the primitives it is tested against do not depend on `group` beyond the
    /// order of the tests within a leaf.
    pub(crate) fn build_grouped(
        boxes: &[BAabb],
        ids: Vec<u32>,
        quality: BvhBuildParams,
        group: u32,
    ) -> Bvh {
        let start = Instant::now();
        let mut core = Duration::default();
        let mut nodes = Vec::new();
        let mut order = Vec::new();
        if !boxes.is_empty() && boxes.len() <= MAX_PRIMITIVES {
            let quality = BvhBuildParams {
                max_prims_per_leaf: quality.max_prims_per_leaf.min(MAX_LEAF),
                ..quality
            };
            let bvh2 = build_binary(boxes, quality, &mut core);
            let prims;
            (nodes, prims) = collapse(&bvh2, group.clamp(1, MAX_LEAF));
            order = prims
                .iter()
                .map(|&i| ids.get(i as usize).copied().unwrap_or(u32::MAX))
                .collect();
        }
        Bvh {
            nodes,
            order,
            build_time: start.elapsed(),
        }
    }

    /// Approximate heap bytes.
    pub(crate) fn memory(&self) -> usize {
        self.nodes.len() * std::mem::size_of::<WideNode>() + self.order.len() * 4
    }

    /// A tree built over clusters turned into one over their members: `members(c)` lists the
    /// primitives of cluster `c` (the id the tree reports for it), and each leaf's clusters
    /// become one contiguous range of their members, in the same order. The leaves' boxes
    /// already hold their members, so nothing else changes. A leaf must not grow past
    /// [`MAX_LEAF`] members ([`Bvh::build_clustered`]: one cluster of at most that many a
    /// leaf).
    fn expand_clusters<'a>(mut self, members: impl Fn(u32) -> &'a [u32]) -> Bvh {
        let start = Instant::now();
        // Where each cluster slot's members begin in the new order, and one past the last.
        let mut first = Vec::with_capacity(self.order.len() + 1);
        let mut order = Vec::with_capacity(self.order.len() * BLOCK);
        for &c in &self.order {
            first.push(order.len() as u32);
            order.extend_from_slice(members(c));
        }
        first.push(order.len() as u32);
        for node in &mut self.nodes {
            for child in node
                .child
                .iter_mut()
                .filter(|c| **c != EMPTY && **c & LEAF != 0)
            {
                let (s, n) = leaf_parts(*child);
                let count = (first[s + n] - first[s]).clamp(1, MAX_LEAF);
                *child = leaf(first[s], count);
            }
        }
        self.order = order;
        self.build_time += start.elapsed();
        self
    }

    /// Lays the slots out anew in blocks of [`BLOCK`]: every leaf starts a fresh block, so a
    /// leaf of up to four primitives is one block (one 4-wide test), and a leaf's start field
    /// becomes its first block. Its slots are `BLOCK·start ..` (`count` of them, in the order
    /// they had), and [`Bvh::order`] is `u32::MAX` in the padding slots after a leaf. Leaves
    /// keep their order in memory. Only the leaf-wise traversals ([`Bvh::closest_leaves`],
    /// [`Bvh::any_leaves`]) may be used afterwards.
    pub(crate) fn into_blocks(mut self) -> Bvh {
        // (first slot, node, lane) of every leaf, in slot order.
        let mut leaves: Vec<(usize, usize, usize)> = Vec::new();
        for (n, node) in self.nodes.iter().enumerate() {
            for (lane, &c) in node.child.iter().enumerate() {
                if c != EMPTY && c & LEAF != 0 {
                    leaves.push((leaf_parts(c).0, n, lane));
                }
            }
        }
        leaves.sort_unstable();
        let mut order = Vec::with_capacity(self.order.len() + self.order.len() / 2);
        for (start, n, lane) in leaves {
            let count = leaf_parts(self.nodes[n].child[lane]).1;
            let block = order.len() / BLOCK;
            order.extend_from_slice(&self.order[start..start + count]);
            order.resize(order.len().next_multiple_of(BLOCK), u32::MAX);
            self.nodes[n].child[lane] = leaf(block as u32, count as u32);
        }
        self.order = order;
        self
    }
}

/// obvhs's `build_bvh2` without its debug-build validation, which asserts a depth below 96 (its
/// own traversal stack): boxes that cannot be split (the same triangle many times) make deeper
/// trees, which rtc's traversal handles (its stack grows), so a debug or test build must not
/// panic on them (the obj_mtl fuzzer found a 10 kB OBJ that did, `tests/bvh_degenerate.rs`).
fn build_binary(boxes: &[BAabb], config: BvhBuildParams, core: &mut Duration) -> Bvh2 {
    let start = Instant::now();
    let ties = ties::find(boxes);
    let untied = ties.as_ref().map(|t| t.builder_boxes(boxes));
    let input = untied.as_deref().unwrap_or(boxes);
    let mut bvh2 = PlocBuilder::with_capacity(input.len()).build(
        config.ploc_search_distance,
        input,
        (0..input.len() as u32).collect(),
        config.sort_precision,
        config.search_depth_threshold,
    );
    let mut reinsertion = ReinsertionOptimizer::default();
    reinsertion.run(&mut bvh2, config.reinsertion_batch_ratio, None);
    collapse_leaves(
        &mut bvh2,
        config.max_prims_per_leaf.clamp(1, 255),
        config.collapse_traversal_cost,
    );
    reinsertion.run(
        &mut bvh2,
        config.reinsertion_batch_ratio * config.post_collapse_reinsertion_batch_ratio_multiplier,
        None,
    );
    if let Some(ties) = &ties {
        ties.splice(
            &mut bvh2,
            boxes,
            config.max_prims_per_leaf.clamp(1, MAX_LEAF),
        );
    }
    *core += start.elapsed();
    bvh2
}

/// Collapses a binary tree (root at 0, children of an inner node at `first_index` and
/// `first_index + 1`) into wide nodes, breadth first: each wide node takes the binary node's
/// children and keeps opening its largest inner child until it has [`WIDTH`] of them. With
/// `group` > 1 a subtree of at most `group` primitives is a leaf (not opened). Returns the
/// nodes and the primitive index of each slot the leaves refer to.
fn collapse(bvh2: &Bvh2, group: u32) -> (Vec<WideNode>, Vec<u32>) {
    let bin = &bvh2.nodes[..];
    let Some(root) = bin.first() else {
        return (Vec::new(), Vec::new());
    };
    let mut out = vec![WideNode::empty()];
    // Grouping lays the slots out anew, in depth-first order, where every subtree's primitives
    // are one contiguous range, left to right: a group's leaf is its subtree's range. Without
    // grouping the slots are obvhs's primitive order (its leaves are already contiguous ranges).
    let (slots, ranges) = match group > 1 {
        true => {
            let r = subtree_ranges(bvh2);
            (r.slots, Some((r.start, r.count)))
        }
        false => (bvh2.primitive_indices.clone(), None),
    };
    let leafish = |k: usize| bin[k].is_leaf() || ranges.as_ref().is_some_and(|r| r.1[k] <= group);
    let leaf_of = |k: usize| match &ranges {
        Some((start, count)) => leaf(start[k], count[k].clamp(1, MAX_LEAF)),
        None => leaf_child(&bin[k]),
    };
    if leafish(0) {
        out[0].set_box(0, &root.aabb);
        out[0].child[0] = leaf_of(0);
        return (out, slots);
    }
    // (binary inner node, wide node it becomes)
    let mut work = std::collections::VecDeque::from([(0usize, 0usize)]);
    let mut kids: Vec<usize> = Vec::with_capacity(WIDTH);
    while let Some((b, w)) = work.pop_front() {
        let first = bin[b].first_index as usize;
        kids.clear();
        kids.extend([first, first + 1]);
        while kids.len() < WIDTH {
            let widest = kids
                .iter()
                .enumerate()
                .filter(|(_, k)| !leafish(**k))
                .max_by(|(_, a), (_, c)| {
                    let area = |i: usize| bin[i].aabb.half_area();
                    area(**a).total_cmp(&area(**c))
                })
                .map(|(pos, _)| pos);
            let Some(pos) = widest else { break };
            let open = kids.swap_remove(pos);
            let f = bin[open].first_index as usize;
            kids.extend([f, f + 1]);
        }
        for (lane, &k) in kids.iter().enumerate() {
            out[w].set_box(lane, &bin[k].aabb);
            out[w].child[lane] = if leafish(k) {
                leaf_of(k)
            } else {
                out.push(WideNode::empty());
                let id = out.len() - 1;
                work.push_back((k, id));
                id as u32
            };
        }
    }
    (out, slots)
}

/// Every primitive of a binary tree in depth-first order, left child first, and for each node
/// the range of that order its subtree covers.
struct SubtreeRanges {
    /// Primitive indices, depth first.
    slots: Vec<u32>,
    /// `start[k]`: where node `k`'s primitives begin in `slots`.
    start: Vec<u32>,
    /// `count[k]`: how many primitives lie under node `k`.
    count: Vec<u32>,
}

/// One depth-first walk of a binary tree rooted at 0 (one visit per node, so the cost does not
/// depend on how obvhs laid the nodes out).
fn subtree_ranges(bvh2: &Bvh2) -> SubtreeRanges {
    let bin = &bvh2.nodes[..];
    let mut r = SubtreeRanges {
        slots: Vec::with_capacity(bvh2.primitive_indices.len()),
        start: vec![0; bin.len()],
        count: vec![0; bin.len()],
    };
    // (node, whether its children are done)
    let mut stack = vec![(0u32, false)];
    while let Some((k, done)) = stack.pop() {
        let (n, ku) = (&bin[k as usize], k as usize);
        if done {
            r.count[ku] = r.slots.len() as u32 - r.start[ku];
            continue;
        }
        r.start[ku] = r.slots.len() as u32;
        if n.is_leaf() {
            let first = n.first_index as usize;
            r.slots
                .extend(&bvh2.primitive_indices[first..first + n.prim_count as usize]);
            r.count[ku] = n.prim_count;
        } else {
            stack.extend([
                (k, true),
                (n.first_index + 1, false),
                (n.first_index, false),
            ]);
        }
    }
    r
}

fn leaf_child(node: &obvhs::bvh2::node::Bvh2Node) -> u32 {
    leaf(node.first_index, node.prim_count.clamp(1, MAX_LEAF))
}

#[cfg(test)]
mod tests;
