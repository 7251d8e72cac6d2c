//! Flat disks.

use crate::num::Norm;
use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use crate::geometry::{aabb::Aabb, ray::Hit, ray::Ray};

/// A disk in object space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Disk {
    center: DVec3,
    normal: DVec3,
    radius: f64,
    /// In-plane frame for texture coordinates.
    e1: DVec3,
    e2: DVec3,
}

impl Disk {
    /// A disk; `None` for a zero normal or a non-positive radius.
    pub(crate) fn new(center: DVec3, normal: DVec3, radius: f64) -> Option<Disk> {
        let normal = normal.try_unit()?;
        if !(radius > 0.0 && radius.is_finite()) {
            return None;
        }
        let e1 = normal.any_orthonormal_vector();
        Some(Disk {
            center,
            normal,
            radius,
            e1,
            e2: normal.cross(e1),
        })
    }

    /// Nearest hit in (t_min, t_max); uv = (angle / 2π, distance / radius).
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let (t, x, y, r2) = self.plane_hit(ray, t_min, t_max)?;
        if r2 > self.radius * self.radius {
            return None;
        }
        let angle = libm::atan2(y, x).rem_euclid(TAU);
        Some(Hit {
            t,
            normal: self.normal,
            uv: DVec2::new(angle / TAU, r2.sqrt() / self.radius),
        })
    }

    /// Where `ray` meets the disk's plane in (t_min, t_max): `t`, the point's in-plane
    /// coordinates (x, y) about the centre and its squared distance from the centre (shared
    /// with [`super::ring::Ring`], which cuts a hole by that distance).
    #[inline]
    pub(crate) fn plane_hit(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
    ) -> Option<(f64, f64, f64, f64)> {
        let denom = self.normal.dot(ray.dir);
        if denom == 0.0 {
            return None;
        }
        let t = (self.center - ray.origin).dot(self.normal) / denom;
        if !(t > t_min && t < t_max) {
            return None;
        }
        let w = ray.at(t) - self.center;
        let (x, y) = (w.dot(self.e1), w.dot(self.e2));
        Some((t, x, y, x * x + y * y))
    }

    /// The disk's radius.
    pub(crate) fn radius(&self) -> f64 {
        self.radius
    }

    /// The disk's unit normal.
    pub(crate) fn normal(&self) -> DVec3 {
        self.normal
    }

    /// Error bound of a computed point `p` on it: its residual off its plane.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        crate::geometry::shapes::plane::point_error(self.center, self.normal, p)
    }

    /// Object-space bounds (tight per axis: radius·√(1 − n_i²)).
    pub(crate) fn bounds(&self) -> Aabb {
        let ext = self.radius
            * (DVec3::ONE - self.normal * self.normal)
                .max(DVec3::ZERO)
                .powf(0.5);
        Aabb::new(self.center - ext, self.center + ext)
    }
}
