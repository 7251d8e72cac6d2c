//! BVHs over boxes with obvhs (compressed wide BVH8): the top level over every bounded object
//! and one per mesh. Traversal is f32; exact hits stay with the callers, who side-store them.

use std::time::{Duration, Instant};

use glam::{DVec3, Vec3A};
use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb as BAabb;
use obvhs::cwbvh::CwBvh;
use obvhs::cwbvh::builder::build_cwbvh;
use obvhs::ray::{Ray as BRay, RayHit};

use super::Aabb;

/// A BVH over a list of boxes; primitive ids in callbacks index [`Bvh::order`].
#[derive(Clone, Debug)]
pub struct Bvh {
    cw: CwBvh,
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

impl Bvh {
    /// Builds over `boxes`; `ids[i]` is reported for `boxes[i]`.
    pub fn build(boxes: &[BAabb], ids: Vec<u32>, quality: BvhBuildParams) -> Bvh {
        let start = Instant::now();
        let mut core = Duration::default();
        let cw = build_cwbvh(boxes, quality, &mut core);
        let order = cw
            .primitive_indices
            .iter()
            .map(|&i| ids.get(i as usize).copied().unwrap_or(u32::MAX))
            .collect();
        Bvh {
            cw,
            order,
            build_time: start.elapsed(),
        }
    }

    /// Number of nodes (for memory statistics).
    pub fn node_count(&self) -> usize {
        self.cw.nodes.len()
    }

    /// Approximate heap bytes.
    pub fn memory(&self) -> usize {
        self.cw.nodes.len() * std::mem::size_of::<obvhs::cwbvh::node::CwBvhNode>()
            + self.cw.primitive_indices.len() * 4
            + self.order.len() * 4
    }

    /// Closest-hit traversal: `f(slot, t_max)` returns the hit distance or `f32::INFINITY`.
    #[inline]
    pub fn closest(&self, ray: BRay, mut f: impl FnMut(usize, f32) -> f32) {
        let mut hit = RayHit::none();
        self.cw.ray_traverse(ray, &mut hit, |r, id| f(id, r.tmax));
    }

    /// Any-hit traversal: stops at the first slot for which `f` returns true.
    #[inline]
    pub fn any(&self, ray: BRay, mut f: impl FnMut(usize) -> bool) -> bool {
        !self
            .cw
            .ray_traverse_miss(ray, |_, id| if f(id) { 0.0 } else { f32::INFINITY })
    }

    /// Visits every slot whose box the ray meets.
    #[inline]
    pub fn all(&self, ray: BRay, f: impl FnMut(usize)) {
        let mut f = f;
        self.cw.ray_traverse_anyhit(ray, |_, id| f(id));
    }
}
