//! What a packet of rays can meet at all: the world's bounds, padded, tested for every camera
//! ray before any object is, so the camera samples that see only background cost a slab test
//! (issue 12: on the course duck 42% of the camera packets miss the mesh's box, and each of
//! them cost as much as a sixth of a packet that hits, in set-up that found nothing).
//!
//! The test only ever drops rays that meet nothing: every object's bounds hold its hits (the
//! BVH relies on the same), the box is padded, and the slab test's few roundings are covered
//! by a relative slack a million times larger; a NaN anywhere keeps the ray.

use wide::f64x4;

use super::World;
use crate::geometry::aabb::Aabb;
use crate::geometry::lanes::RayLanes;
use crate::lanes::{self, Lanes, Mask, WIDTH};

/// Relative padding of the world's box and relative slack of the slab test: far above the
/// test's rounding (a few ulps, ~1e-15) and far below anything a scene can resolve.
const SLACK: f64 = 1e-9;

/// `bounds` (the world's: every object's box holds its hits) padded by [`SLACK`] of its size;
/// an empty box stays empty.
pub(crate) fn padded(bounds: Aabb) -> Aabb {
    if bounds.is_empty() {
        return bounds;
    }
    let size = bounds.min.abs().max(bounds.max.abs()).max_element()
        + (bounds.max - bounds.min).max_element();
    let pad = glam::DVec3::splat(SLACK * size);
    Aabb::new(bounds.min - pad, bounds.max + pad)
}

impl World {
    /// The rays of `live` that may meet something from t = 0 on (all of them when something
    /// is unbounded); the others meet nothing at all.
    #[inline]
    pub(crate) fn may_meet(&self, rays: &RayLanes, live: Mask) -> Mask {
        match self.reach {
            None => live,
            Some(reach) => meet_box(reach, rays, live),
        }
    }
}

/// The rays of `live` whose segment from t = 0 on may meet `reach`, four lanes at a time.
/// Kept out of line so that it does not change the compiler's choices in the packet trace.
#[inline(never)]
fn meet_box(reach: Aabb, rays: &RayLanes, live: Mask) -> Mask {
    if reach.is_empty() {
        return 0;
    }
    let (o, d) = (&rays.origin, &rays.dir);
    let mut open = 0;
    for q in 0..WIDTH / 4 {
        let at = |v: &Lanes| lanes::quad(v, q);
        let (ox, oy, oz) = (at(&o.x), at(&o.y), at(&o.z));
        let (dx, dy, dz) = (at(&d.x), at(&d.y), at(&d.z));
        let (nx, fx) = slab(reach.min.x, reach.max.x, ox, dx);
        let (ny, fy) = slab(reach.min.y, reach.max.y, oy, dy);
        let (nz, fz) = slab(reach.min.z, reach.max.z, oz, dz);
        let entry = nx.fast_max(ny).fast_max(nz);
        let exit = fx.fast_min(fy).fast_min(fz);
        // An infinite entry or exit comes from a ray parallel to a slab outside it, a sure
        // miss: no slack there (the sum would be infinite).
        let slack = f64x4::splat(SLACK) * (entry.abs() + exit.abs());
        let slack = slack.is_finite().select(slack, f64x4::ZERO);
        let missed = entry.simd_gt(exit + slack) | exit.simd_lt(-slack);
        // A ray with a NaN or infinite part is kept: the slab arithmetic says nothing of it.
        let odd = !(ox + oy + oz + dx + dy + dz).is_finite();
        open |= (!missed | odd).to_bitmask() << (4 * q);
    }
    live & open
}

/// The parameters at which four rays (origin `o`, direction `d` along one axis) enter and
/// leave the slab `lo ≤ x ≤ hi`, entering first. A ray parallel to the slab (its 1/d
/// infinite) is in it for every t or for none, by where it starts; this also keeps out the
/// NaN of 0·∞ from a ray starting on a face.
#[inline(always)]
fn slab(lo: f64, hi: f64, o: f64x4, d: f64x4) -> (f64x4, f64x4) {
    let inv = f64x4::ONE / d;
    let t0 = (f64x4::splat(lo) - o) * inv;
    let t1 = (f64x4::splat(hi) - o) * inv;
    let parallel = inv.is_inf();
    let inside = o.simd_ge(f64x4::splat(lo)) & o.simd_le(f64x4::splat(hi));
    let (never, always) = (f64x4::splat(f64::INFINITY), f64x4::splat(f64::NEG_INFINITY));
    let near = parallel.select(inside.select(always, never), t0.fast_min(t1));
    let far = parallel.select(inside.select(never, always), t0.fast_max(t1));
    (near, far)
}

#[cfg(test)]
mod tests {
    use glam::{DAffine3, DVec3};

    use super::*;
    use crate::geometry::ray::Ray;
    use crate::geometry::shapes::Leaf;
    use crate::geometry::world::balls::WorldParts;
    use crate::geometry::world::primitive::Geom;
    use crate::geometry::world::primitive::Primitive;
    use crate::ir::MaterialId;
    use crate::lanes;
    use crate::num::Norm;

    fn sphere(center: DVec3, radius: f64, stretch: DVec3) -> Primitive {
        let geom = Geom::Leaf(Leaf::Sphere { center, radius });
        Primitive::new(geom, DAffine3::from_scale(stretch), MaterialId(0))
    }

    fn world_of(prims: Vec<Primitive>) -> World {
        let mut parts = WorldParts::default();
        for (i, p) in prims.into_iter().enumerate() {
            parts.push(p, i as u32);
        }
        World::new(parts, u64::MAX)
    }

    /// The lanes of `rays` that `world` keeps (lanes past the rays are not live).
    fn kept(world: &World, rays: &[Ray]) -> Vec<bool> {
        let mask = world.may_meet(&RayLanes::of(rays), lanes::first(rays.len()));
        (0..rays.len()).map(|i| mask & (1 << i) != 0).collect()
    }

    /// The rule the renderer relies on: a dropped ray hits nothing, for rays from inside,
    /// outside and on the edge of a world of balls and stretched spheres (nodes), with and
    /// without a BVH; and the test does drop rays (it is not a test that cannot fail).
    #[test]
    fn a_dropped_ray_meets_nothing() {
        let mut rnd = crate::geometry::testing::test_uniform(29);
        for count in [3, 40] {
            let prims = (0..count)
                .map(|i| {
                    let c = DVec3::new(rnd(), rnd(), rnd()) * 6.0 - 3.0;
                    let stretch = if i % 2 == 0 {
                        DVec3::ONE
                    } else {
                        DVec3::new(1.5, 0.5, 1.0)
                    };
                    sphere(c, 0.1 + 0.5 * rnd(), stretch)
                })
                .collect();
            let world = world_of(prims);
            let (mut dropped, mut total) = (0, 0);
            for _ in 0..300 {
                let rays: Vec<Ray> = (0..lanes::WIDTH)
                    .map(|_| {
                        let origin = DVec3::new(rnd(), rnd(), rnd()) * 24.0 - 12.0;
                        let dir = (DVec3::new(rnd(), rnd(), rnd()) - 0.5).unit();
                        Ray::new(origin, dir)
                    })
                    .collect();
                for (ray, keep) in rays.iter().zip(kept(&world, &rays)) {
                    total += 1;
                    if !keep {
                        dropped += 1;
                        let hit = world.intersect(ray, 1e-9, f64::INFINITY);
                        assert!(hit.is_none(), "{count} objects: dropped {ray:?} hits");
                    }
                }
            }
            assert!(
                dropped > total / 4 && dropped < total,
                "{dropped} of {total} dropped"
            );
        }
    }

    /// Hand-made cases around a unit sphere at the origin (box ±1, padded by ~2e-9): aimed at
    /// it, away from it, past it, from inside, parallel to an axis inside and outside the
    /// slab, and lying in a face of the box (the NaN case).
    #[test]
    fn the_box_test_keeps_what_it_must_and_drops_what_it_may() {
        let world = world_of(vec![sphere(DVec3::ZERO, 1.0, DVec3::ONE)]);
        let top = world.reach.expect("bounded").max.y;
        assert!(top > 1.0 && top < 1.0 + 1e-8, "padded top {top}");
        let ray = |o: [f64; 3], d: [f64; 3]| Ray::new(DVec3::from(o), DVec3::from(d).unit());
        let rays = [
            ray([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]),        // aimed at it
            ray([0.0, 0.0, -5.0], [0.0, 0.0, -1.0]),       // away: the box is behind
            ray([0.0, 3.0, -5.0], [0.0, 0.0, 1.0]),        // past it
            ray([0.2, 0.1, 0.3], [0.3, -0.5, 0.8]),        // from inside
            ray([0.9, -0.9, 7.0], [0.0, 0.0, -1.0]),       // parallel to z in the slab
            ray([1.1, 0.0, 7.0], [0.0, 0.0, -1.0]),        // parallel to z beside it
            ray([-5.0, top, 0.0], [1.0, 0.0, 0.0]),        // in the padded box's top face
            ray([-5.0, 1.0 + 1e-6, 0.0], [1.0, 0.0, 0.0]), // just above it
            ray([-5.0, -5.0, 0.0], [1.0, 1.0, 0.0]),       // through the corner region
            ray([-5.0, -2.9, 0.0], [1.0, 1.0, 0.0]),       // beside the corner
        ];
        let want = [
            true, false, false, true, true, false, true, false, true, false,
        ];
        assert_eq!(kept(&world, &rays), want);
    }

    /// A ray with a NaN or infinite part is kept whatever else it says (the renderer's own
    /// tests decide what it meets), beside ordinary lanes in the same group of four.
    #[test]
    fn odd_rays_are_kept() {
        let world = world_of(vec![sphere(DVec3::ZERO, 1.0, DVec3::ONE)]);
        let away = Ray::new(DVec3::new(0.0, 5.0, 0.0), DVec3::Y);
        let mut rays = [away; 6];
        rays[1].origin.x = f64::NAN;
        rays[2].dir.z = f64::NAN;
        rays[4].origin.y = f64::INFINITY;
        assert_eq!(kept(&world, &rays), [false, true, true, false, true, false]);
    }

    /// Something unbounded (a plane) keeps every ray; an empty world drops every ray.
    #[test]
    fn unbounded_worlds_keep_all_and_empty_worlds_none() {
        let plane = Leaf::Plane {
            point: DVec3::ZERO,
            normal: DVec3::Y,
        };
        let plane = Primitive::new(Geom::Leaf(plane), DAffine3::IDENTITY, MaterialId(0));
        let unbounded = world_of(vec![plane, sphere(DVec3::ZERO, 1.0, DVec3::ONE)]);
        let away = [Ray::new(DVec3::new(0.0, 5.0, 0.0), DVec3::Y); 3];
        assert_eq!(kept(&unbounded, &away), [true; 3]);
        assert_eq!(kept(&world_of(Vec::new()), &away), [false; 3]);
    }
}
