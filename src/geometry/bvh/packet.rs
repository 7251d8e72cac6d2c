//! Packet traversal of the wide BVH: up to [`PACKET`] rays walk the tree together, each node
//! loaded once and tested against every ray still in it, one control flow for all of them.
//!
//! Why: a pixel's camera rays (or its hit points' shadow rays towards one light) are so close
//! together that they pass the same few nodes and leaves; traced one by one, each pays the
//! node loop's branches and its stack again, and its tests wait on its own chain. In a packet
//! the rays' node tests are independent and overlap.
//!
//! An inner node is tested once for the whole packet, against the bounds of its rays
//! ([`Bounds`]): a test that passes whenever the test of any one ray ([`test`]) would pass,
//! which f32 rounding's monotonicity guarantees (below). A leaf's primitives are handed to a
//! ray only when that ray's own test of the leaf's box passes, exactly as in
//! [`Bvh::closest_leaves`] and [`Bvh::any_leaves`]. So a ray is offered the same leaves as
//! alone, except that its nearest hit so far may prune a different subset of those that lie
//! beyond it (the visiting order differs: the packet's nearest child first). The any-hit
//! answer is therefore the same, and the nearest hit is the same but for a choice between
//! triangles at exactly the same `t`, which the caller resolves (`Mesh::intersect_packet`
//! retraces such a ray alone).
//!
//! The packet test: a ray's entry into a child is `round(round(plane − o) · inv)` per axis,
//! maximised with `t_min`. Rounding is monotone, so over rays whose origins lie in
//! `[o_min, o_max]` and whose reciprocal directions lie in `[inv_min, inv_max]` (one sign on
//! the axis), the same two operations on the extreme origin and on the reciprocal the sign of
//! the difference calls for give a value no greater than any ray's, and likewise an exit no
//! smaller than any ray's; an axis the rays cross both ways is left out (no bound). The
//! packet's box test with these passes whenever one ray's passes.

use glam::{Vec3A, Vec4};

use crate::geometry::bvh::traverse::{EXIT_WIDEN, Stack, test};
use crate::geometry::bvh::{Bvh, BvhRay, EMPTY, LEAF, WIDTH, WideNode, leaf_parts};

/// Most rays in one packet (one bit each in a `u32` mask).
pub const PACKET: usize = 16;

/// The rays of `mask` (bits) as indices, in increasing order.
#[inline(always)]
fn bits(mut mask: u32) -> impl Iterator<Item = usize> {
    std::iter::from_fn(move || {
        (mask != 0).then(|| {
            let r = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            r
        })
    })
}

/// The rays of a packet bounded together for one test of a node that holds for all of them.
#[derive(Clone, Copy, Debug)]
struct Bounds {
    /// Per axis, the origins' extremes.
    o_min: [f32; 3],
    o_max: [f32; 3],
    /// Per axis, the reciprocal directions' extremes.
    inv_min: [f32; 3],
    inv_max: [f32; 3],
    /// Per axis, the slab every ray enters by, or `None` when the rays cross the axis both ways.
    entry: [Option<usize>; 3],
    /// The smallest `t_min`.
    t_min: f32,
}

impl Bounds {
    /// The bounds of the rays of `mask` (not empty).
    fn of(rays: &[BvhRay], mask: u32) -> Bounds {
        let first = &rays[mask.trailing_zeros() as usize];
        let xyz = |v: &[Vec4; 3]| Vec3A::new(v[0].x, v[1].x, v[2].x);
        let (mut o_min, mut o_max) = (xyz(&first.origin), xyz(&first.origin));
        let (mut inv_min, mut inv_max) = (xyz(&first.inv), xyz(&first.inv));
        let mut t_min = first.t_min;
        let mut same = [true; 3];
        for r in bits(mask) {
            let ray = &rays[r];
            let (o, inv) = (xyz(&ray.origin), xyz(&ray.inv));
            (o_min, o_max) = (o_min.min(o), o_max.max(o));
            (inv_min, inv_max) = (inv_min.min(inv), inv_max.max(inv));
            if ray.t_min < t_min {
                t_min = ray.t_min;
            }
            for (same, (a, b)) in same
                .iter_mut()
                .zip(ray.entry_plane.iter().zip(first.entry_plane))
            {
                *same &= *a == b;
            }
        }
        // An axis some rays cross forwards and others backwards gives no bound.
        let entry = [0, 1, 2].map(|axis| same[axis].then_some(first.entry_plane[axis]));
        Bounds {
            o_min: o_min.to_array(),
            o_max: o_max.to_array(),
            inv_min: inv_min.to_array(),
            inv_max: inv_max.to_array(),
            entry,
            t_min,
        }
    }

    /// Lower bounds of every ray's entry distance into the eight children of `node` and the
    /// mask of the children some ray with `t_max` at most `t_max` may meet.
    #[inline(always)]
    fn test(&self, node: &WideNode, t_max: f32) -> ([f32; WIDTH], u32) {
        let mut near = [Vec4::splat(self.t_min); 2];
        let mut far = [Vec4::splat(t_max); 2];
        let zero = Vec4::ZERO;
        for axis in 0..3 {
            let Some(entry) = self.entry[axis] else {
                continue;
            };
            let exit = if entry < 3 { entry + 3 } else { entry - 3 };
            let forward = entry < 3;
            // The origin that makes `plane − o` smallest (entry, forward) or largest.
            let (o_near, o_far) = match forward {
                true => (self.o_max[axis], self.o_min[axis]),
                false => (self.o_min[axis], self.o_max[axis]),
            };
            let (lo, hi) = (
                Vec4::splat(self.inv_min[axis]),
                Vec4::splat(self.inv_max[axis]),
            );
            for half in 0..2 {
                let d = node.planes[entry][half] - Vec4::splat(o_near);
                // A product d·inv is smallest at the smallest inv when d ≥ 0, else at the
                // largest (and the other way round for the exit's largest).
                near[half] = near[half].max(d * Vec4::select(d.cmpge(zero), lo, hi));
                let d = node.planes[exit][half] - Vec4::splat(o_far);
                far[half] = far[half].min(d * Vec4::select(d.cmpge(zero), hi, lo));
            }
        }
        let widen = Vec4::splat(EXIT_WIDEN);
        let mask =
            near[0].cmple(far[0] * widen).bitmask() | near[1].cmple(far[1] * widen).bitmask() << 4;
        let mut out = [0.0; WIDTH];
        out[..4].copy_from_slice(&near[0].to_array());
        out[4..].copy_from_slice(&near[1].to_array());
        (out, mask)
    }
}

/// Each ray's own test ([`test`]) of `node`: the mask of the children it meets, per ray.
/// When every ray enters each axis by the same slab (`entry`), the node's planes are loaded
/// once for all of them; each ray's test is the same operations in the same order as
/// [`test`], so its mask is the same.
#[inline(always)]
fn per_ray(
    node: &WideNode,
    rays: &[BvhRay],
    mask: u32,
    entry: [Option<usize>; 3],
    t_max: impl Fn(usize) -> f32,
) -> [u8; PACKET] {
    let mut out = [0u8; PACKET];
    let [Some(ex), Some(ey), Some(ez)] = entry else {
        for r in bits(mask) {
            out[r] = test(node, &rays[r], t_max(r)).1 as u8;
        }
        return out;
    };
    let exit = |e: usize| if e < 3 { e + 3 } else { e - 3 };
    let near_planes = [ex, ey, ez].map(|e| node.planes[e]);
    let far_planes = [ex, ey, ez].map(|e| node.planes[exit(e)]);
    let widen = Vec4::splat(EXIT_WIDEN);
    for r in bits(mask) {
        let ray = &rays[r];
        let mut near = [Vec4::splat(ray.t_min); 2];
        let mut far = [Vec4::splat(t_max(r)); 2];
        for axis in 0..3 {
            let (o, inv) = (ray.origin[axis], ray.inv[axis]);
            for half in 0..2 {
                near[half] = near[half].max((near_planes[axis][half] - o) * inv);
                far[half] = far[half].min((far_planes[axis][half] - o) * inv);
            }
        }
        out[r] = (near[0].cmple(far[0] * widen).bitmask()
            | near[1].cmple(far[1] * widen).bitmask() << 4) as u8;
    }
    out
}

/// The largest `t_max` of the rays of `mask` (plain comparisons: no NaN to care for).
#[inline(always)]
fn largest(t_max: &[f32; PACKET], mask: u32) -> f32 {
    let mut m = f32::NEG_INFINITY;
    for r in bits(mask) {
        if t_max[r] > m {
            m = t_max[r];
        }
    }
    m
}

impl Bvh {
    /// Closest-hit traversal of the rays of `active` (bits into `rays`) together:
    /// `f(ray, start, count, t_max)` gets a leaf that ray's own box test passes (start field and
    /// primitive count as in [`Bvh::closest_leaves`]) and returns that ray's nearest hit so far
    /// (at most `t_max`). `t_max[r]` starts as ray `r`'s limit and ends as its nearest hit.
    #[inline]
    pub(crate) fn closest_leaves_packet(
        &self,
        rays: &[BvhRay],
        active: u32,
        t_max: &mut [f32; PACKET],
        mut f: impl FnMut(usize, usize, usize, f32) -> f32,
    ) {
        if self.nodes.is_empty() || active == 0 {
            return;
        }
        let bounds = Bounds::of(rays, active);
        // (node, the rays still in it, a lower bound of their entry distances)
        let mut stack = Stack::new((0u32, 0u32, 0f32));
        let (mut node, mut mask) = (0u32, active);
        loop {
            let n = &self.nodes[node as usize];
            let far = largest(t_max, mask);
            let (near, mut hit) = bounds.test(n, far);
            // Inner children met, to be visited nearest first.
            let mut inner = [(0u32, 0u32, 0f32); WIDTH];
            let mut count = 0;
            // The rays' own tests, made at the first leaf child met.
            let mut own: Option<[u8; PACKET]> = None;
            while hit != 0 {
                let lane = hit.trailing_zeros() as usize;
                hit &= hit - 1;
                let c = n.child[lane];
                if c & LEAF == 0 {
                    let mut k = count;
                    while k > 0 && inner[k - 1].2 < near[lane] {
                        inner[k] = inner[k - 1];
                        k -= 1;
                    }
                    inner[k] = (c, mask, near[lane]);
                    count += 1;
                } else if c != EMPTY {
                    let own = own
                        .get_or_insert_with(|| per_ray(n, rays, mask, bounds.entry, |r| t_max[r]));
                    let (start, len) = leaf_parts(c);
                    for r in bits(mask) {
                        if own[r] >> lane & 1 == 1 && near[lane] <= t_max[r] {
                            t_max[r] = t_max[r].min(f(r, start, len, t_max[r]));
                        }
                    }
                }
            }
            // A ray whose nearest hit is nearer than a bound of its entry into a box cannot
            // meet anything nearer in it.
            let still =
                |rays: u32, d: f32| bits(rays).fold(0, |m, r| m | ((d <= t_max[r]) as u32) << r);
            if let Some((&(n, rays, d), farther)) = inner[..count].split_last() {
                for &item in farther {
                    stack.push(item);
                }
                let rays = still(rays, d);
                if rays != 0 {
                    (node, mask) = (n, rays);
                    continue;
                }
            }
            (node, mask) = loop {
                match stack.pop() {
                    Some((n, rays, d)) => {
                        let rays = still(rays, d);
                        if rays != 0 {
                            break (n, rays);
                        }
                    }
                    None => return,
                }
            };
        }
    }

    /// Any-hit traversal of the rays of `active` together: `f(ray, start, count)` as in
    /// [`Bvh::any_leaves`] for each leaf that ray's own box test passes, until it returns true
    /// for that ray. Returns the rays for which it did (the same set as one ray at a time).
    #[inline]
    pub(crate) fn any_leaves_packet(
        &self,
        rays: &[BvhRay],
        active: u32,
        mut f: impl FnMut(usize, usize, usize) -> bool,
    ) -> u32 {
        if self.nodes.is_empty() || active == 0 {
            return 0;
        }
        let bounds = Bounds::of(rays, active);
        let mut limits = [0.0; PACKET];
        for r in bits(active) {
            limits[r] = rays[r].t_max;
        }
        let far = largest(&limits, active);
        let mut done = 0u32;
        let mut stack = Stack::new((0u32, 0u32));
        let (mut node, mut mask) = (0u32, active);
        loop {
            let n = &self.nodes[node as usize];
            let (_, mut hit) = bounds.test(n, far);
            // The last inner child met goes next, as if pushed and popped at once.
            let mut last = None;
            let mut own: Option<[u8; PACKET]> = None;
            while hit != 0 {
                let lane = hit.trailing_zeros() as usize;
                hit &= hit - 1;
                let c = n.child[lane];
                if c & LEAF == 0 {
                    if let Some(earlier) = last.replace(c) {
                        stack.push((earlier, mask));
                    }
                } else if c != EMPTY {
                    let own = own.get_or_insert_with(|| {
                        per_ray(n, rays, mask, bounds.entry, |r| rays[r].t_max)
                    });
                    let (start, len) = leaf_parts(c);
                    for r in bits(mask & !done) {
                        if own[r] >> lane & 1 == 1 && f(r, start, len) {
                            done |= 1 << r;
                        }
                    }
                    if done == active {
                        return done;
                    }
                }
            }
            mask &= !done;
            (node, mask) = match last {
                Some(n) if mask != 0 => (n, mask),
                _ => loop {
                    match stack.pop() {
                        Some((n, rays)) if rays & !done != 0 => break (n, rays & !done),
                        Some(_) => continue,
                        None => return done,
                    }
                },
            };
        }
    }
}
