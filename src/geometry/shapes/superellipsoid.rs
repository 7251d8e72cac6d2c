//! Superellipsoids (POV-Ray's `superellipsoid { <e, n> }`) in the cube [-1, 1]³:
//! `f(p) = (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) − 1 = 0`, inside where negative.
//! Exponents near 0 give sharp boxes, 1 a sphere, 2 a double cone, 3 a pinched star.
//!
//! `f` is smooth between the planes where a coordinate vanishes or `|x| = |y|`, so a ray's
//! chord through the cube is cut at its crossings of those planes (as POV-Ray does) and each
//! piece again into equal parts (where `f` may bend back, a pinched exponent above 2); every
//! sign change found is solved to full precision by a bracketed regula falsi
//! ([`crate::geometry::shapes::bracket`]). With both exponents at most 2, `f + 1` is convex
//! (a norm raised to a power ≥ 1, plus a convex power), so once it is above 1 and rising along
//! the ray no later crossing exists and the scan stops there. Powers and logarithms go through
//! `libm` and are taken in logarithms, so exponents of 0.001 neither overflow nor underflow.

use crate::num::Norm;

use glam::DVec3;

use crate::geometry::ray::equirectangular_uv;
use crate::geometry::shapes::bracket::brent;
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};

/// Equal parts each piece of the chord is cut into before looking for sign changes.
const PARTS: usize = 6;

/// A superellipsoid in object space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Superellipsoid {
    e: f64,
    n: f64,
}

/// `ln(e^a + e^b)` without overflow: the larger plus `ln(1 + e^−|a − b|)` (two `libm` calls).
fn log_add(a: f64, b: f64) -> f64 {
    let m = a.max(b);
    if m == f64::NEG_INFINITY {
        return m;
    }
    m + libm::log1p(libm::exp(-(a - b).abs()))
}

impl Superellipsoid {
    /// A superellipsoid with exponents `e` (east-west) and `n` (north-south); `None` unless
    /// both are positive and finite.
    pub(crate) fn new(e: f64, n: f64) -> Option<Superellipsoid> {
        let ok = e > 0.0 && n > 0.0 && e.is_finite() && n.is_finite();
        ok.then_some(Superellipsoid { e, n })
    }

    /// `ln` of the two terms `(|x|^(2/e) + |y|^(2/e))^(e/n)` and `|z|^(2/n)`, and
    /// `ln(|x|^(2/e) + |y|^(2/e))`, from `l = ln |p|` per coordinate (each taken once).
    fn log_terms(&self, l: DVec3) -> (f64, f64, f64) {
        let (ie, iz) = (2.0 / self.e, 2.0 / self.n);
        let ls = log_add(ie * l.x, ie * l.y);
        (ls * (self.e / self.n), iz * l.z, ls)
    }

    /// `ln |p|` per coordinate.
    fn logs(p: DVec3) -> DVec3 {
        DVec3::new(
            libm::log(p.x.abs()),
            libm::log(p.y.abs()),
            libm::log(p.z.abs()),
        )
    }

    /// The implicit function's sign as a number: `ln(sum of terms)`, negative inside. Its zero
    /// set is the surface, and near it it changes like `f` (no overflow at small exponents).
    fn value(&self, p: DVec3) -> f64 {
        let (a, b, _) = self.log_terms(Self::logs(p));
        log_add(a, b)
    }

    /// The gradient's direction (unit), facing out.
    fn normal(&self, p: DVec3) -> DVec3 {
        let l = Self::logs(p);
        let (_, _, ls) = self.log_terms(l);
        let (ie, iz) = (2.0 / self.e, 2.0 / self.n);
        // ∂f/∂x = (2/n)·S^(e/n − 1)·|x|^(2/e − 1)·sign(x), likewise y; ∂f/∂z = (2/n)·|z|^(2/n − 1)
        // sign(z): their logarithms, shifted by the largest before exponentiating.
        let shared = (self.e / self.n - 1.0) * ls;
        let lx = shared + (ie - 1.0) * l.x;
        let ly = shared + (ie - 1.0) * l.y;
        let lz = (iz - 1.0) * l.z;
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

    /// Every sign change of `f` along the line of `ray` past `t_from`, in increasing `t`;
    /// `rising` when the ray leaves the solid. `f` returns false to stop (a nearest hit found):
    /// later roots are then not solved for, nor are those of brackets ending before `t_from`.
    fn roots(&self, ray: &Ray, t_from: f64, mut f: impl FnMut(f64, bool) -> bool) {
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
        let convex = self.e <= 2.0 && self.n <= 2.0;
        let mut lo = 0.0;
        let mut f_lo = at(lo);
        for &hi_piece in cuts.iter().chain(std::iter::once(&span)) {
            let piece_lo = lo;
            for k in 1..=PARTS {
                let hi = piece_lo + (hi_piece - piece_lo) * (k as f64 / PARTS as f64);
                let f_hi = at(hi);
                if (f_lo < 0.0) != (f_hi < 0.0) && t0 + hi > t_from {
                    let (t, _, _) = brent(at, lo, hi, f_lo, f_hi);
                    if !f(t0 + t, f_hi >= 0.0) {
                        return;
                    }
                }
                // Convex and outside and rising (by more than rounding): no crossing after.
                if convex && f_hi > 0.0 && f_hi - f_lo > 1e-9 * (1.0 + f_hi.abs() + f_lo.abs()) {
                    return;
                }
                lo = hi;
                f_lo = f_hi;
            }
        }
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
        // The roots come in increasing order: the first past t_min is the nearest.
        let mut best = None;
        self.roots(ray, t_min, |t, _| {
            if t > t_min && t < t_max {
                best = Some(t);
            }
            t <= t_min
        });
        best.map(|t| self.hit(ray, t))
    }

    /// Boundary crossings along the whole line.
    pub(crate) fn crossings(&self, ray: &Ray, out: &mut Vec<Crossing>) {
        self.roots(ray, f64::NEG_INFINITY, |t, rising| {
            out.push(Crossing {
                hit: self.hit(ray, t),
                entering: !rising,
            });
            true
        });
    }

    /// True when `p` is inside or on the solid.
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        self.value(p) <= 0.0
    }

    /// Error bound of a computed point `p` on the surface: a distance `δ` such that `f`
    /// changes sign between `p ∓ δ·n` along the normal `n`, so the surface provably lies within
    /// it (a sign test, not a gradient estimate, so a sharp box's flat value cannot fool it),
    /// plus rounding. `δ` starts at a few units in the last place of `p` and grows sixteenfold
    /// until the sign changes (two evaluations for a hit solved to full precision), up to a
    /// reach of 1e-4 beyond which the bound is that reach.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let nrm = self.normal(p);
        let size = p.abs().max_element().max(1.0);
        let reach = 1e-4 * size;
        let mut delta = f64::EPSILON * 0.25 * size;
        let dist = loop {
            if delta >= reach {
                break reach;
            }
            let (fa, fb) = (self.value(p - delta * nrm), self.value(p + delta * nrm));
            if (fa < 0.0) != (fb < 0.0) {
                break delta;
            }
            delta *= 16.0;
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
