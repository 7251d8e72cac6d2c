//! Axis-aligned bounding boxes.

use glam::{DAffine3, DVec3};

use crate::geometry::ray::Ray;

/// An axis-aligned box; `EMPTY` has min > max.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// Minimum corner.
    pub min: DVec3,
    /// Maximum corner.
    pub max: DVec3,
}

impl Aabb {
    /// The empty box (the identity of `union`).
    pub(crate) const EMPTY: Aabb = Aabb {
        min: DVec3::splat(f64::INFINITY),
        max: DVec3::splat(f64::NEG_INFINITY),
    };

    /// A box from two corners.
    pub fn new(min: DVec3, max: DVec3) -> Aabb {
        Aabb { min, max }
    }

    /// The smallest box containing both.
    pub(crate) fn union(self, other: Aabb) -> Aabb {
        Aabb::new(self.min.min(other.min), self.max.max(other.max))
    }

    /// The overlap of both (may be empty).
    pub(crate) fn intersection(self, other: Aabb) -> Aabb {
        Aabb::new(self.min.max(other.min), self.max.min(other.max))
    }

    /// True when min ≤ max on every axis.
    pub fn is_empty(&self) -> bool {
        self.min.cmpgt(self.max).any()
    }

    /// True when every coordinate is finite.
    pub fn is_finite(&self) -> bool {
        self.min.is_finite() && self.max.is_finite()
    }

    /// Centre point.
    pub fn center(&self) -> DVec3 {
        0.5 * (self.min + self.max)
    }

    /// True when `p` lies inside or on the box, with tolerance `eps`.
    pub fn contains(&self, p: DVec3, eps: f64) -> bool {
        p.cmpge(self.min - eps).all() && p.cmple(self.max + eps).all()
    }

    /// The bounds of this box after an affine transform (all eight corners).
    pub fn transformed(&self, m: &DAffine3) -> Aabb {
        if self.is_empty() || !self.is_finite() {
            return *self;
        }
        let mut out = Aabb::EMPTY;
        for i in 0..8 {
            let c = DVec3::new(
                if i & 1 == 0 { self.min.x } else { self.max.x },
                if i & 2 == 0 { self.min.y } else { self.max.y },
                if i & 4 == 0 { self.min.z } else { self.max.z },
            );
            let p = m.transform_point3(c);
            out = out.union(Aabb::new(p, p));
        }
        out
    }

    /// Slab test: the parameter interval where the ray is inside the box, if it meets [t_min, t_max].
    pub(crate) fn hit_interval(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(f64, f64)> {
        let inv = ray.dir.recip();
        let t0 = (self.min - ray.origin) * inv;
        let t1 = (self.max - ray.origin) * inv;
        let near = t0.min(t1).max_element().max(t_min);
        let far = t0.max(t1).min_element().min(t_max);
        (near <= far).then_some((near, far))
    }
}
