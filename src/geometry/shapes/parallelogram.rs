//! Parallelograms `corner + s·u + t·v`.

use crate::num::Norm;
use glam::{DVec2, DVec3};

use crate::geometry::{aabb::Aabb, ray::Hit, ray::Ray};

/// A parallelogram in object space; its front normal is `u × v`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Quad {
    corner: DVec3,
    u: DVec3,
    v: DVec3,
    /// `u × v`, unnormalised.
    n: DVec3,
    normal: DVec3,
}

impl Quad {
    /// A quad from a corner and two edges; `None` when the edges are parallel.
    pub(crate) fn new(corner: DVec3, u: DVec3, v: DVec3) -> Option<Quad> {
        let n = u.cross(v);
        let normal = n.try_unit()?;
        Some(Quad {
            corner,
            u,
            v,
            n,
            normal,
        })
    }

    /// Nearest hit in (t_min, t_max); uv = (s, t).
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let denom = self.n.dot(ray.dir);
        if denom == 0.0 {
            return None;
        }
        let t = (self.corner - ray.origin).dot(self.n) / denom;
        if !(t > t_min && t < t_max) {
            return None;
        }
        let w = ray.at(t) - self.corner;
        let nn = self.n.length_squared();
        let s = w.cross(self.v).dot(self.n) / nn;
        let r = self.u.cross(w).dot(self.n) / nn;
        ((0.0..=1.0).contains(&s) && (0.0..=1.0).contains(&r)).then_some(Hit {
            t,
            normal: self.normal,
            uv: DVec2::new(s, r),
        })
    }

    /// Error bound of a computed point `p` on it: its residual off its plane.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        crate::geometry::shapes::plane::point_error(self.corner, self.normal, p)
    }

    /// Object-space bounds.
    pub(crate) fn bounds(&self) -> Aabb {
        let c = self.corner;
        [c + self.u, c + self.v, c + self.u + self.v]
            .into_iter()
            .fold(Aabb::new(c, c), |b, p| b.union(Aabb::new(p, p)))
    }
}
