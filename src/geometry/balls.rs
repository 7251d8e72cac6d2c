//! Compact storage for the commonest object of large scenes: an untransformed sphere that stands
//! still, kept by the world as a [`Ball`] (centre, radius, material and object: 40 bytes) instead
//! of a [`Primitive`] (about three times that, plus its surface record). A ball answers every
//! query exactly as the primitive it replaces would (the same functions compute its hits), so
//! images do not depend on which of the two holds a sphere.

use glam::DVec3;

use super::primitive::{GeoHit, Geom, Primitive, SurfaceId, plain_sphere_hit};
use super::shape::Leaf;
use super::{Aabb, MappingFrame, Ray, sphere};
use crate::ir::MaterialId;

/// Tag bit of a ball in the world's object ids and in its surface ids (untagged ids are
/// primitives and their surfaces); the BVH indexes at most 2²⁶ objects, far below it.
pub(super) const BALL: u32 = 1 << 31;

/// An untransformed, unmoving sphere of the world.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ball {
    /// Centre (world space).
    pub center: DVec3,
    /// Radius.
    pub radius: f64,
    /// The material to shade with.
    pub material: MaterialId,
    /// The top-level scene object it is.
    pub object: u32,
}

impl Ball {
    /// The ball a prepared top-level object is, when it is a plain sphere (no transform, no
    /// motion); `object` is its index among the scene's objects.
    pub fn of(p: &Primitive, object: u32) -> Option<Ball> {
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
    pub(super) fn surface(index: u32) -> SurfaceId {
        SurfaceId(BALL | index)
    }

    /// Nearest hit in (t_min, t_max), ball number `index`, without uv (see [`Ball::finish`]).
    #[inline]
    pub(super) fn intersect(
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

    /// True when the sphere lies in (t_min, t_max) along the ray.
    #[inline]
    pub(super) fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        sphere::hit_t(self.center, self.radius, ray, t_min, t_max).is_some()
    }

    /// Adds the uv that `intersect` leaves out, as [`Primitive::finish`] does for a sphere.
    pub(super) fn finish(&self, h: &mut GeoHit) {
        h.uv = self.frame().spherical_uv(h.local_point);
    }

    /// The frame texture mappings read its hits in.
    pub(super) fn frame(&self) -> MappingFrame {
        MappingFrame::Sphere {
            center: self.center,
            radius: self.radius,
        }
    }

    /// World-space bounds.
    pub(super) fn bounds(&self) -> Aabb {
        sphere::bounds(self.center, self.radius)
    }

    /// Whether the point is inside the ball.
    pub(super) fn contains(&self, p: DVec3) -> bool {
        sphere::contains(self.center, self.radius, p)
    }
}

/// The prepared top-level objects of a world, as the preparation stage hands them over: plain
/// spheres go straight into compact storage, everything else stays a [`Primitive`].
#[derive(Debug, Default)]
pub struct WorldParts {
    pub(super) nodes: Vec<Primitive>,
    /// Scene object index of each node (increasing).
    pub(super) object_of: Vec<u32>,
    pub(super) balls: Vec<Ball>,
}

impl WorldParts {
    /// Adds the prepared top-level object `p`, scene object number `object` (objects are added
    /// in increasing order).
    pub fn push(&mut self, p: Primitive, object: u32) {
        match Ball::of(&p, object) {
            Some(b) => self.balls.push(b),
            None => {
                self.nodes.push(p);
                self.object_of.push(object);
            }
        }
    }

    /// The objects added so far.
    pub fn len(&self) -> usize {
        self.nodes.len() + self.balls.len()
    }

    /// True when nothing was added.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}
