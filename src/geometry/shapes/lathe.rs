//! Lathes (POV-Ray's `lathe`): a 2-D profile of spline segments in the (r, y) half-plane,
//! revolved about the +Y axis.
//!
//! Each segment is a cubic (or lower) `(r(s), y(s))`, s ∈ [0, 1]. A ray `o + t·d` meets the
//! revolved segment where `|h(t)|² = r(s)²` and `y(t) = y(s)` (`h` the ray's x–z part).
//! Eliminating `t = (y(s) − o_y)/d_y` gives a polynomial of degree 6 in `s`, solved on [0, 1]
//! by the isolating root finder ([`crate::geometry::shapes::quartic`]); a horizontal ray
//! instead meets the circles at the heights where `y(s) = o_y`. The solid is POV-Ray's: a
//! point is inside when a ray from it away from the axis crosses the profile an odd number of
//! times, so a closed profile bounds a solid, and a profile point at r = 0 (a cusp on the axis)
//! needs no special case.

use crate::num::Norm;
use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use crate::geometry::shapes::quartic::{eval, roots_in};
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};
use crate::ir::Spline;

/// A ray whose direction's y part is below this (relative) is treated as horizontal.
const FLAT: f64 = 1e-9;

/// One spline segment: `r(s)` and `y(s)`, coefficients lowest degree first.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Segment {
    r: [f64; 4],
    y: [f64; 4],
    /// Lowest and highest `y` on the segment.
    y_range: (f64, f64),
    /// Least and greatest distance `|r|` of the segment from the axis.
    r_range: (f64, f64),
}

/// A lathe in object space.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Lathe {
    segments: Vec<Segment>,
    bounds: Aabb,
    /// +1 when the profile (closed by a chord from its last point to its first) runs
    /// counter-clockwise in the (r, y) plane, so `(y', −r')` points outside; −1 otherwise.
    orient: f64,
}

/// The derivative's coefficients.
fn derivative(c: &[f64; 4]) -> [f64; 3] {
    [c[1], 2.0 * c[2], 3.0 * c[3]]
}

/// Product of two polynomials (lowest degree first) into `out` (zeroed, long enough).
fn mul_add(a: &[f64], b: &[f64], k: f64, out: &mut [f64]) {
    for (i, &x) in a.iter().enumerate() {
        for (j, &y) in b.iter().enumerate() {
            out[i + j] += k * x * y;
        }
    }
}

/// The sign-changing roots of `c` (any degree up to 15) in `(lo, hi)`, linear ones included.
fn each_root(c: &[f64], lo: f64, hi: f64, mut f: impl FnMut(f64)) {
    let deg = c.iter().rposition(|&k| k != 0.0).unwrap_or(0);
    if deg == 1 {
        let s = -c[0] / c[1];
        if s > lo && s < hi {
            f(s);
        }
    } else {
        for r in roots_in(&c[..=deg], lo, hi).iter() {
            f(r.t);
        }
    }
}

/// Extremes of a cubic on [0, 1]: its ends and its critical points inside.
fn range01(c: &[f64; 4]) -> (f64, f64) {
    let mut lo = eval(c, 0.0).min(eval(c, 1.0));
    let mut hi = eval(c, 0.0).max(eval(c, 1.0));
    if let Some((a, b)) = crate::geometry::shapes::quartic::quadratic(3.0 * c[3], 2.0 * c[2], c[1])
    {
        for s in [a, b] {
            if (0.0..=1.0).contains(&s) {
                lo = lo.min(eval(c, s));
                hi = hi.max(eval(c, s));
            }
        }
    }
    (lo, hi)
}

/// The segments of a profile, as POV-Ray builds them (`Compute_Lathe`): `linear` joins
/// neighbours, `quadratic` and `cubic` skip the first (and for cubic the last) point as a
/// control point, `bezier` takes groups of four.
pub(crate) fn segment_count(spline: Spline, n: usize) -> usize {
    match spline {
        Spline::Linear => n.saturating_sub(1),
        Spline::Quadratic => n.saturating_sub(2),
        Spline::Cubic => n.saturating_sub(3),
        Spline::Bezier => n / 4,
    }
}

impl Lathe {
    /// A lathe of `points` `[r, y]` joined by `spline`; `None` without a segment, with a
    /// non-finite point, or when the profile has no extent.
    pub(crate) fn new(points: &[[f64; 2]], spline: Spline) -> Option<Lathe> {
        let p: Vec<DVec2> = points.iter().map(|q| DVec2::new(q[0], q[1])).collect();
        if !p.iter().all(|q| q.is_finite()) {
            return None;
        }
        let count = segment_count(spline, p.len());
        let mut segments = Vec::with_capacity(count);
        for k in 0..count {
            let (a, b, c, d) = match spline {
                Spline::Linear => (DVec2::ZERO, DVec2::ZERO, p[k + 1] - p[k], p[k]),
                Spline::Quadratic => (
                    DVec2::ZERO,
                    0.5 * p[k] - p[k + 1] + 0.5 * p[k + 2],
                    -0.5 * p[k] + 0.5 * p[k + 2],
                    p[k + 1],
                ),
                Spline::Cubic => (
                    -0.5 * p[k] + 1.5 * p[k + 1] - 1.5 * p[k + 2] + 0.5 * p[k + 3],
                    p[k] - 2.5 * p[k + 1] + 2.0 * p[k + 2] - 0.5 * p[k + 3],
                    -0.5 * p[k] + 0.5 * p[k + 2],
                    p[k + 1],
                ),
                Spline::Bezier => {
                    let q = &p[4 * k..4 * k + 4];
                    (
                        q[3] - 3.0 * q[2] + 3.0 * q[1] - q[0],
                        3.0 * q[2] - 6.0 * q[1] + 3.0 * q[0],
                        3.0 * q[1] - 3.0 * q[0],
                        q[0],
                    )
                }
            };
            let r = [d.x, c.x, b.x, a.x];
            let y = [d.y, c.y, b.y, a.y];
            // A segment on the axis (r ≡ 0) has no area: it adds no surface and no crossing.
            if r.iter().all(|&k| k == 0.0) {
                continue;
            }
            let (lo, hi) = range01(&r);
            let far = lo.abs().max(hi.abs());
            let near = if lo <= 0.0 && hi >= 0.0 {
                0.0
            } else {
                lo.abs().min(hi.abs())
            };
            segments.push(Segment {
                r,
                y,
                y_range: range01(&y),
                r_range: (near, far),
            });
        }
        let mut r_max: f64 = 0.0;
        let (mut y_lo, mut y_hi) = (f64::INFINITY, f64::NEG_INFINITY);
        // Twice the signed area: ∫ r·y' − y·r' over the segments, exact for polynomials.
        let mut area2 = 0.0;
        for s in &segments {
            let (lo, hi) = range01(&s.r);
            r_max = r_max.max(lo.abs()).max(hi.abs());
            y_lo = y_lo.min(s.y_range.0);
            y_hi = y_hi.max(s.y_range.1);
            let mut w = [0.0; 7];
            mul_add(&s.r, &derivative(&s.y), 1.0, &mut w);
            mul_add(&s.y, &derivative(&s.r), -1.0, &mut w);
            area2 += w
                .iter()
                .enumerate()
                .map(|(i, &k)| k / (i + 1) as f64)
                .sum::<f64>();
        }
        let (first, last) = (segments.first()?, segments.last()?);
        let start = DVec2::new(eval(&first.r, 0.0), eval(&first.y, 0.0));
        let end = DVec2::new(eval(&last.r, 1.0), eval(&last.y, 1.0));
        area2 += end.perp_dot(start);
        if !(r_max > 0.0 && y_hi > y_lo && area2 != 0.0 && r_max.is_finite() && y_hi.is_finite()) {
            return None;
        }
        Some(Lathe {
            segments,
            bounds: Aabb::new(
                DVec3::new(-r_max, y_lo, -r_max),
                DVec3::new(r_max, y_hi, r_max),
            ),
            orient: area2.signum(),
        })
    }

    /// Object-space bounds.
    pub(crate) fn bounds(&self) -> Aabb {
        self.bounds
    }

    fn size(&self) -> f64 {
        self.bounds
            .max
            .x
            .max(self.bounds.max.y.abs())
            .max(self.bounds.min.y.abs())
    }

    /// Every root along the whole line of `ray`: `f(t, segment, s)`, unordered.
    fn roots(&self, ray: &Ray, mut f: impl FnMut(f64, usize, f64)) {
        let len = ray.dir.norm();
        if len == 0.0 || !len.is_finite() {
            return;
        }
        let pad = 1e-6 * self.size();
        let b = Aabb::new(self.bounds.min - pad, self.bounds.max + pad);
        let Some((t0, t1)) = b.hit_interval(ray, f64::NEG_INFINITY, f64::INFINITY) else {
            return;
        };
        // From the box entry with a unit direction, the coefficients stay of the shape's size.
        let d = ray.dir / len;
        let o = ray.at(t0);
        let (ho, hd) = (DVec2::new(o.x, o.z), DVec2::new(d.x, d.z));
        let (hd2, hod, ho2) = (hd.length_squared(), ho.dot(hd), ho.length_squared());
        let span = (t1 - t0) * len + 2.0 * pad;
        let (ray_lo, ray_hi) = {
            let (a, b) = (o.y - pad * d.y.abs(), o.y + span * d.y);
            (a.min(b) - pad, a.max(b) + pad)
        };
        let last = self.segments.len() - 1;
        for (k, seg) in self.segments.iter().enumerate() {
            if seg.y_range.1 < ray_lo || seg.y_range.0 > ray_hi {
                continue;
            }
            // The segment lies in the shell between the cylinders of radius `r_range` over its
            // heights: a ray that stays outside the outer one or inside the inner one there
            // (POV-Ray's per-segment bounding cylinders) cannot meet it.
            if d.y.abs() > FLAT && self.misses_shell(seg, (o.y, d.y), (ho, hd), pad) {
                continue;
            }
            // Roots at s = 1 belong to the next segment's s = 0, except on the last.
            let keep = |s: f64| s >= 0.0 && (s < 1.0 || (k == last && s <= 1.0));
            let mut yy = seg.y;
            yy[0] -= o.y;
            // Two t on the circle of radius r(s) in the ray's horizontal plane.
            let circle =
                |r: f64| crate::geometry::shapes::quartic::quadratic(hd2, 2.0 * hod, ho2 - r * r);
            if d.y.abs() <= FLAT {
                each_root(&yy, -1e-9, 1.0 + 1e-9, |s| {
                    if !keep(s) {
                        return;
                    }
                    if let Some((ta, tb)) = circle(eval(&seg.r, s))
                        && ta < tb
                    {
                        f(t0 + ta / len, k, s);
                        f(t0 + tb / len, k, s);
                    }
                });
                continue;
            }
            // Q(s) = Y²·|h_d|² + 2·Y·d_y·(h_o·h_d) + d_y²·(|h_o|² − r²).
            let mut q = [0.0; 7];
            mul_add(&yy, &yy, hd2, &mut q);
            mul_add(&yy, &[1.0], 2.0 * d.y * hod, &mut q);
            mul_add(&seg.r, &seg.r, -d.y * d.y, &mut q);
            q[0] += d.y * d.y * ho2;
            each_root(&q, -1e-9, 1.0 + 1e-9, |s| {
                if !keep(s) {
                    return;
                }
                let ys = eval(&yy, s);
                // Solve for t the well-conditioned way: through y on steep rays, through the
                // circle on shallow ones (choosing the root at the right height).
                let t = if d.y.abs() >= hd2.sqrt() {
                    ys / d.y
                } else {
                    match circle(eval(&seg.r, s)) {
                        Some((ta, tb)) => {
                            if (ta * d.y - ys).abs() <= (tb * d.y - ys).abs() {
                                ta
                            } else {
                                tb
                            }
                        }
                        None => ys / d.y,
                    }
                };
                f(t0 + t / len, k, s);
            });
        }
    }

    /// True when the line `y = oy + τ·dy`, horizontal part `ho + τ·hd` (τ along a unit
    /// direction) is, at every height of `seg` (widened by `pad`), farther from the axis than
    /// its largest radius or nearer than its smallest.
    fn misses_shell(
        &self,
        seg: &Segment,
        (oy, dy): (f64, f64),
        (ho, hd): (DVec2, DVec2),
        pad: f64,
    ) -> bool {
        let (ya, yb) = (
            (seg.y_range.0 - pad - oy) / dy,
            (seg.y_range.1 + pad - oy) / dy,
        );
        let (ta, tb) = (ya.min(yb), ya.max(yb));
        let dist2 = |t: f64| (ho + t * hd).length_squared();
        let (at_a, at_b) = (dist2(ta), dist2(tb));
        // Nearest approach to the axis within [ta, tb] (a convex quadratic in τ).
        let hd2 = hd.length_squared();
        let nearest = if hd2 > 0.0 {
            let t = (-ho.dot(hd) / hd2).clamp(ta, tb);
            dist2(t).min(at_a).min(at_b)
        } else {
            at_a.min(at_b)
        };
        let farthest = at_a.max(at_b);
        // The margins cover the rounding of these few operations many times over.
        let (near, far) = (seg.r_range.0 - pad, seg.r_range.1 + pad);
        nearest > far * far * (1.0 + 1e-9) || (near > 0.0 && farthest < near * near * (1.0 - 1e-9))
    }

    fn hit(&self, ray: &Ray, t: f64, k: usize, s: f64) -> Hit {
        let seg = &self.segments[k];
        let p = ray.at(t);
        let rho = DVec2::new(p.x, p.z).norm();
        let r = eval(&seg.r, s);
        // The surface is at |r(s)|: its slope flips where the profile dips below the axis.
        let dr = eval(&derivative(&seg.r), s) * if r < 0.0 { -1.0 } else { 1.0 };
        let dy = eval(&derivative(&seg.y), s);
        let n = if rho > 0.0 {
            DVec3::new(dy * p.x / rho, -dr, dy * p.z / rho)
        } else {
            DVec3::new(0.0, -dr, 0.0)
        };
        let normal = (n * self.orient).try_unit().unwrap_or(DVec3::Y);
        let (lo, hi) = (self.bounds.min.y, self.bounds.max.y);
        let u = libm::atan2(-p.z, p.x).rem_euclid(TAU) / TAU;
        let v = ((p.y - lo) / (hi - lo)).clamp(0.0, 1.0);
        Hit {
            t,
            normal,
            uv: DVec2::new(u, v),
        }
    }

    /// Nearest hit in (t_min, t_max).
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let mut best: Option<(f64, usize, f64)> = None;
        self.roots(ray, |t, k, s| {
            if t > t_min && t < t_max && best.is_none_or(|b| t < b.0) {
                best = Some((t, k, s));
            }
        });
        best.map(|(t, k, s)| self.hit(ray, t, k, s))
    }

    /// Boundary crossings along the whole line, entering where the outward normal faces the
    /// ray.
    pub(crate) fn crossings(&self, ray: &Ray, out: &mut Vec<Crossing>) {
        let from = out.len();
        self.roots(ray, |t, k, s| {
            let hit = self.hit(ray, t, k, s);
            out.push(Crossing {
                entering: hit.normal.dot(ray.dir) < 0.0,
                hit,
            });
        });
        out[from..].sort_by(|a, b| a.hit.t.total_cmp(&b.hit.t));
    }

    /// True when `p` is inside or on the solid: an odd number of profile crossings on the
    /// horizontal half-line from `(|p_xz|, p_y)` away from the axis (POV-Ray's rule).
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        if !self.bounds.contains(p, 0.0) {
            return false;
        }
        let rho = DVec2::new(p.x, p.z).norm();
        let mut odd = false;
        let last = self.segments.len() - 1;
        for (k, seg) in self.segments.iter().enumerate() {
            if p.y < seg.y_range.0 || p.y > seg.y_range.1 {
                continue;
            }
            let mut yy = seg.y;
            yy[0] -= p.y;
            each_root(&yy, -1e-12, 1.0 + 1e-12, |s| {
                let keep = s >= 0.0 && (s < 1.0 || (k == last && s <= 1.0));
                if keep && eval(&seg.r, s).abs() >= rho {
                    odd = !odd;
                }
            });
        }
        odd
    }

    /// Error bound of a computed point `p` on the surface: its distance to the profile along
    /// the horizontal or the vertical through it (each at least the true distance), plus the
    /// rounding of the evaluation.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let rho = DVec2::new(p.x, p.z).norm();
        let mut dist = f64::INFINITY;
        for seg in &self.segments {
            let mut yy = seg.y;
            yy[0] -= p.y;
            for s in roots_on(&yy) {
                dist = dist.min((eval(&seg.r, s).abs() - rho).abs());
            }
            for sign in [1.0, -1.0] {
                let mut rr = seg.r;
                rr[0] -= sign * rho;
                for s in roots_on(&rr) {
                    dist = dist.min((eval(&seg.y, s) - p.y).abs());
                }
            }
        }
        let size = self.size() + p.abs().max_element();
        if !dist.is_finite() {
            // Off every segment's lines (a point at a profile's extreme): the box is a bound.
            dist = size;
        }
        // The roots in s are found to about 1e-12 of the segment, but a degree-6 polynomial's
        // conditioning turns that into up to ~1e-10 of the shape's size along the ray: a
        // spawned ray must start beyond it or it meets its own surface again (acne).
        rounding::from_residual(dist, 64, size) + DVec3::splat(1e-9 * size)
    }
}

/// The real roots of a cubic (or lower) in [0, 1] for error bounds: its sign changes, and its
/// critical points where it (nearly) vanishes (double roots, which do not change sign).
fn roots_on(c: &[f64; 4]) -> Vec<f64> {
    let mut out = Vec::new();
    each_root(c, -1e-9, 1.0 + 1e-9, |s| out.push(s.clamp(0.0, 1.0)));
    let scale = c.iter().map(|k| k.abs()).sum::<f64>();
    each_root(&derivative(c), -1e-9, 1.0 + 1e-9, |s| {
        let s = s.clamp(0.0, 1.0);
        if eval(c, s).abs() <= 1e-9 * scale {
            out.push(s);
        }
    });
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A closed cone profile with its tip on the axis: (0, 0) → (1, 0) → (0, 2) → (0, 0).
    fn cone() -> Lathe {
        Lathe::new(
            &[[0.0, 0.0], [1.0, 0.0], [0.0, 2.0], [0.0, 0.0]],
            Spline::Linear,
        )
        .unwrap()
    }

    #[test]
    fn a_linear_cone_is_hit_where_the_cone_is() {
        let l = cone();
        // Horizontal ray at y = 1: the cone's radius there is 0.5.
        let r = Ray::new(DVec3::new(-5.0, 1.0, 0.0), DVec3::X);
        let h = l.intersect(&r, 0.0, f64::INFINITY).unwrap();
        assert!((h.t - 4.5).abs() < 1e-12, "{}", h.t);
        let want = DVec3::new(-2.0, 1.0, 0.0).unit();
        assert!((h.normal - want).norm() < 1e-12, "{}", h.normal);
        // A slanted ray through the tip region.
        let r = Ray::new(DVec3::new(0.3, 5.0, 0.0), DVec3::new(0.0, -1.0, 0.0));
        let h = l.intersect(&r, 0.0, f64::INFINITY).unwrap();
        assert!((h.t - (5.0 - 1.4)).abs() < 1e-12, "{}", h.t);
        let mut out = Vec::new();
        l.crossings(&r, &mut out);
        assert_eq!(out.len(), 2);
        assert!(out[0].entering && !out[1].entering);
        assert!((out[1].hit.t - 5.0).abs() < 1e-12);
        assert!(l.contains(DVec3::new(0.2, 0.5, 0.1)));
        assert!(!l.contains(DVec3::new(0.7, 1.0, 0.0)));
        assert!(!l.contains(DVec3::new(0.0, 2.5, 0.0)));
    }

    #[test]
    fn a_clockwise_profile_still_faces_out() {
        let l = Lathe::new(
            &[[0.0, 0.0], [0.0, 2.0], [1.0, 0.0], [0.0, 0.0]],
            Spline::Linear,
        )
        .unwrap();
        let r = Ray::new(DVec3::new(0.0, 1.0, 5.0), -DVec3::Z);
        let h = l.intersect(&r, 0.0, f64::INFINITY).unwrap();
        assert!(h.normal.z > 0.0 && h.normal.y > 0.0, "{}", h.normal);
    }

    #[test]
    fn a_bezier_half_circle_is_close_to_a_sphere() {
        // The usual 4-point approximation of a quarter circle, twice: a sphere of radius 1.
        let k = 0.552_284_749_830_793_4;
        let l = Lathe::new(
            &[
                [0.0, -1.0],
                [k, -1.0],
                [1.0, -k],
                [1.0, 0.0],
                [1.0, 0.0],
                [1.0, k],
                [k, 1.0],
                [0.0, 1.0],
            ],
            Spline::Bezier,
        )
        .unwrap();
        for (o, d) in [
            (DVec3::new(0.1, 0.2, -4.0), DVec3::Z),
            (DVec3::new(3.0, 3.0, 0.5), DVec3::new(-1.0, -1.0, -0.1)),
            (DVec3::new(0.0, -4.0, 0.3), DVec3::Y),
        ] {
            let r = Ray::new(o, d);
            let h = l.intersect(&r, 0.0, f64::INFINITY).unwrap();
            // The Bézier circle is within 3e-4 of the unit sphere.
            assert!((r.at(h.t).norm() - 1.0).abs() < 3e-4, "{}", r.at(h.t));
            assert!(h.normal.dot(r.at(h.t).unit()) > 0.999);
        }
        assert!(l.contains(DVec3::ZERO) && !l.contains(DVec3::splat(0.7)));
    }
}
