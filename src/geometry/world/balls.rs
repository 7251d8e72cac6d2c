//! Compact storage for the commonest object of large scenes: a sphere that stands still and is
//! either untransformed or only translated, kept by the world as a [`Ball`] (centre, radius,
//! material and object: 40 bytes) instead of a [`Primitive`] (about three times that, plus its
//! surface record and, when translated, a boxed 264-byte placement). A ball answers every
//! query exactly as the primitive it replaces would (the same functions compute its hits), so
//! images do not depend on which of the two holds a sphere.
//!
//! A translated ball is `sphere(radius: r).translate(p)` (its own centre at the origin): it
//! keeps `p` where a plain ball keeps its centre and tests rays the way the primitive does, in
//! object space through the placement `Placement::of(translation p)`, rebuilt from `p` for each
//! test (a few operations) rather than stored. Folding `p` into the centre and testing in
//! world space would round differently (the hit point and normal differ in their last bits,
//! which could change pixels), and the texture frame stays the sphere's own.

use glam::{DAffine3, DMat3, DVec3};

use crate::geometry::shapes::Leaf;
use crate::geometry::world::primitive::{
    GeoHit, Geom, Placement, Primitive, SurfaceId, plain_sphere_hit, plain_sphere_hit_at,
};
use crate::geometry::{aabb::Aabb, ray::MappingFrame, ray::Ray, shapes::sphere};
use crate::ir::MaterialId;

/// Tag bit of a ball in the world's object ids and in its surface ids (untagged ids are
/// primitives and their surfaces); the BVH indexes at most 2²⁶ objects, far below it.
pub(crate) const BALL: u32 = 1 << 31;

/// Flag bit of a translated ball in [`Ball`]'s object number (scene objects number far fewer).
const TRANSLATED: u32 = 1 << 31;

/// A sphere of the world that stands still: untransformed, or a sphere about its own origin
/// that is only translated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Ball {
    /// Centre (world space); for a translated ball, the translation (its own centre is the
    /// origin, so this is its centre in the world too, though its hits are computed from the
    /// ray in object space).
    pub(crate) center: DVec3,
    /// Radius.
    pub(crate) radius: f64,
    /// The material to shade with.
    pub(crate) material: MaterialId,
    /// The top-level scene object it is, with [`TRANSLATED`] set for a translated ball.
    tagged: u32,
}

impl Ball {
    /// The untransformed sphere (`center`, `radius`) of scene object `object`.
    pub(crate) fn plain(center: DVec3, radius: f64, material: MaterialId, object: u32) -> Ball {
        Ball {
            center,
            radius,
            material,
            tagged: object,
        }
    }

    /// The sphere of `radius` about the origin translated by `offset` (finite), scene object
    /// `object`: the ball of a primitive placed by that translation; `None` when `object` is too
    /// large to carry the flag.
    pub(crate) fn translated(
        offset: DVec3,
        radius: f64,
        material: MaterialId,
        object: u32,
    ) -> Option<Ball> {
        (object & TRANSLATED == 0).then_some(Ball {
            center: offset,
            radius,
            material,
            tagged: object | TRANSLATED,
        })
    }

    /// The ball a prepared top-level object is, when it is a sphere that stands still and is
    /// untransformed, or about its own origin (bit for bit) and only translated; `object` is
    /// its index among the scene's objects.
    fn of(p: &Primitive, object: u32) -> Option<Ball> {
        let (Geom::Leaf(Leaf::Sphere { center, radius }), None) = (&p.geom, &p.moving) else {
            return None;
        };
        match &p.placement {
            None => Some(Ball::plain(*center, *radius, p.material, object)),
            Some(place) if is_origin(*center) => {
                Ball::translated(place.translation()?, *radius, p.material, object)
            }
            Some(_) => None,
        }
    }

    /// The top-level scene object it is.
    pub(crate) fn object(&self) -> u32 {
        self.tagged & !TRANSLATED
    }

    /// Whether it is a translated ball (hits computed in its object space).
    pub(crate) fn is_translated(&self) -> bool {
        self.tagged & TRANSLATED != 0
    }

    /// A translated ball's placement, as its primitive held it.
    #[inline]
    fn placement(&self) -> Placement {
        Placement::of(DAffine3::from_translation(self.center))
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
        if self.is_translated() {
            // `Primitive::intersect` of a sphere, step by step.
            let place = self.placement();
            let (r, t_min) = Primitive::local_after(Some(&place), ray, t_min);
            return plain_sphere_hit(
                DVec3::ZERO,
                self.radius,
                &r,
                t_min,
                t_max,
                Ball::surface(index),
                self.material,
            )
            .map(|h| Primitive::out(Some(&place), h));
        }
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

    /// [`Ball::intersect`]'s hit at a `t` the same test already found (the world's lanes,
    /// which hold plain balls only).
    #[inline]
    pub(crate) fn hit_at(&self, index: u32, ray: &Ray, t: f64) -> GeoHit {
        debug_assert!(
            !self.is_translated(),
            "a translated ball in the sphere lanes"
        );
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
        if self.is_translated() {
            let place = self.placement();
            let (r, t_min) = Primitive::local_after(Some(&place), ray, t_min);
            return sphere::hit_t(DVec3::ZERO, self.radius, &r, t_min, t_max).is_some();
        }
        sphere::hit_t(self.center, self.radius, ray, t_min, t_max).is_some()
    }

    /// Adds the uv that `intersect` leaves out, as [`Primitive::finish`] does for a sphere.
    pub(crate) fn finish(&self, h: &mut GeoHit) {
        h.uv = self.frame().spherical_uv(h.local_point);
    }

    /// The frame texture mappings read its hits in (a translated ball's own: about the
    /// origin of its object space, where `local_point` lies).
    pub(crate) fn frame(&self) -> MappingFrame {
        MappingFrame::Sphere {
            center: self.own_center(),
            radius: self.radius,
        }
    }

    /// The matrix that carries a gradient from its object space to world space, as the world
    /// records it for the primitive (`number_surfaces`).
    pub(crate) fn normal_matrix(&self) -> DMat3 {
        match self.is_translated() {
            true => DMat3::IDENTITY * self.placement().normal_matrix,
            false => DMat3::IDENTITY,
        }
    }

    /// World-space bounds (a translated ball's as `Primitive::new` computes them).
    pub(crate) fn bounds(&self) -> Aabb {
        match self.is_translated() {
            true => sphere::bounds(DVec3::ZERO, self.radius)
                .transformed(&DAffine3::from_translation(self.center)),
            false => sphere::bounds(self.center, self.radius),
        }
    }

    /// The centre in its own space.
    fn own_center(&self) -> DVec3 {
        match self.is_translated() {
            true => DVec3::ZERO,
            false => self.center,
        }
    }
}

/// Whether `c` is the origin bit for bit (`-0.0` is not: the sphere's own arithmetic would
/// differ in the sign of a zero).
pub(crate) fn is_origin(c: DVec3) -> bool {
    c.to_array().map(f64::to_bits) == [0; 3]
}

/// The prepared top-level objects of a world, as the preparation stage hands them over: plain
/// and translated spheres go straight into compact storage, everything else stays a
/// [`Primitive`].
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
    /// scene object number `b.object()` (objects are added in increasing order).
    pub(crate) fn push_ball(&mut self, b: Ball) {
        self.balls.push(b);
    }
}

#[cfg(test)]
mod tests {
    use crate::num::Norm;

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

    /// `sphere(radius: radius).translate(offset)` as the preparation stage makes it.
    fn translated(offset: DVec3, radius: f64, material: u32) -> Primitive {
        let geom = Geom::Leaf(Leaf::Sphere {
            center: DVec3::ZERO,
            radius,
        });
        let t = DAffine3::from_translation(offset);
        Primitive::new(geom, t, MaterialId(material))
    }

    /// A world of balls answers every ray as the primitives they replace do, tested one by
    /// one: the same t, point, normals, uv, error bound and material, the right object,
    /// frame and normal matrix, the same bounds; with a BVH (30 spheres) and without one (5
    /// spheres), plain and translated balls mixed (every third sphere is plain; the offsets
    /// include zero components of either sign, where a world-space fold would differ).
    #[test]
    fn balls_hit_exactly_like_the_primitives_they_replace() {
        let mut rnd = crate::geometry::testing::test_uniform(17);
        for count in [5, 30] {
            let prims: Vec<Primitive> = (0..count)
                .map(|i| {
                    let mut c = DVec3::new(rnd(), rnd(), rnd()) * 8.0 - 4.0;
                    if i % 4 == 1 {
                        c.x = if i % 8 == 1 { 0.0 } else { -0.0 };
                    }
                    match i % 3 {
                        0 => sphere(c, 0.2 + rnd(), i),
                        _ => translated(c, 0.2 + rnd(), i),
                    }
                })
                .collect();
            let want_bounds = prims.iter().fold(Aabb::EMPTY, |b, p| b.union(p.bounds));
            let mut parts = WorldParts::default();
            for (i, p) in prims.iter().enumerate() {
                // Object numbers with gaps, as when some objects failed to prepare.
                parts.push(p.clone(), 2 * i as u32);
            }
            // A translation by -0.0 alone is the identity (no placement): a plain ball.
            let plain = prims.iter().filter(|p| p.placement.is_none()).count();
            let shifted = parts.balls.iter().filter(|b| b.is_translated()).count();
            assert_eq!((parts.balls.len(), parts.nodes.len()), (count as usize, 0));
            assert_eq!(shifted, count as usize - plain);
            let world = World::new(parts, u64::MAX);
            assert_eq!(world.bounds(), want_bounds);
            for k in 0..400 {
                let mut origin = DVec3::new(rnd(), rnd(), rnd()) * 20.0 - 10.0;
                if k % 5 == 0 {
                    origin.x = if k % 10 == 0 { 0.0 } else { -0.0 };
                }
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
                let want = DMat3::IDENTITY * prims[i].normal_matrix();
                assert_eq!(world.normal_matrix(&got), want);
            }
        }
    }
}
