//! Traversal of the wide BVH: the 8-lane node test and the closest-hit, any-hit and all-hits
//! loops. Callbacks get primitive slots (indices into [`Bvh::order`]) and are generic so they
//! inline into the loop.

use glam::Vec4;

use crate::geometry::bvh::{Bvh, BvhRay, EMPTY, LEAF, WIDTH, WideNode, leaf_parts};

/// Slab distances are rounded in f32; widening the exit by a few ulps (Ize 2013, 1 + 2γ₃)
/// keeps a box that the exact ray grazes from being culled. (A negative exit is narrowed
/// instead, which only matters for boxes behind `t_min ≥ 0`, culled anyway.)
pub(crate) const EXIT_WIDEN: f32 =
    1.0 + 2.0 * (3.0 * f32::EPSILON * 0.5) / (1.0 - 3.0 * f32::EPSILON * 0.5);

/// Entries kept on the array part of the stack before spilling to the heap. Every traversal
/// zeroes the array first, so it is kept short: 48 entries were a 392-byte `memset` call per
/// ray (3% of the duck's instructions), while a mesh of a few thousand triangles (depth 4–5)
/// rarely holds more than a dozen entries, and a deeper tree only spills its excess.
const STACK: usize = 16;

/// Entry distances of the eight children and the mask of those the ray meets in
/// `[ray.t_min, t_max]`.
#[inline(always)]
pub(crate) fn test(node: &WideNode, ray: &BvhRay, t_max: f32) -> ([f32; WIDTH], u32) {
    let mut near = [Vec4::splat(ray.t_min); 2];
    let mut far = [Vec4::splat(t_max); 2];
    for axis in 0..3 {
        let entry = ray.entry_plane[axis];
        // The exit plane of an axis is the other one of its pair (axis ↔ 3 + axis).
        let exit = if entry < 3 { entry + 3 } else { entry - 3 };
        let (o, inv) = (ray.origin[axis], ray.inv[axis]);
        for half in 0..2 {
            near[half] = near[half].max((node.planes[entry][half] - o) * inv);
            far[half] = far[half].min((node.planes[exit][half] - o) * inv);
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

/// A traversal stack (of node and entry distance, or a packet's entries) that lives on the
/// call stack and spills to the heap only for unusually deep trees.
pub(crate) struct Stack<T> {
    items: [T; STACK],
    len: usize,
    spill: Vec<T>,
}

impl<T: Copy> Stack<T> {
    /// An empty stack; `fill` only initialises the array.
    #[inline(always)]
    pub(crate) fn new(fill: T) -> Stack<T> {
        Stack {
            items: [fill; STACK],
            len: 0,
            spill: Vec::new(),
        }
    }

    #[inline(always)]
    pub(crate) fn push(&mut self, item: T) {
        if self.len < STACK {
            self.items[self.len] = item;
            self.len += 1;
        } else {
            self.spill.push(item);
        }
    }

    #[inline(always)]
    pub(crate) fn pop(&mut self) -> Option<T> {
        if let Some(item) = self.spill.pop() {
            return Some(item);
        }
        if self.len == 0 {
            return None;
        }
        self.len -= 1;
        Some(self.items[self.len])
    }
}

impl Bvh {
    /// Closest-hit traversal: `f(slot, t_max)` returns the hit distance (or `f32::INFINITY`);
    /// children are visited nearest first and anything beyond the best hit is skipped.
    #[inline]
    pub(crate) fn closest(&self, ray: &BvhRay, mut f: impl FnMut(usize, f32) -> f32) {
        self.closest_leaves(ray, |start, count, mut t_max| {
            for slot in start..start + count {
                let t = f(slot, t_max);
                if t < t_max {
                    t_max = t;
                }
            }
            t_max
        });
    }

    /// [`Bvh::closest`] a leaf at a time: `f(start, count, t_max)` gets the leaf's start field
    /// (its first slot, or its first block after [`Bvh::into_blocks`]) and its primitive count,
    /// and returns the nearest hit so far (at most `t_max`).
    #[inline]
    pub(crate) fn closest_leaves(&self, ray: &BvhRay, mut f: impl FnMut(usize, usize, f32) -> f32) {
        if self.nodes.is_empty() {
            return;
        }
        let mut t_max = ray.t_max;
        let mut stack = Stack::new((0u32, 0f32));
        let mut node = 0u32;
        loop {
            let (near, mut mask) = test(&self.nodes[node as usize], ray, t_max);
            let children = &self.nodes[node as usize].child;
            // Inner children met, to be visited nearest first.
            let mut inner = [(0u32, 0f32); WIDTH];
            let mut count = 0;
            while mask != 0 {
                let lane = mask.trailing_zeros() as usize;
                mask &= mask - 1;
                let c = children[lane];
                if c & LEAF == 0 {
                    // Insertion into a list sorted by distance, farthest first.
                    let mut k = count;
                    while k > 0 && inner[k - 1].1 < near[lane] {
                        inner[k] = inner[k - 1];
                        k -= 1;
                    }
                    inner[k] = (c, near[lane]);
                    count += 1;
                } else if c != EMPTY && near[lane] <= t_max {
                    let (start, n) = leaf_parts(c);
                    let t = f(start, n, t_max);
                    if t < t_max {
                        t_max = t;
                    }
                }
            }
            // The nearest goes next without a trip through the stack (the same order as
            // pushing it last and popping it).
            if let Some((&(n, d), farther)) = inner[..count].split_last() {
                for &item in farther {
                    stack.push(item);
                }
                if d <= t_max {
                    node = n;
                    continue;
                }
            }
            node = loop {
                match stack.pop() {
                    Some((n, d)) if d <= t_max => break n,
                    Some(_) => continue,
                    None => return,
                }
            };
        }
    }

    /// Any-hit traversal: stops at the first slot for which `f` returns true.
    #[inline]
    pub(crate) fn any(&self, ray: &BvhRay, mut f: impl FnMut(usize) -> bool) -> bool {
        self.any_leaves(ray, |start, count| (start..start + count).any(&mut f))
    }

    /// [`Bvh::any`] a leaf at a time: `f(start, count)` as in [`Bvh::closest_leaves`].
    #[inline]
    pub(crate) fn any_leaves(&self, ray: &BvhRay, mut f: impl FnMut(usize, usize) -> bool) -> bool {
        if self.nodes.is_empty() {
            return false;
        }
        let mut stack = Stack::new((0u32, 0f32));
        let mut node = 0u32;
        loop {
            let (_, mut mask) = test(&self.nodes[node as usize], ray, ray.t_max);
            let children = &self.nodes[node as usize].child;
            // The last inner child met: it goes next, as if pushed and popped at once.
            let mut last = None;
            while mask != 0 {
                let lane = mask.trailing_zeros() as usize;
                mask &= mask - 1;
                let c = children[lane];
                if c & LEAF == 0 {
                    if let Some(earlier) = last.replace(c) {
                        stack.push((earlier, 0.0));
                    }
                } else if c != EMPTY {
                    let (start, n) = leaf_parts(c);
                    if f(start, n) {
                        return true;
                    }
                }
            }
            match last.or_else(|| stack.pop().map(|(n, _)| n)) {
                Some(n) => node = n,
                None => return false,
            }
        }
    }

    /// Visits every slot whose box the ray meets (an any-hit traversal that never stops; the
    /// tests').
    #[cfg(test)]
    pub(crate) fn all(&self, ray: &BvhRay, mut f: impl FnMut(usize)) {
        self.any(ray, |slot| {
            f(slot);
            false
        });
    }
}
