//! Tori about the +Y axis: a quartic in the ray parameter, solved in f64 by root isolation
//! ([`crate::geometry::shapes::quartic`]) so grazing rays neither miss nor speckle.
//!
//! With the tube's radius r larger than the ring's R the tube overlaps itself: a *spindle*
//! torus (POV-Ray's). In the plane through the axis a point is at d₁ from the near point of
//! the centre circle and d₂ from the far one, and the quartic is `(d₁² − r²)(d₂² − r²)`: its
//! zeros are the apple (d₁ = r) and the lemon-shaped spindle inside it (d₂ = r; within
//! √(r² − R²) of the centre). [`Spindle`] says which are seen and which are inside.

use crate::num::Norm;
use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use crate::geometry::shapes::quartic::{eval, roots_in};
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};
use crate::ir::Spindle;

/// A torus in object space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Torus {
    center: DVec3,
    major: f64,
    minor: f64,
    /// The parts of a spindle torus; `None` for a ring torus (r < R), which has no spindle.
    spindle: Option<Spindle>,
}

impl Torus {
    /// A torus; `None` unless both radii are positive and finite.
    pub(crate) fn new(center: DVec3, major: f64, minor: f64, mode: Spindle) -> Option<Torus> {
        let ok = major > 0.0 && minor > 0.0 && major.is_finite() && minor.is_finite();
        ok.then_some(Torus {
            center,
            major,
            minor,
            spindle: (minor > major).then_some(mode),
        })
    }

    /// Whether the surface point `p` (torus space, centred) is on the spindle: within the
    /// sphere through its tips (POV-Ray's test).
    fn on_spindle(&self, p: DVec3) -> bool {
        self.spindle.is_some()
            && p.length_squared() < self.minor * self.minor - self.major * self.major
    }

    /// Distance from `p` (centred) to the far point of the centre circle in its plane through
    /// the axis, less r: negative inside the spindle.
    fn spindle_distance(&self, p: DVec3) -> f64 {
        let ring = DVec2::new(p.x, p.z).norm() + self.major;
        DVec2::new(ring, p.y).norm() - self.minor
    }

    /// Whether a root at `p` (centred) is seen, and whether the solid's boundary crossing
    /// there enters it when the quartic falls through zero (`None`: not a boundary of the
    /// solid, as the spindle's surface inside a union's apple).
    fn classify(&self, p: DVec3) -> (bool, Option<bool>) {
        let Some(mode) = self.spindle else {
            return (true, Some(true));
        };
        let lemon = self.on_spindle(p);
        // Falling through zero enters the apple-minus-lemon region: the apple at its surface,
        // and leaves the lemon at its surface.
        match (mode, lemon) {
            (Spindle::Difference, _) | (Spindle::Union | Spindle::Merge, false) => {
                (true, Some(true))
            }
            (Spindle::Union, true) => (true, None),
            (Spindle::Merge, true) | (Spindle::Intersection, false) => (false, None),
            (Spindle::Intersection, true) => (true, Some(false)),
        }
    }

    /// Signed distance to the tube (exact for a torus), negative inside.
    fn distance(&self, p: DVec3) -> f64 {
        let p = p - self.center;
        let ring = DVec2::new(p.x, p.z).norm() - self.major;
        DVec2::new(ring, p.y).norm() - self.minor
    }

    /// Error bound of a computed point `p` on the torus: its exact signed distance as evaluated,
    /// plus the rounding of that evaluation (to the spindle's surface where it is on it).
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let size = (p - self.center).abs().element_sum() + self.major + self.minor;
        let residual = if self.on_spindle(p - self.center) {
            self.spindle_distance(p - self.center)
        } else {
            self.distance(p)
        };
        rounding::from_residual(residual, 10, size)
    }

    /// Object-space bounds (of the spindle alone in `Spindle::Intersection`).
    pub(crate) fn bounds(&self) -> Aabb {
        if self.spindle == Some(Spindle::Intersection) {
            let tip = (self.minor * self.minor - self.major * self.major).sqrt();
            let e = DVec3::new(self.minor - self.major, tip, self.minor - self.major);
            return Aabb::new(self.center - e, self.center + e);
        }
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
            if self.on_spindle(p) {
                // Away from the far point of the centre circle: out of the lemon, which is
                // outside the solid in a difference.
                let out = (p + c).try_unit().unwrap_or(DVec3::Y);
                if self.spindle == Some(Spindle::Difference) {
                    -out
                } else {
                    out
                }
            } else {
                (p - c).try_unit().unwrap_or(DVec3::Y)
            }
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
        if self.spindle.is_none() {
            return crate::geometry::shapes::quartic::nearest_root(t_min, t_max, |visit| {
                self.roots(ray, visit)
            })
            .map(|t| self.hit(ray, t));
        }
        let mut best: Option<f64> = None;
        self.roots(ray, |t, _| {
            if t > t_min
                && t < t_max
                && best.is_none_or(|b| t < b)
                && self.classify(ray.at(t) - self.center).0
            {
                best = Some(t);
            }
        });
        best.map(|t| self.hit(ray, t))
    }

    /// Boundary crossings of the solid along the whole line.
    pub(crate) fn crossings(&self, ray: &Ray, out: &mut Vec<Crossing>) {
        self.roots(ray, |t, rising| {
            let Some(falling_enters) = self.classify(ray.at(t) - self.center).1 else {
                return;
            };
            out.push(Crossing {
                hit: self.hit(ray, t),
                entering: falling_enters != rising,
            });
        });
    }

    /// True when `p` is inside or on the solid.
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        let in_lemon = || self.spindle_distance(p - self.center) <= 0.0;
        match self.spindle {
            None | Some(Spindle::Union) | Some(Spindle::Merge) => self.distance(p) <= 0.0,
            Some(Spindle::Intersection) => in_lemon(),
            Some(Spindle::Difference) => self.distance(p) <= 0.0 && !in_lemon(),
        }
    }
}
