//! Algebraic surfaces (POV-Ray's `poly`, `cubic` and `quartic`): the zeros of a polynomial in
//! x, y, z of total degree 2 to 15, inside where it is negative. Usually unbounded: bound one
//! with CSG, as POV-Ray's scenes do.
//!
//! Along a ray `o + t·d` the polynomial is a univariate one in `t`, built exactly by expanding
//! each term's powers of `(o + t·d)` (grouped as `Σ_i X_i·Σ_j Y_j·Σ_k c_ijk·Z_k`, so the cost is
//! about `order⁴`), from the point of the line closest to the origin with a unit direction (so
//! its coefficients stay of the surface's size), and solved on the whole line by the isolating
//! root finder ([`crate::geometry::shapes::quartic`]) within Cauchy's bound.

use crate::num::Norm;

use glam::DVec3;

use crate::geometry::ray::equirectangular_uv;
use crate::geometry::shapes::quartic::{MAX_DEGREE, root_bound, roots_in};
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};

/// Coefficients per `t` polynomial.
const LEN: usize = MAX_DEGREE + 1;

/// A polynomial surface in object space.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Poly {
    order: usize,
    /// `(i, j, k, c)`: the non-zero terms `c·x^i·y^j·z^k`.
    terms: Vec<([usize; 3], f64)>,
}

/// `(a + b·t)^m` for m = 0..=order, lowest degree first.
fn binomials(a: f64, b: f64, order: usize) -> [[f64; LEN]; LEN] {
    let mut out = [[0.0; LEN]; LEN];
    out[0][0] = 1.0;
    for m in 1..=order {
        for i in 0..=m {
            let keep = if i < m { out[m - 1][i] * a } else { 0.0 };
            let grow = if i > 0 { out[m - 1][i - 1] * b } else { 0.0 };
            out[m][i] = keep + grow;
        }
    }
    out
}

/// `acc += k·p·q` for polynomials of at most `LEN` coefficients (products beyond are zero
/// because every term's total degree is at most the order).
fn mul_acc(acc: &mut [f64; LEN], p: &[f64; LEN], q: &[f64; LEN], dp: usize, dq: usize) {
    for i in 0..=dp {
        if p[i] == 0.0 {
            continue;
        }
        for j in 0..=dq.min(LEN - 1 - i) {
            acc[i + j] += p[i] * q[j];
        }
    }
}

impl Poly {
    /// The surface of `order` with `terms` `[i, j, k]` (exponents of x, y, z) and their
    /// `coefficients`; `None` unless the order is 2 to 15, the lists match and some non-constant
    /// coefficient is non-zero and all are finite.
    pub(crate) fn new(order: usize, terms: &[[u32; 3]], coefficients: &[f64]) -> Option<Poly> {
        if !(2..=MAX_DEGREE).contains(&order) || terms.len() != coefficients.len() {
            return None;
        }
        if !coefficients.iter().all(|c| c.is_finite()) {
            return None;
        }
        let terms: Vec<([usize; 3], f64)> = terms
            .iter()
            .zip(coefficients)
            .filter(|(_, c)| **c != 0.0)
            .map(|(e, c)| ([e[0] as usize, e[1] as usize, e[2] as usize], *c))
            .collect();
        terms
            .iter()
            .any(|(e, _)| e.iter().sum::<usize>() > 0)
            .then_some(Poly { order, terms })
    }

    /// The polynomial at `p` (negative inside) and the sum of its terms' magnitudes.
    fn value(&self, p: DVec3) -> (f64, f64) {
        let pw = self.powers(p);
        let mut v = 0.0;
        let mut size = 0.0;
        for &([i, j, k], c) in &self.terms {
            let t = c * pw[i].x * pw[j].y * pw[k].z;
            v += t;
            size += t.abs();
        }
        (v, size)
    }

    /// `p^m` per axis, m = 0..=order.
    fn powers(&self, p: DVec3) -> [DVec3; LEN] {
        let mut pw = [DVec3::ONE; LEN];
        for m in 1..=self.order {
            pw[m] = pw[m - 1] * p;
        }
        pw
    }

    /// The gradient at `p` (points outside).
    fn gradient(&self, p: DVec3) -> DVec3 {
        let pw = self.powers(p);
        let mut g = DVec3::ZERO;
        for &([i, j, k], c) in &self.terms {
            let (x, y, z) = (pw[i].x, pw[j].y, pw[k].z);
            if i > 0 {
                g.x += c * i as f64 * pw[i - 1].x * y * z;
            }
            if j > 0 {
                g.y += c * j as f64 * x * pw[j - 1].y * z;
            }
            if k > 0 {
                g.z += c * k as f64 * x * y * pw[k - 1].z;
            }
        }
        g
    }

    /// The polynomial along the line `o + s·d` (coefficients of `s`, lowest first).
    fn along(&self, o: DVec3, d: DVec3) -> [f64; LEN] {
        let n = self.order;
        let (bx, by, bz) = (
            binomials(o.x, d.x, n),
            binomials(o.y, d.y, n),
            binomials(o.z, d.z, n),
        );
        let mut out = [0.0; LEN];
        // Terms arrive sorted by i, then j (POV-Ray's order); group them so each power of x and
        // y multiplies once per group.
        let mut idx = 0;
        while idx < self.terms.len() {
            let i = self.terms[idx].0[0];
            let mut in_x = [0.0; LEN];
            while idx < self.terms.len() && self.terms[idx].0[0] == i {
                let j = self.terms[idx].0[1];
                let mut in_y = [0.0; LEN];
                let mut deg_z = 0;
                while idx < self.terms.len()
                    && self.terms[idx].0[0] == i
                    && self.terms[idx].0[1] == j
                {
                    let ([_, _, k], c) = self.terms[idx];
                    for (m, v) in bz[k][..=k].iter().enumerate() {
                        in_y[m] += c * v;
                    }
                    deg_z = deg_z.max(k);
                    idx += 1;
                }
                mul_acc(&mut in_x, &by[j], &in_y, j, deg_z);
            }
            mul_acc(&mut out, &bx[i], &in_x, i, n - i);
        }
        out
    }

    /// Every sign-changing root along the whole line, in increasing `t`; `rising` where the
    /// ray leaves the inside.
    fn roots(&self, ray: &Ray, mut f: impl FnMut(f64, bool)) {
        let len = ray.dir.norm();
        if len == 0.0 || !len.is_finite() {
            return;
        }
        let d = ray.dir / len;
        // The point of the line nearest the origin.
        let tc = -ray.origin.dot(d) / len;
        let o = ray.at(tc);
        let c = self.along(o, d);
        let Some(bound) = root_bound(&c[..=self.order]) else {
            return;
        };
        for r in roots_in(&c[..=self.order], -bound, bound).iter() {
            f(tc + r.t / len, r.rising);
        }
    }

    fn hit(&self, ray: &Ray, t: f64) -> Hit {
        let g = self.gradient(ray.at(t));
        let normal = g.try_unit().unwrap_or_else(|| -ray.dir.unit_or(DVec3::Y));
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

    /// Every crossing along the whole line: entering where the polynomial falls through zero.
    pub(crate) fn crossings(&self, ray: &Ray, out: &mut Vec<Crossing>) {
        self.roots(ray, |t, rising| {
            out.push(Crossing {
                hit: self.hit(ray, t),
                entering: !rising,
            });
        });
    }

    /// Whether the line of `ray` starts inside (at t → −∞): the sign there of the polynomial
    /// along it, from its highest non-zero coefficient.
    pub(crate) fn inside_at_start(&self, ray: &Ray) -> bool {
        let len = ray.dir.norm();
        if len == 0.0 || !len.is_finite() {
            return self.contains(ray.origin);
        }
        let d = ray.dir / len;
        let o = ray.at(-ray.origin.dot(d) / len);
        let c = self.along(o, d);
        match c[..=self.order].iter().rposition(|&k| k != 0.0) {
            Some(m) => {
                let at_minus_infinity = if m % 2 == 0 { c[m] } else { -c[m] };
                at_minus_infinity < 0.0
            }
            None => false,
        }
    }

    /// True when `p` is inside or on the surface.
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        self.value(p).0 <= 0.0
    }

    /// Object-space bounds: unbounded (clip an algebraic surface with CSG to bound it).
    pub(crate) fn bounds(&self) -> Aabb {
        Aabb::new(DVec3::NEG_INFINITY, DVec3::INFINITY)
    }

    /// Error bound of a computed point `p` on the surface: the residual `f(p)/|∇f(p)|` plus
    /// the rounding of evaluating the polynomial (its terms' magnitudes over the gradient).
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let (v, size) = self.value(p);
        let g = self.gradient(p).norm().max(f64::MIN_POSITIVE);
        let ops = 2 * self.order as u32 + 4;
        rounding::from_residual(v / g, ops, size / g)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ir::poly_terms;

    fn from(order: u32, f: impl Fn([u32; 3]) -> f64) -> Poly {
        let terms = poly_terms(order);
        let c: Vec<f64> = terms.iter().map(|&e| f(e)).collect();
        Poly::new(order as usize, &terms, &c).unwrap()
    }

    #[test]
    fn the_order_two_sphere_matches_the_sphere() {
        // x² + y² + z² − 1 in POV-Ray's order: x², xy, xz, x, y², yz, y, z², z, 1.
        let terms = poly_terms(2);
        assert_eq!(terms[0], [2, 0, 0]);
        assert_eq!(terms[4], [0, 2, 0]);
        assert_eq!(terms[7], [0, 0, 2]);
        assert_eq!(terms[9], [0, 0, 0]);
        let p = from(2, |e| match e {
            [2, 0, 0] | [0, 2, 0] | [0, 0, 2] => 1.0,
            [0, 0, 0] => -1.0,
            _ => 0.0,
        });
        let r = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        let h = p.intersect(&r, 0.0, f64::INFINITY).unwrap();
        assert!((h.t - 4.0).abs() < 1e-12 && (h.normal + DVec3::Z).norm() < 1e-12);
        assert!(p.contains(DVec3::ZERO) && !p.contains(DVec3::splat(0.7)));
        assert!(!p.inside_at_start(&r));
    }

    #[test]
    fn a_torus_as_a_quartic_meets_a_ray_where_the_torus_does() {
        // (x² + y² + z² + R² − r²)² − 4R²(x² + z²), R = 2, r = 0.5 (about the y axis).
        let (r2, s2) = (4.0, 0.25);
        let k = r2 - s2;
        let p = from(4, |[i, j, l]| match [i, j, l] {
            [4, 0, 0] | [0, 4, 0] | [0, 0, 4] => 1.0,
            [2, 2, 0] | [2, 0, 2] | [0, 2, 2] => 2.0,
            [2, 0, 0] | [0, 0, 2] => 2.0 * k - 4.0 * r2,
            [0, 2, 0] => 2.0 * k,
            [0, 0, 0] => k * k,
            _ => 0.0,
        });
        let r = Ray::new(DVec3::new(-10.0, 0.1, 0.0), DVec3::X);
        let mut out = Vec::new();
        p.crossings(&r, &mut out);
        let ts: Vec<f64> = out.iter().map(|c| c.hit.t).collect();
        let x = (0.25f64 - 0.01).sqrt();
        let want = [
            10.0 - 2.0 - x,
            10.0 - 2.0 + x,
            10.0 + 2.0 - x,
            10.0 + 2.0 + x,
        ];
        assert_eq!(ts.len(), 4, "{ts:?}");
        for (got, w) in ts.iter().zip(want) {
            assert!((got - w).abs() < 1e-10, "{got} vs {w}");
        }
        assert!(out[0].entering && !out[1].entering);
    }
}
