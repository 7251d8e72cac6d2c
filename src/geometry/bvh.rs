//! BVHs over boxes with obvhs (compressed wide BVH8): the top level over every bounded object
//! and one per mesh. Traversal is f32; exact hits stay with the callers, who side-store them.

use std::time::{Duration, Instant};

use glam::{DVec3, Vec3A};
use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb as BAabb;
use obvhs::bvh2::Bvh2;
use obvhs::bvh2::builder::build_bvh2;
use obvhs::cwbvh::CwBvh;
use obvhs::cwbvh::builder::build_cwbvh;
use obvhs::ray::{Ray as BRay, RayHit};

use super::Aabb;

/// The tree: a compressed wide BVH8 (fastest to traverse) or a binary one (several times
/// faster to build, for meshes so large that building dominates the time to first ray).
#[derive(Clone)]
enum Tree {
    Wide(CwBvh),
    Binary(Bvh2),
}

/// Which tree to build.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BvhKind {
    /// Compressed wide BVH8.
    Wide,
    /// Binary BVH (no wide conversion).
    Binary,
}

/// A BVH over a list of boxes; primitive ids in callbacks index [`Bvh::order`].
#[derive(Clone, Debug)]
pub struct Bvh {
    tree: Tree,
    /// The caller's primitive index for each BVH slot.
    pub order: Vec<u32>,
    /// Time spent building.
    pub build_time: Duration,
}

/// An f32 box that contains the f64 box (rounded outward), or `None` if it does not fit in f32.
pub fn to_f32_box(b: &Aabb) -> Option<BAabb> {
    let lo = b.min.as_vec3a();
    let hi = b.max.as_vec3a();
    let down = |v: Vec3A| Vec3A::new(v.x.next_down(), v.y.next_down(), v.z.next_down());
    let up = |v: Vec3A| Vec3A::new(v.x.next_up(), v.y.next_up(), v.z.next_up());
    let out = BAabb::new(down(lo), up(hi));
    (out.min.is_finite() && out.max.is_finite() && !b.is_empty()).then_some(out)
}

/// The f32 ray for traversal, or `None` when it cannot be represented.
pub fn to_f32_ray(origin: DVec3, dir: DVec3, t_max: f64) -> Option<BRay> {
    // obvhs orders slabs by `dir < 0` but inverts −0.0 to −∞: a negative zero would make
    // every box look empty, so fold it to +0.0.
    let (o, d) = (origin.as_vec3a(), dir.as_vec3a() + Vec3A::ZERO);
    if !o.is_finite() || !d.is_finite() || d == Vec3A::ZERO {
        return None;
    }
    let t_max = if t_max.is_finite() {
        (t_max as f32).next_up()
    } else {
        f32::INFINITY
    };
    Some(BRay::new(o, d, 0.0, t_max))
}

/// Like [`to_f32_ray`] with the f64 reciprocal direction already known (saves the divisions
/// obvhs's constructor would repeat).
pub fn to_f32_ray_inv(origin: DVec3, dir: DVec3, inv: DVec3, t_max: f64) -> Option<BRay> {
    let (o, d) = (origin.as_vec3a(), dir.as_vec3a() + Vec3A::ZERO);
    if !o.is_finite() || !d.is_finite() || d == Vec3A::ZERO {
        return None;
    }
    // obvhs's safe inverse: components within f32::EPSILON of zero invert to ±1/ε.
    let safe = |x: f32, i: f64| {
        if x.abs() <= f32::EPSILON {
            x.signum() / f32::EPSILON
        } else {
            i as f32
        }
    };
    let t_max = if t_max.is_finite() {
        (t_max as f32).next_up()
    } else {
        f32::INFINITY
    };
    Some(BRay {
        origin: o,
        direction: d,
        inv_direction: Vec3A::new(safe(d.x, inv.x), safe(d.y, inv.y), safe(d.z, inv.z)),
        tmin: 0.0,
        tmax: t_max,
    })
}

impl std::fmt::Debug for Tree {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Tree::Wide(t) => write!(f, "Wide({} nodes)", t.nodes.len()),
            Tree::Binary(t) => write!(f, "Binary({} nodes)", t.nodes.len()),
        }
    }
}

impl Bvh {
    /// Builds over `boxes`; `ids[i]` is reported for `boxes[i]`.
    pub fn build(boxes: &[BAabb], ids: Vec<u32>, quality: BvhBuildParams, kind: BvhKind) -> Bvh {
        let start = Instant::now();
        let mut core = Duration::default();
        let (tree, indices) = match kind {
            BvhKind::Wide => {
                let cw = build_cwbvh(boxes, quality, &mut core);
                let idx = cw.primitive_indices.clone();
                (Tree::Wide(cw), idx)
            }
            BvhKind::Binary => {
                let b = build_bvh2(boxes, quality, &mut core);
                let idx = b.primitive_indices.clone();
                (Tree::Binary(b), idx)
            }
        };
        let order = indices
            .iter()
            .map(|&i| ids.get(i as usize).copied().unwrap_or(u32::MAX))
            .collect();
        Bvh {
            tree,
            order,
            build_time: start.elapsed(),
        }
    }

    /// Approximate heap bytes.
    pub fn memory(&self) -> usize {
        let nodes = match &self.tree {
            Tree::Wide(t) => {
                t.nodes.len() * std::mem::size_of::<obvhs::cwbvh::node::CwBvhNode>()
                    + t.primitive_indices.len() * 4
            }
            Tree::Binary(t) => {
                t.nodes.len() * std::mem::size_of::<obvhs::bvh2::node::Bvh2Node>()
                    + t.primitive_indices.len() * 4
            }
        };
        nodes + self.order.len() * 4
    }

    /// Closest-hit traversal: `f(slot, t_max)` returns the hit distance or `f32::INFINITY`.
    #[inline]
    pub fn closest(&self, ray: BRay, mut f: impl FnMut(usize, f32) -> f32) {
        let mut hit = RayHit::none();
        match &self.tree {
            Tree::Wide(t) => {
                t.ray_traverse(ray, &mut hit, |r, id| f(id, r.tmax));
            }
            Tree::Binary(t) => {
                t.ray_traverse(ray, &mut hit, |r, id| f(id, r.tmax));
            }
        }
    }

    /// Any-hit traversal: stops at the first slot for which `f` returns true.
    #[inline]
    pub fn any(&self, ray: BRay, mut f: impl FnMut(usize) -> bool) -> bool {
        let mut g = |_: &BRay, id: usize| if f(id) { 0.0 } else { f32::INFINITY };
        !match &self.tree {
            Tree::Wide(t) => t.ray_traverse_miss(ray, &mut g),
            Tree::Binary(t) => t.ray_traverse_miss(ray, &mut g),
        }
    }

    /// Visits every slot whose box the ray meets.
    #[inline]
    pub fn all(&self, ray: BRay, mut f: impl FnMut(usize)) {
        match &self.tree {
            Tree::Wide(t) => t.ray_traverse_anyhit(ray, |_, id| f(id)),
            Tree::Binary(t) => t.ray_traverse_anyhit(ray, |_, id| f(id)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Both tree kinds agree with brute force on random boxes for closest, any and all.
    #[test]
    fn both_tree_kinds_match_brute_force() {
        let mut seed = 7u64;
        let mut rnd = move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 33) as f32) / (1u64 << 31) as f32
        };
        let boxes: Vec<BAabb> = (0..500)
            .map(|_| {
                let c = Vec3A::new(rnd(), rnd(), rnd()) * 10.0;
                let h = Vec3A::new(rnd(), rnd(), rnd()) * 0.3 + 0.01;
                BAabb::new(c - h, c + h)
            })
            .collect();
        let ids: Vec<u32> = (0..boxes.len() as u32).collect();
        for kind in [BvhKind::Wide, BvhKind::Binary] {
            let bvh = Bvh::build(&boxes, ids.clone(), BvhBuildParams::fast_build(), kind);
            for _ in 0..300 {
                let o = DVec3::new(-5.0, rnd() as f64 * 10.0, rnd() as f64 * 10.0);
                let d = DVec3::new(1.0, rnd() as f64 - 0.5, rnd() as f64 - 0.5).normalize();
                let r = to_f32_ray(o, d, f64::INFINITY).unwrap();
                let entry = |i: usize| {
                    let t = boxes[i].intersect_ray(&r);
                    (t < f32::INFINITY).then_some(t.max(0.0))
                };
                let want = (0..boxes.len())
                    .filter_map(entry)
                    .fold(f32::INFINITY, f32::min);
                let mut got = f32::INFINITY;
                bvh.closest(r, |slot, _| match entry(bvh.order[slot] as usize) {
                    Some(t) => {
                        got = got.min(t);
                        t
                    }
                    None => f32::INFINITY,
                });
                assert_eq!(got, want, "{kind:?}");
                assert_eq!(
                    bvh.any(r, |slot| entry(bvh.order[slot] as usize).is_some()),
                    want.is_finite()
                );
                let mut n = 0;
                bvh.all(r, |slot| {
                    n += entry(bvh.order[slot] as usize).is_some() as usize
                });
                assert_eq!(
                    n,
                    (0..boxes.len()).filter(|&i| entry(i).is_some()).count(),
                    "{kind:?}"
                );
            }
        }
    }
}
