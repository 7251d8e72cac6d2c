//! Flat rings: a disk with a round hole in its middle (POV-Ray's `disc` with a hole radius).

use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use crate::geometry::shapes::disk::Disk;
use crate::geometry::{aabb::Aabb, ray::Hit, ray::Ray};

/// A ring in object space: the points of a disk at least `inner` from its centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Ring {
    disk: Disk,
    inner: f64,
}

impl Ring {
    /// A ring; `None` for a zero normal, a non-positive radius or a hole that is negative or
    /// not smaller than the radius.
    pub(crate) fn new(center: DVec3, normal: DVec3, radius: f64, inner: f64) -> Option<Ring> {
        let disk = Disk::new(center, normal, radius)?;
        (inner >= 0.0 && inner < radius).then_some(Ring { disk, inner })
    }

    /// Nearest hit in (t_min, t_max); uv = (angle / 2π, (distance − inner) / (radius − inner)):
    /// v runs across the band from the hole's edge to the rim.
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let (t, x, y, r2) = self.disk.plane_hit(ray, t_min, t_max)?;
        let radius = self.disk.radius();
        if r2 > radius * radius || r2 < self.inner * self.inner {
            return None;
        }
        let angle = libm::atan2(y, x).rem_euclid(TAU);
        Some(Hit {
            t,
            normal: self.disk.normal(),
            uv: DVec2::new(
                angle / TAU,
                (r2.sqrt() - self.inner) / (radius - self.inner),
            ),
        })
    }

    /// Error bound of a computed point `p` on it: its residual off its plane (the disk's).
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        self.disk.point_error(p)
    }

    /// Object-space bounds: the whole disk's (the hole does not shrink the box).
    pub(crate) fn bounds(&self) -> Aabb {
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
