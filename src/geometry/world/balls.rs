//! Compact storage for the commonest object of large scenes: an untransformed sphere that stands
//! still, kept by the world as a [`Ball`] (centre, radius, material and object: 40 bytes) instead
//! of a [`Primitive`] (about three times that, plus its surface record). A ball answers every
//! query exactly as the primitive it replaces would (the same functions compute its hits), so
//! images do not depend on which of the two holds a sphere.

use glam::DVec3;

use crate::geometry::shapes::Leaf;
use crate::geometry::world::primitive::{
    GeoHit, Geom, Primitive, SurfaceId, plain_sphere_hit, plain_sphere_hit_at,
};
use crate::geometry::{aabb::Aabb, ray::MappingFrame, ray::Ray, shapes::sphere};
use crate::ir::MaterialId;

/// Tag bit of a ball in the world's object ids and in its surface ids (untagged ids are
/// primitives and their surfaces); the BVH indexes at most 2²⁶ objects, far below it.
pub(crate) const BALL: u32 = 1 << 31;

/// An untransformed, unmoving sphere of the world.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Ball {
    /// Centre (world space).
    pub(crate) center: DVec3,
    /// Radius.
    pub(crate) radius: f64,
    /// The material to shade with.
    pub(crate) material: MaterialId,
    /// The top-level scene object it is.
    pub(crate) object: u32,
}

impl Ball {
    /// The ball a prepared top-level object is, when it is a plain sphere (no transform, no
    /// motion); `object` is its index among the scene's objects.
    fn of(p: &Primitive, object: u32) -> Option<Ball> {
        match (&p.geom, &p.placement, &p.moving) {
            (Geom::Leaf(Leaf::Sphere { center, radius }), None, None) => Some(Ball {
                center: *center,
                radius: *radius,
                material: p.material,
                object,
            }),
            _ => None,
        }
    }

    /// The surface id of ball number `index`.
    fn surface(index: u32) -> SurfaceId {
        SurfaceId(BALL | index)
    }

    /// Nearest hit in (t_min, t_max), ball number `index`, without uv (see [`Ball::finish`]).
    #[inline]
    pub(crate) fn intersect(
        &self,
        index: u32,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
    ) -> Option<GeoHit> {
        plain_sphere_hit(
            self.center,
            self.radius,
            ray,
            t_min,
            t_max,
            Ball::surface(index),
            self.material,
        )
    }

    /// [`Ball::intersect`]'s hit at a `t` the same test already found (the world's lanes).
    #[inline]
    pub(crate) fn hit_at(&self, index: u32, ray: &Ray, t: f64) -> GeoHit {
        plain_sphere_hit_at(
            self.center,
            self.radius,
            ray,
            t,
            Ball::surface(index),
            self.material,
        )
    }

    /// True when the sphere lies in (t_min, t_max) along the ray.
    #[inline]
    pub(crate) fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        sphere::hit_t(self.center, self.radius, ray, t_min, t_max).is_some()
    }

    /// Adds the uv that `intersect` leaves out, as [`Primitive::finish`] does for a sphere.
    pub(crate) fn finish(&self, h: &mut GeoHit) {
        h.uv = self.frame().spherical_uv(h.local_point);
    }

    /// The frame texture mappings read its hits in.
    pub(crate) fn frame(&self) -> MappingFrame {
        MappingFrame::Sphere {
            center: self.center,
            radius: self.radius,
        }
    }

    /// World-space bounds.
    pub(crate) fn bounds(&self) -> Aabb {
        sphere::bounds(self.center, self.radius)
    }
}

/// The prepared top-level objects of a world, as the preparation stage hands them over: plain
/// spheres go straight into compact storage, everything else stays a [`Primitive`].
#[derive(Debug, Default)]
pub(crate) struct WorldParts {
    pub(crate) nodes: Vec<Primitive>,
    /// Scene object index of each node (increasing).
    pub(crate) object_of: Vec<u32>,
    pub(crate) balls: Vec<Ball>,
}

impl WorldParts {
    /// Adds the prepared top-level object `p`, scene object number `object` (objects are added
    /// in increasing order).
    pub(crate) fn push(&mut self, p: Primitive, object: u32) {
        match Ball::of(&p, object) {
            Some(b) => self.balls.push(b),
            None => {
                self.nodes.push(p);
                self.object_of.push(object);
            }
        }
    }

    /// Adds a ball made without its primitive (what [`WorldParts::push`] would make of it),
    /// scene object number `b.object` (objects are added in increasing order).
    pub(crate) fn push_ball(&mut self, b: Ball) {
        self.balls.push(b);
    }
}

#[cfg(test)]
mod tests {
    use crate::num::Norm;
    use glam::DAffine3;

    use super::*;
    use crate::geometry::world::World;

    /// Issue 12's rule for lean geometry: a sphere in 32–64 bytes.
    #[test]
    fn a_ball_takes_at_most_64_bytes() {
        assert!(std::mem::size_of::<Ball>() <= 64);
    }

    fn sphere(center: DVec3, radius: f64, material: u32) -> Primitive {
        let geom = Geom::Leaf(Leaf::Sphere { center, radius });
        Primitive::new(geom, DAffine3::IDENTITY, MaterialId(material))
    }

    /// A world of balls answers every ray as the primitives they replace do, tested one by
    /// one: the same t, point, normals, uv, error bound and material, the right object and
    /// frame; with a BVH (30 spheres) and without one (5 spheres).
    #[test]
    fn balls_hit_exactly_like_the_primitives_they_replace() {
        let mut rnd = crate::geometry::testing::test_uniform(17);
        for count in [5, 30] {
            let prims: Vec<Primitive> = (0..count)
                .map(|i| {
                    let c = DVec3::new(rnd(), rnd(), rnd()) * 8.0 - 4.0;
                    sphere(c, 0.2 + rnd(), i)
                })
                .collect();
            let mut parts = WorldParts::default();
            for (i, p) in prims.iter().enumerate() {
                // Object numbers with gaps, as when some objects failed to prepare.
                parts.push(p.clone(), 2 * i as u32);
            }
            assert_eq!((parts.balls.len(), parts.nodes.len()), (count as usize, 0));
            let world = World::new(parts, u64::MAX);
            for _ in 0..400 {
                let origin = DVec3::new(rnd(), rnd(), rnd()) * 20.0 - 10.0;
                let dir = (DVec3::new(rnd(), rnd(), rnd()) - 0.5).unit();
                let ray = Ray::new(origin, dir);
                let mut want: Option<(GeoHit, usize)> = None;
                let mut far = f64::INFINITY;
                for (i, p) in prims.iter().enumerate() {
                    if let Some(h) = p.intersect(&ray, 1e-9, far) {
                        far = h.t;
                        want = Some((h, i));
                    }
                }
                let got = world.intersect(&ray, 1e-9, f64::INFINITY);
                assert_eq!(world.occluded(&ray, 1e-9, f64::INFINITY), want.is_some());
                let (Some(got), Some((mut want, i))) = (got, want) else {
                    assert!(got.is_none() && want.is_none(), "{count} spheres: {ray:?}");
                    continue;
                };
                prims[i].finish(&mut want);
                assert_eq!(
                    (got.t, got.surface_point, got.normal, got.geometric_normal),
                    (want.t, want.point, want.normal, want.geometric_normal)
                );
                assert_eq!(
                    (got.uv, got.local_point, got.error, got.material),
                    (want.uv, want.local_point, want.error, want.material)
                );
                assert_eq!(world.object(&got), 2 * i as u32);
                let Geom::Leaf(leaf) = &prims[i].geom else {
                    unreachable!()
                };
                assert_eq!(world.frame(&got), leaf.frame());
            }
        }
    }
}
