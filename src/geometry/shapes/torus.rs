//! Tori about the +Y axis: a quartic in the ray parameter, solved in f64 by root isolation
//! ([`crate::geometry::shapes::quartic`]) so grazing rays neither miss nor speckle.

use crate::num::Norm;
use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use crate::geometry::shapes::quartic::{eval, roots_in};
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};

/// A torus in object space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Torus {
    center: DVec3,
    major: f64,
    minor: f64,
}

impl Torus {
    /// A torus; `None` unless both radii are positive and finite.
    pub(crate) fn new(center: DVec3, major: f64, minor: f64) -> Option<Torus> {
        let ok = major > 0.0 && minor > 0.0 && major.is_finite() && minor.is_finite();
        ok.then_some(Torus {
            center,
            major,
            minor,
        })
    }

    /// Signed distance to the surface (exact for a torus), negative inside.
    fn distance(&self, p: DVec3) -> f64 {
        let p = p - self.center;
        let ring = DVec2::new(p.x, p.z).norm() - self.major;
        DVec2::new(ring, p.y).norm() - self.minor
    }

    /// Error bound of a computed point `p` on the torus: its exact signed distance as evaluated,
    /// plus the rounding of that evaluation.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let size = (p - self.center).abs().element_sum() + self.major + self.minor;
        rounding::from_residual(self.distance(p), 10, size)
    }

    /// Object-space bounds.
    pub(crate) fn bounds(&self) -> Aabb {
        let e = DVec3::new(self.major + self.minor, self.minor, self.major + self.minor);
        Aabb::new(self.center - e, self.center + e)
    }

    /// Every sign-changing root along the whole line, in increasing `t`; `rising` means the
    /// ray leaves the solid there.
    fn roots(&self, ray: &Ray, mut f: impl FnMut(f64, bool)) {
        let len = ray.dir.norm();
        if len == 0.0 || !len.is_finite() {
            return;
        }
        // Work from the entry into a slightly enlarged bounding box, with a unit direction,
        // so the polynomial's coefficients stay small whatever the ray's origin.
        let pad = 1e-6 * (self.major + self.minor);
        let b = self.bounds();
        let b = Aabb::new(b.min - pad, b.max + pad);
        let Some((t0, t1)) = b.hit_interval(ray, f64::NEG_INFINITY, f64::INFINITY) else {
            return;
        };
        let d = ray.dir / len;
        let o = ray.at(t0) - self.center;
        let (r2, s2) = (self.major * self.major, self.minor * self.minor);
        let bb = 2.0 * o.dot(d);
        let k = o.length_squared() + r2 - s2;
        let c = [
            k * k - 4.0 * r2 * (o.x * o.x + o.z * o.z),
            2.0 * bb * k - 8.0 * r2 * (o.x * d.x + o.z * d.z),
            bb * bb + 2.0 * k - 4.0 * r2 * (d.x * d.x + d.z * d.z),
            2.0 * bb,
            1.0,
        ];
        let span = (t1 - t0) * len;
        // The box entry can sit exactly on a root of a grazing ray; start just before it.
        for r in roots_in(&c, -pad, span + pad).iter() {
            debug_assert!(eval(&c, r.t).is_finite());
            f(t0 + r.t / len, r.rising);
        }
    }

    fn hit(&self, ray: &Ray, t: f64) -> Hit {
        let p = ray.at(t) - self.center;
        let ring = DVec2::new(p.x, p.z);
        let rl = ring.norm();
        // Normal: from the nearest point of the tube's centre circle (exact, no cancellation).
        let normal = if rl > 0.0 {
            let c = DVec3::new(p.x, 0.0, p.z) * (self.major / rl);
            (p - c).try_unit().unwrap_or(DVec3::Y)
        } else {
            DVec3::Y * p.y.signum()
        };
        let u = libm::atan2(-p.z, p.x).rem_euclid(TAU) / TAU;
        let v = libm::atan2(p.y, rl - self.major).rem_euclid(TAU) / TAU;
        Hit {
            t,
            normal,
            uv: DVec2::new(u, v),
        }
    }

    /// Nearest hit in (t_min, t_max).
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        crate::geometry::shapes::quartic::nearest_root(t_min, t_max, |visit| self.roots(ray, visit))
            .map(|t| self.hit(ray, t))
    }

    /// Boundary crossings along the whole line.
    pub(crate) fn crossings(&self, ray: &Ray, out: &mut Vec<Crossing>) {
        self.roots(ray, |t, rising| {
            out.push(Crossing {
                hit: self.hit(ray, t),
                entering: !rising,
            });
        });
    }

    /// True when `p` is inside or on the solid.
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        self.distance(p) <= 0.0
    }
}
