//! Superellipsoids (POV-Ray's `superellipsoid { <e, n> }`) in the cube [-1, 1]³:
//! `f(p) = (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) − 1 = 0`, inside where negative.
//! Exponents near 0 give sharp boxes, 1 a sphere, 2 a double cone, 3 a pinched star.
//!
//! `f` is smooth between the planes where a coordinate vanishes or `|x| = |y|`, so a ray's
//! chord through the cube is cut at its crossings of those planes (as POV-Ray does) and each
//! piece again into equal parts (where `f` may bend back, a pinched exponent above 2); every
//! sign change found is bisected to full precision. Powers and logarithms go through `libm`
//! and are taken in logarithms, so exponents of 0.05 neither overflow nor underflow.

use crate::num::Norm;

use glam::DVec3;

use crate::geometry::ray::equirectangular_uv;
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};

/// Equal parts each piece of the chord is cut into before looking for sign changes.
const PARTS: usize = 6;

/// A superellipsoid in object space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Superellipsoid {
    e: f64,
    n: f64,
}

/// `ln(e^a + e^b)` without overflow.
fn log_add(a: f64, b: f64) -> f64 {
    let m = a.max(b);
    if m == f64::NEG_INFINITY {
        return m;
    }
    m + libm::log(libm::exp(a - m) + libm::exp(b - m))
}

impl Superellipsoid {
    /// A superellipsoid with exponents `e` (east-west) and `n` (north-south); `None` unless
    /// both are positive and finite.
    pub(crate) fn new(e: f64, n: f64) -> Option<Superellipsoid> {
        let ok = e > 0.0 && n > 0.0 && e.is_finite() && n.is_finite();
        ok.then_some(Superellipsoid { e, n })
    }

    /// `ln` of the two terms `(|x|^(2/e) + |y|^(2/e))^(e/n)` and `|z|^(2/n)`, and
    /// `ln(|x|^(2/e) + |y|^(2/e))`.
    fn log_terms(&self, p: DVec3) -> (f64, f64, f64) {
        let (ie, iz) = (2.0 / self.e, 2.0 / self.n);
        let ls = log_add(ie * libm::log(p.x.abs()), ie * libm::log(p.y.abs()));
        (ls * (self.e / self.n), iz * libm::log(p.z.abs()), ls)
    }

    /// The implicit function's sign as a number: `ln(sum of terms)`, negative inside. Its zero
    /// set is the surface, and near it it changes like `f` (no overflow at small exponents).
    fn value(&self, p: DVec3) -> f64 {
        let (a, b, _) = self.log_terms(p);
        log_add(a, b)
    }

    /// The gradient's direction (unit), facing out.
    fn normal(&self, p: DVec3) -> DVec3 {
        let (_, _, ls) = self.log_terms(p);
        let (ie, iz) = (2.0 / self.e, 2.0 / self.n);
        // ∂f/∂x = (2/n)·S^(e/n − 1)·|x|^(2/e − 1)·sign(x), likewise y; ∂f/∂z = (2/n)·|z|^(2/n − 1)
        // sign(z): their logarithms, shifted by the largest before exponentiating.
        let shared = (self.e / self.n - 1.0) * ls;
        let lx = shared + (ie - 1.0) * libm::log(p.x.abs());
        let ly = shared + (ie - 1.0) * libm::log(p.y.abs());
        let lz = (iz - 1.0) * libm::log(p.z.abs());
        let m = lx.max(ly).max(lz);
        let comp = |l: f64, c: f64| {
            if c == 0.0 || !m.is_finite() {
                0.0
            } else {
                libm::exp(l - m).copysign(c)
            }
        };
        let g = DVec3::new(comp(lx, p.x), comp(ly, p.y), comp(lz, p.z));
        g.try_unit().unwrap_or_else(|| {
            // On an axis or an edge where a term's slope is undefined: the dominant axis.
            let a = p.abs();
            if a.z >= a.x.max(a.y) {
                DVec3::Z * p.z.signum()
            } else if a.x >= a.y {
                DVec3::X * p.x.signum()
            } else {
                DVec3::Y * p.y.signum()
            }
        })
    }

    /// Object-space bounds: the cube [-1, 1]³.
    pub(crate) fn bounds(&self) -> Aabb {
        Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0))
    }

    /// Every sign change of `f` along the line of `ray`, in increasing `t`; `rising` when the
    /// ray leaves the solid.
    fn roots(&self, ray: &Ray, mut f: impl FnMut(f64, bool)) {
        let len = ray.dir.norm();
        if len == 0.0 || !len.is_finite() {
            return;
        }
        let b = Aabb::new(DVec3::splat(-1.0 - 1e-9), DVec3::splat(1.0 + 1e-9));
        let Some((t0, t1)) = b.hit_interval(ray, f64::NEG_INFINITY, f64::INFINITY) else {
            return;
        };
        // Work from the cube's entry, so the points stay small however far the origin is.
        let o = ray.at(t0);
        let d = ray.dir;
        let span = t1 - t0;
        let mut cuts = [0.0; 8];
        let mut n = 0;
        let mut cut = |t: f64| {
            if t > 0.0 && t < span && t.is_finite() {
                cuts[n] = t;
                n += 1;
            }
        };
        cut(-o.x / d.x);
        cut(-o.y / d.y);
        cut(-o.z / d.z);
        cut(-(o.x - o.y) / (d.x - d.y));
        cut(-(o.x + o.y) / (d.x + d.y));
        let cuts = &mut cuts[..n];
        cuts.sort_by(f64::total_cmp);
        let at = |t: f64| self.value(o + t * d);
        let mut lo = 0.0;
        let mut f_lo = at(lo);
        for &hi_piece in cuts.iter().chain(std::iter::once(&span)) {
            let piece_lo = lo;
            for k in 1..=PARTS {
                let hi = piece_lo + (hi_piece - piece_lo) * (k as f64 / PARTS as f64);
                let f_hi = at(hi);
                if (f_lo < 0.0) != (f_hi < 0.0) {
                    let t = self.bisect(o, d, lo, hi, f_lo < 0.0);
                    f(t0 + t, f_hi >= 0.0);
                }
                lo = hi;
                f_lo = f_hi;
            }
        }
    }

    /// The sign change of `f(o + t·d)` in `[lo, hi]`, to full precision.
    fn bisect(&self, o: DVec3, d: DVec3, mut lo: f64, mut hi: f64, lo_inside: bool) -> f64 {
        for _ in 0..80 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if (self.value(o + mid * d) < 0.0) == lo_inside {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    fn hit(&self, ray: &Ray, t: f64) -> Hit {
        let normal = self.normal(ray.at(t));
        Hit {
            t,
            normal,
            uv: equirectangular_uv(normal),
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
        self.value(p) <= 0.0
    }

    /// Error bound of a computed point `p` on the surface: where the ray through `p` along
    /// its normal crosses the surface, found by bisection (so a sharp box's flat value does
    /// not blow up a gradient-based estimate), plus rounding.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let nrm = self.normal(p);
        let size = p.abs().max_element().max(1.0);
        // The surface lies within 1e-6 of a computed hit; look a little further either way.
        let reach = 1e-4 * size;
        let (a, b) = (p - reach * nrm, p + reach * nrm);
        let (fa, fb) = (self.value(a), self.value(b));
        let dist = if (fa < 0.0) != (fb < 0.0) {
            let t = self.bisect(a, nrm, 0.0, 2.0 * reach, fa < 0.0);
            (t - reach).abs()
        } else {
            reach
        };
        rounding::from_residual(dist, 64, size)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exponent_one_is_the_unit_sphere() {
        let s = Superellipsoid::new(1.0, 1.0).unwrap();
        let r = Ray::new(DVec3::new(0.3, -0.2, 5.0), -DVec3::Z);
        let h = s.intersect(&r, 0.0, f64::INFINITY).unwrap();
        let p = r.at(h.t);
        assert!((p.norm() - 1.0).abs() < 1e-12, "{p}");
        assert!((h.normal - p.unit()).norm() < 1e-9, "{}", h.normal);
        let mut out = Vec::new();
        s.crossings(&r, &mut out);
        assert_eq!(out.len(), 2);
        assert!(out[0].entering && !out[1].entering);
    }

    #[test]
    fn a_sharp_box_and_a_pinched_star() {
        // e = n = 0.05: nearly the cube; a ray through a face hits close to it.
        let b = Superellipsoid::new(0.05, 0.05).unwrap();
        let r = Ray::new(DVec3::new(0.5, 0.3, 4.0), -DVec3::Z);
        let h = b.intersect(&r, 0.0, f64::INFINITY).unwrap();
        assert!((r.at(h.t).z - 1.0).abs() < 0.05, "{}", r.at(h.t));
        assert!(h.normal.z > 0.999, "{}", h.normal);
        // e = n = 3: concave faces; the point (0.5, 0.5, 0.5) is outside, the axes reach 1.
        let s = Superellipsoid::new(3.0, 3.0).unwrap();
        assert!(!s.contains(DVec3::splat(0.5)) && s.contains(DVec3::new(0.0, 0.0, 0.99)));
        let r = Ray::new(DVec3::new(0.0, 0.0, 4.0), -DVec3::Z);
        let h = s.intersect(&r, 0.0, f64::INFINITY).unwrap();
        assert!((h.t - 3.0).abs() < 1e-12, "{}", h.t);
    }
}
