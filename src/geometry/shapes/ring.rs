//! Flat rings: a disk with a round hole in its middle (POV-Ray's `disc` with a hole radius).

use crate::num::Norm;
use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use crate::geometry::shapes::disk::Disk;
use crate::geometry::{aabb::Aabb, ray::Hit, ray::Ray};

/// A ring in object space: the points of a disk of radius `radius` at least `inner` from its
/// centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ring {
    disk: Disk,
    center: DVec3,
    normal: DVec3,
    radius: f64,
    inner: f64,
    /// In-plane frame for texture coordinates (the disk's).
    e1: DVec3,
    e2: DVec3,
}

impl Ring {
    /// A ring; `None` for a zero normal, a non-positive radius or a hole that is negative or
    /// not smaller than the radius.
    pub fn new(center: DVec3, normal: DVec3, radius: f64, inner: f64) -> Option<Ring> {
        let disk = Disk::new(center, normal, radius)?;
        if !(inner >= 0.0 && inner < radius) {
            return None;
        }
        let normal = normal.try_unit()?;
        let e1 = normal.any_orthonormal_vector();
        Some(Ring {
            disk,
            center,
            normal,
            radius,
            inner,
            e1,
            e2: normal.cross(e1),
        })
    }

    /// Nearest hit in (t_min, t_max); uv = (angle / 2π, (distance − inner) / (radius − inner)):
    /// v runs across the band from the hole's edge to the rim.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
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
        let r2 = x * x + y * y;
        if r2 > self.radius * self.radius || r2 < self.inner * self.inner {
            return None;
        }
        let angle = libm::atan2(y, x).rem_euclid(TAU);
        Some(Hit {
            t,
            normal: self.normal,
            uv: DVec2::new(
                angle / TAU,
                (r2.sqrt() - self.inner) / (self.radius - self.inner),
            ),
        })
    }

    /// Error bound of a computed point `p` on it: its residual off its plane (the disk's).
    pub fn point_error(&self, p: DVec3) -> DVec3 {
        self.disk.point_error(p)
    }

    /// Object-space bounds: the whole disk's (the hole does not shrink the box).
    pub fn bounds(&self) -> Aabb {
        self.disk.bounds()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rays_through_the_hole_pass_and_rays_through_the_band_hit() {
        let ring = Ring::new(DVec3::ZERO, DVec3::Y, 2.0, 1.0).unwrap();
        let down = |x: f64| Ray::new(DVec3::new(x, 5.0, 0.0), -DVec3::Y);
        assert!(ring.intersect(&down(0.0), 0.0, f64::INFINITY).is_none());
        assert!(ring.intersect(&down(0.99), 0.0, f64::INFINITY).is_none());
        let hit = ring.intersect(&down(1.5), 0.0, f64::INFINITY).unwrap();
        assert_eq!(hit.t, 5.0);
        assert!((hit.uv.y - 0.5).abs() < 1e-12);
        assert!(ring.intersect(&down(2.01), 0.0, f64::INFINITY).is_none());
    }

    #[test]
    fn a_hole_as_wide_as_the_ring_or_negative_is_no_ring() {
        assert!(Ring::new(DVec3::ZERO, DVec3::Y, 1.0, 1.0).is_none());
        assert!(Ring::new(DVec3::ZERO, DVec3::Y, 1.0, -0.1).is_none());
        assert!(Ring::new(DVec3::ZERO, DVec3::ZERO, 1.0, 0.5).is_none());
        assert!(Ring::new(DVec3::ZERO, DVec3::Y, 1.0, 0.0).is_some());
    }
}
