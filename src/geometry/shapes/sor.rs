//! Surfaces of revolution (POV-Ray's `sor`): about the +Y axis, the squared radius a cubic of
//! the height on each segment.
//!
//! Segment `k` runs from point `k + 1` to point `k + 2` (the first and last points only steer):
//! its radius² is the Hermite cubic through those points' radii² with the slopes POV-Ray gives
//! them (`Compute_Sor`: `2·r_{k+1}·(r_{k+2} − r_k)/(y_{k+2} − y_k)` and its counterpart), written
//! here in the segment's own variable `u = (y − y_{k+1})/(y_{k+2} − y_{k+1}) ∈ [0, 1]` so the
//! coefficients stay of the shape's size. A ray `o + t·d` meets it where
//! `|h(t)|² = R(u(t))` (`h` the ray's x–z part), a cubic in t solved by the isolating root
//! finder ([`crate::geometry::shapes::quartic`]). The solid is POV-Ray's: the points between
//! the lowest and highest heights whose distance from the axis is at most `sqrt(R)`, closed by a
//! base and a cap disk unless `open`.

use std::f64::consts::TAU;

use glam::{DVec2, DVec3};

use crate::geometry::shapes::quartic::{eval, quadratic, roots_in};
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};
use crate::num::Norm;

/// One segment: radius² in `u`, coefficients lowest degree first, over `[y0, y0 + h]`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Segment {
    r2: [f64; 4],
    y0: f64,
    h: f64,
}

impl Segment {
    /// The local variable of height `y`.
    fn u(&self, y: f64) -> f64 {
        (y - self.y0) / self.h
    }

    /// d(radius²)/dy at `u`.
    fn slope(&self, u: f64) -> f64 {
        let c = &self.r2;
        (c[1] + u * (2.0 * c[2] + u * 3.0 * c[3])) / self.h
    }
}

/// Which part of the surface a hit is on.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Part {
    Curve(usize),
    Base,
    Cap,
}

/// A surface of revolution in object space.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Sor {
    segments: Vec<Segment>,
    /// Radii of the base (lowest) and cap (highest) disks; 0 when open or on the axis.
    base: f64,
    cap: f64,
    open: bool,
    bounds: Aabb,
}

/// The segment's Hermite cubic in `u` from the radii² `a`, `b` at its ends and the slopes
/// `m0`, `m1` of radius² per unit height there (`h` the segment's height).
fn hermite(a: f64, b: f64, m0: f64, m1: f64, h: f64) -> [f64; 4] {
    let (s0, s1) = (h * m0, h * m1);
    [
        a,
        s0,
        -3.0 * a - 2.0 * s0 + 3.0 * b - s1,
        2.0 * a + s0 - 2.0 * b + s1,
    ]
}

/// The largest value of a cubic on [0, 1]: its ends and its critical points inside.
fn max01(c: &[f64; 4]) -> f64 {
    let mut hi = eval(c, 0.0).max(eval(c, 1.0));
    if let Some((a, b)) = quadratic(3.0 * c[3], 2.0 * c[2], c[1]) {
        for s in [a, b] {
            if (0.0..=1.0).contains(&s) {
                hi = hi.max(eval(c, s));
            }
        }
    }
    hi
}

/// `c(u0 + du·t)` as a polynomial in t (lowest degree first).
fn compose(c: &[f64; 4], u0: f64, du: f64) -> [f64; 4] {
    // Horner on polynomials: p ← p·(u0 + du·t) + c_i.
    let mut p = [0.0; 4];
    for &k in c.iter().rev() {
        let mut q = [k, 0.0, 0.0, 0.0];
        for (i, &pi) in p.iter().enumerate() {
            q[i] += pi * u0;
            // p has degree at most 2 before the last step: its t³ term is never dropped.
            if let Some(next) = q.get_mut(i + 1) {
                *next += pi * du;
            }
        }
        p = q;
    }
    p
}

impl Sor {
    /// A surface of revolution through `points` `[r, y]`; `None` with fewer than four points,
    /// a non-finite or negative-radius point, heights that do not increase from the second
    /// point to the last but one, equal heights two apart at either end (POV-Ray's rules), or
    /// no extent.
    pub(crate) fn new(points: &[[f64; 2]], open: bool) -> Option<Sor> {
        let n = points.len();
        if n < 4
            || !points
                .iter()
                .all(|p| p[0].is_finite() && p[1].is_finite() && p[0] >= 0.0)
        {
            return None;
        }
        let p: Vec<DVec2> = points.iter().map(|q| DVec2::new(q[0], q[1])).collect();
        if p[1..n - 1].windows(2).any(|w| w[1].y <= w[0].y)
            || p[2].y == p[0].y
            || p[n - 1].y == p[n - 3].y
        {
            return None;
        }
        let mut segments = Vec::with_capacity(n - 3);
        let mut r2_max: f64 = 0.0;
        for k in 0..n - 3 {
            let (p0, p1, p2, p3) = (p[k], p[k + 1], p[k + 2], p[k + 3]);
            let m0 = 2.0 * p1.x * (p2.x - p0.x) / (p2.y - p0.y);
            let m1 = 2.0 * p2.x * (p3.x - p1.x) / (p3.y - p1.y);
            let h = p2.y - p1.y;
            let r2 = hermite(p1.x * p1.x, p2.x * p2.x, m0, m1, h);
            r2_max = r2_max.max(max01(&r2));
            segments.push(Segment { r2, y0: p1.y, h });
        }
        let r_max = r2_max.sqrt();
        let (lo, hi) = (p[1].y, p[n - 2].y);
        if !(r_max > 0.0
            && r_max.is_finite()
            && segments.iter().all(|s| s.r2.iter().all(|c| c.is_finite())))
        {
            return None;
        }
        let disk = |r: f64| if open { 0.0 } else { r };
        Some(Sor {
            segments,
            base: disk(p[1].x),
            cap: disk(p[n - 2].x),
            open,
            bounds: Aabb::new(DVec3::new(-r_max, lo, -r_max), DVec3::new(r_max, hi, r_max)),
        })
    }

    /// Object-space bounds.
    pub(crate) fn bounds(&self) -> Aabb {
        self.bounds
    }

    /// Whether the base and cap are closed (a solid).
    pub(crate) fn is_closed(&self) -> bool {
        !self.open
    }

    fn size(&self) -> f64 {
        self.bounds
            .max
            .x
            .max(self.bounds.max.y.abs())
            .max(self.bounds.min.y.abs())
    }

    /// Every hit along the whole line of `ray`: `f(t, part)`, unordered.
    fn roots(&self, ray: &Ray, mut f: impl FnMut(f64, Part)) {
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
        let span = (t1 - t0) * len;
        let (ho, hd) = (DVec2::new(o.x, o.z), DVec2::new(d.x, d.z));
        let (hd2, hod, ho2) = (hd.length_squared(), ho.dot(hd), ho.length_squared());
        let last = self.segments.len() - 1;
        for (k, seg) in self.segments.iter().enumerate() {
            let (u0, du) = (seg.u(o.y), d.y / seg.h);
            // The ray's stretch within the segment's heights (all of it when level).
            let (lo, hi) = if du != 0.0 {
                let (a, b) = (-u0 / du, (1.0 - u0) / du);
                (a.min(b).max(-pad), a.max(b).min(span + pad))
            } else if (0.0..=1.0).contains(&u0) {
                (-pad, span + pad)
            } else {
                continue;
            };
            if lo > hi {
                continue;
            }
            let r = compose(&seg.r2, u0, du);
            let q = [ho2 - r[0], 2.0 * hod - r[1], hd2 - r[2], -r[3]];
            let widen = 1e-9 * (hi - lo).max(self.size());
            for root in roots_in(&q, lo - widen, hi + widen).iter() {
                let u = u0 + du * root.t;
                // Roots at u = 1 belong to the next segment's u = 0, except on the last.
                if u >= 0.0 && (u < 1.0 || (k == last && u <= 1.0)) {
                    f(t0 + root.t / len, Part::Curve(k));
                }
            }
        }
        if d.y != 0.0 {
            for (part, y, r) in [
                (Part::Base, self.bounds.min.y, self.base),
                (Part::Cap, self.bounds.max.y, self.cap),
            ] {
                if r > 0.0 {
                    let t = (y - o.y) / d.y;
                    if (ho + t * hd).length_squared() <= r * r {
                        f(t0 + t / len, part);
                    }
                }
            }
        }
    }

    fn hit(&self, ray: &Ray, t: f64, part: Part) -> Hit {
        let p = ray.at(t);
        let rho = DVec2::new(p.x, p.z).norm();
        let n_segs = self.segments.len() as f64;
        let (normal, v) = match part {
            Part::Curve(k) => {
                let seg = &self.segments[k];
                let u = seg.u(p.y);
                // The gradient of x² + z² − R(y): positive outside.
                let n = DVec3::new(2.0 * p.x, -seg.slope(u), 2.0 * p.z);
                (
                    n.try_unit().unwrap_or(DVec3::Y),
                    (k as f64 + u.clamp(0.0, 1.0)) / n_segs,
                )
            }
            // POV-Ray's v: the base disk from −1 (centre) to 0, the cap from 2 to 1.
            Part::Base => (-DVec3::Y, rho / self.base - 1.0),
            Part::Cap => (DVec3::Y, 2.0 - rho / self.cap),
        };
        let u = libm::atan2(-p.z, p.x).rem_euclid(TAU) / TAU;
        Hit {
            t,
            normal,
            uv: DVec2::new(u, v),
        }
    }

    /// Nearest hit in (t_min, t_max).
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let mut best: Option<(f64, Part)> = None;
        self.roots(ray, |t, part| {
            if t > t_min && t < t_max && best.is_none_or(|b| t < b.0) {
                best = Some((t, part));
            }
        });
        best.map(|(t, part)| self.hit(ray, t, part))
    }

    /// Boundary crossings along the whole line, entering where the outward normal faces the
    /// ray.
    pub(crate) fn crossings(&self, ray: &Ray, out: &mut Vec<Crossing>) {
        let from = out.len();
        self.roots(ray, |t, part| {
            let hit = self.hit(ray, t, part);
            out.push(Crossing {
                entering: hit.normal.dot(ray.dir) < 0.0,
                hit,
            });
        });
        out[from..].sort_by(|a, b| a.hit.t.total_cmp(&b.hit.t));
    }

    /// The segment holding height `y` (the first whose top is at or above it), if any.
    fn segment_at(&self, y: f64) -> Option<&Segment> {
        if !(self.bounds.min.y..=self.bounds.max.y).contains(&y) {
            return None;
        }
        self.segments.iter().find(|s| y <= s.y0 + s.h)
    }

    /// True when `p` is inside or on the solid (never for an open one, a surface).
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        if self.open {
            return false;
        }
        self.segment_at(p.y)
            .is_some_and(|s| DVec2::new(p.x, p.z).length_squared() <= eval(&s.r2, s.u(p.y)))
    }

    /// Error bound of a computed point `p` on the surface: the smaller of its horizontal
    /// distance to the curve and the first-order distance `|ρ² − R| / |∇|`, or its distance to
    /// a disk's plane, plus the rounding of the evaluation.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let rho = DVec2::new(p.x, p.z).norm();
        let mut dist = f64::INFINITY;
        if let Some(s) = self.segment_at(p.y) {
            let u = s.u(p.y);
            let r2 = eval(&s.r2, u);
            let grad = DVec2::new(2.0 * rho, s.slope(u)).norm();
            let first_order = (rho * rho - r2).abs() / grad.max(f64::MIN_POSITIVE);
            let horizontal = (rho - r2.max(0.0).sqrt()).abs();
            dist = first_order.min(horizontal);
        }
        for (y, r) in [
            (self.bounds.min.y, self.base),
            (self.bounds.max.y, self.cap),
        ] {
            if r > 0.0 && rho <= r * (1.0 + 1e-9) {
                dist = dist.min((p.y - y).abs());
            }
        }
        let size = self.size() + p.abs().max_element();
        if !dist.is_finite() {
            dist = size;
        }
        // The cubic's roots in t are polished to full precision, but a root near a double
        // one (a grazing ray) keeps only about half the digits along the ray.
        rounding::from_residual(dist, 64, size) + DVec3::splat(1e-10 * size)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_straight_profile_is_a_cylinder() {
        // Equal radii: every slope is 0, so radius² is 1 on every segment.
        let s = Sor::new(&[[1.0, -1.0], [1.0, 0.0], [1.0, 1.0], [1.0, 2.0]], false).unwrap();
        let r = Ray::new(DVec3::new(-5.0, 0.5, 0.0), DVec3::X);
        let h = s.intersect(&r, 0.0, f64::INFINITY).unwrap();
        assert!((h.t - 4.0).abs() < 1e-12, "{}", h.t);
        assert!((h.normal + DVec3::X).norm() < 1e-12, "{}", h.normal);
        let down = Ray::new(DVec3::new(0.2, 5.0, 0.1), -DVec3::Y);
        let h = s.intersect(&down, 0.0, f64::INFINITY).unwrap();
        assert!((h.t - 4.0).abs() < 1e-12 && h.normal == DVec3::Y);
        let mut out = Vec::new();
        s.crossings(&down, &mut out);
        assert_eq!(out.len(), 2);
        assert!(out[0].entering && !out[1].entering && (out[1].hit.t - 5.0).abs() < 1e-12);
        assert!(s.contains(DVec3::new(0.5, 0.5, 0.5)) && !s.contains(DVec3::new(0.0, 1.5, 0.0)));
        let open = Sor::new(&[[1.0, -1.0], [1.0, 0.0], [1.0, 1.0], [1.0, 2.0]], true).unwrap();
        assert!(open.intersect(&down, 0.0, f64::INFINITY).is_none());
    }

    #[test]
    fn heights_must_increase() {
        assert!(Sor::new(&[[1.0, 0.0], [1.0, 1.0], [1.0, 1.0], [1.0, 2.0]], false).is_none());
        assert!(Sor::new(&[[1.0, 0.0], [1.0, 1.0], [1.0, 2.0]], false).is_none());
        assert!(Sor::new(&[[1.0, 0.0], [-1.0, 1.0], [1.0, 2.0], [1.0, 3.0]], false).is_none());
    }
}
