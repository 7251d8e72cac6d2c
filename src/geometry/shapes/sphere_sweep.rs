//! Sphere sweeps (POV-Ray's `sphere_sweep`): the union of the spheres whose centre `C(s)` and
//! radius `r(s)` run along a spline through modelling spheres.
//!
//! A linear sweep is exact in closed form: its spheres joined, per segment, by the cone
//! frustum tangent to both end spheres (the two spheres' convex hull). A Catmull-Rom or
//! B-spline segment (cubic `C` and `r`) is found analytically in `s` instead: along a ray
//! `X(τ) = o + τ·d` (`d` a unit vector) the sphere of parameter `s` covers
//! `τ ∈ [c(s) − √g(s), c(s) + √g(s)]`, with `c = d·(C − o)` its closest approach and
//! `g = r² − |C − o|² + c²` (degree 6), wherever `g ≥ 0`. Over an interval of `s` where
//! `g ≥ 0` those stretches form one stretch, whose ends are the smallest entry and largest exit:
//! at the interval's ends, or where `c′ = ±g′/(2√g)`, i.e. at the roots of
//! `4·g·c′² − g′²` (degree 10). Each polynomial is solved on [0, 1] by the isolating root finder
//! ([`crate::geometry::shapes::quartic`]), so the result is deterministic and exact to rounding.
//! The shape's stretches are merged into the union's; the normal at a hit is that of the
//! sphere it lies on (the envelope's normal).

use glam::DVec3;

use crate::geometry::ray::equirectangular_uv;
use crate::geometry::shapes::cone::Cone;
use crate::geometry::shapes::quartic::{MAX_DEGREE, eval, quadratic, roots_in};
use crate::geometry::shapes::sphere;
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};
use crate::ir::SweepSpline;
use crate::num::Norm;

/// POV-Ray's Catmull-Rom basis: row i gives the coefficient of s^i from the four spheres.
const CATMULL_ROM: [[f64; 4]; 4] = [
    [0.0, 1.0, 0.0, 0.0],
    [-0.5, 0.0, 0.5, 0.0],
    [1.0, -2.5, 2.0, -0.5],
    [-0.5, 1.5, -1.5, 0.5],
];

/// POV-Ray's uniform cubic B-spline basis, the same way.
const B_SPLINE: [[f64; 4]; 4] = [
    [1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0, 0.0],
    [-3.0 / 6.0, 0.0, 3.0 / 6.0, 0.0],
    [3.0 / 6.0, -6.0 / 6.0, 3.0 / 6.0, 0.0],
    [-1.0 / 6.0, 3.0 / 6.0, -3.0 / 6.0, 1.0 / 6.0],
];

/// A cubic segment of a spline sweep: `C(s)` and `r(s)`, coefficients lowest degree first, with
/// a sphere holding every sphere of the segment.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Segment {
    c: [DVec3; 4],
    r: [f64; 4],
    bound_center: DVec3,
    bound_radius: f64,
    bounds: Aabb,
}

/// One convex or swept part of the union.
#[derive(Clone, Debug, PartialEq)]
enum Piece {
    Ball { center: DVec3, radius: f64 },
    Frustum(Cone),
    Spline(Segment),
}

/// A sphere sweep in object space.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct SphereSweep {
    pieces: Vec<Piece>,
    bounds: Aabb,
}

/// Product of two polynomials (lowest degree first) added into `out`, times `k`.
fn mul_add(a: &[f64], b: &[f64], k: f64, out: &mut [f64]) {
    for (i, &x) in a.iter().enumerate() {
        for (j, &y) in b.iter().enumerate() {
            out[i + j] += k * x * y;
        }
    }
}

/// The derivative of a polynomial of degree `N − 1`, in an array as long.
fn derivative<const N: usize>(c: &[f64; N]) -> [f64; N] {
    let mut d = [0.0; N];
    for (i, &k) in c.iter().enumerate().skip(1) {
        d[i - 1] = k * i as f64;
    }
    d
}

/// Lowest and highest value of a cubic on [0, 1].
fn range01(c: &[f64; 4]) -> (f64, f64) {
    let (mut lo, mut hi) = (
        eval(c, 0.0).min(eval(c, 1.0)),
        eval(c, 0.0).max(eval(c, 1.0)),
    );
    if let Some((a, b)) = quadratic(3.0 * c[3], 2.0 * c[2], c[1]) {
        for s in [a, b] {
            if (0.0..=1.0).contains(&s) {
                lo = lo.min(eval(c, s));
                hi = hi.max(eval(c, s));
            }
        }
    }
    (lo, hi)
}

impl Segment {
    fn new(c: [DVec3; 4], r: [f64; 4]) -> Segment {
        let axis = |k: usize| range01(&c.map(|v| v[k]));
        let (x, y, z) = (axis(0), axis(1), axis(2));
        let (r_lo, r_hi) = range01(&r);
        let rad = r_lo.abs().max(r_hi.abs());
        let bounds = Aabb::new(
            DVec3::new(x.0, y.0, z.0) - rad,
            DVec3::new(x.1, y.1, z.1) + rad,
        );
        Segment {
            c,
            r,
            bound_center: bounds.center(),
            bound_radius: 0.5 * (bounds.max - bounds.min).norm(),
            bounds,
        }
    }

    fn center(&self, s: f64) -> DVec3 {
        self.c[0] + s * (self.c[1] + s * (self.c[2] + s * self.c[3]))
    }

    /// `f(s) = |C(s) − p|² − r(s)²` (degree 6): negative where the sphere holds `p`.
    fn gap(&self, p: DVec3) -> [f64; 7] {
        let mut q = self.c;
        q[0] -= p;
        let mut f = [0.0; 7];
        for k in 0..3 {
            let qk = q.map(|v| v[k]);
            mul_add(&qk, &qk, 1.0, &mut f);
        }
        mul_add(&self.r, &self.r, -1.0, &mut f);
        f
    }

    /// The stretches of the line of `ray` (unit direction `d`, from `o`) the segment's spheres
    /// cover: `(τ, s)` of entry and exit, τ along `d` from `o`.
    fn stretches(&self, o: DVec3, d: DVec3, mut f: impl FnMut((f64, f64), (f64, f64))) {
        let mut q = self.c;
        q[0] -= o;
        let c = q.map(|v| v.dot(d));
        // g = r² − |q|² + c²
        let mut g = [0.0; 7];
        mul_add(&self.r, &self.r, 1.0, &mut g);
        for k in 0..3 {
            let qk = q.map(|v| v[k]);
            mul_add(&qk, &qk, -1.0, &mut g);
        }
        mul_add(&c, &c, 1.0, &mut g);
        // The intervals of s where g ≥ 0 (some sphere meets the line); none, and the ray misses
        // the segment without the degree-10 work below.
        let g_roots = roots_in(&g, 0.0, 1.0);
        let mut cuts = [0.0; MAX_DEGREE + 2];
        let mut n = 1;
        for r in g_roots.iter() {
            cuts[n] = r.t;
            n += 1;
        }
        cuts[n] = 1.0;
        n += 1;
        let mut covered = [false; MAX_DEGREE + 1];
        let (mut from, mut to) = (f64::INFINITY, f64::NEG_INFINITY);
        for (k, w) in cuts[..n].windows(2).enumerate() {
            covered[k] = eval(&g, 0.5 * (w[0] + w[1])) >= 0.0;
            if covered[k] {
                from = from.min(w[0]);
                to = to.max(w[1]);
            }
        }
        if from > to {
            return;
        }
        let dc = derivative(&c);
        let dg = derivative(&g);
        // h = 4·g·c′² − g′²: zero where the entry or the exit is stationary in s.
        let mut dc2 = [0.0; 5];
        mul_add(&dc[..3], &dc[..3], 1.0, &mut dc2);
        let mut h = [0.0; 11];
        mul_add(&g, &dc2, 4.0, &mut h);
        mul_add(&dg[..6], &dg[..6], -1.0, &mut h);
        // Only the stationary points inside covered intervals count: a grazing ray's few.
        let stationary = roots_in(&h, from, to);
        let ends = |s: f64| {
            let (cs, w) = (eval(&c, s), eval(&g, s).max(0.0).sqrt());
            (cs - w, cs + w)
        };
        for (k, w) in cuts[..n].windows(2).enumerate() {
            let (a, b) = (w[0], w[1]);
            if !covered[k] {
                continue;
            }
            let mut entry = (f64::INFINITY, a);
            let mut exit = (f64::NEG_INFINITY, a);
            let inside = stationary.iter().map(|r| r.t).filter(|&s| s > a && s < b);
            for s in [a, b].into_iter().chain(inside) {
                let (e, x) = ends(s);
                if e < entry.0 {
                    entry = (e, s);
                }
                if x > exit.0 {
                    exit = (x, s);
                }
            }
            f(entry, exit);
        }
    }
}

impl SphereSweep {
    /// A sweep through `spheres` `(centre, radius)` along `spline`; `None` with too few spheres
    /// for the spline, a non-finite centre or a radius not above 0.
    pub(crate) fn new(spheres: &[(DVec3, f64)], spline: SweepSpline) -> Option<SphereSweep> {
        if spheres.len() < spline.min_spheres()
            || !spheres
                .iter()
                .all(|(c, r)| c.is_finite() && r.is_finite() && *r > 0.0)
        {
            return None;
        }
        let mut pieces = Vec::new();
        match spline {
            SweepSpline::Linear => {
                for &(center, radius) in spheres {
                    pieces.push(Piece::Ball { center, radius });
                }
                for w in spheres.windows(2) {
                    if let Some(cone) = tangent_frustum(w[0], w[1]) {
                        pieces.push(Piece::Frustum(cone));
                    }
                }
            }
            SweepSpline::CatmullRom | SweepSpline::BSpline => {
                let m = if spline == SweepSpline::CatmullRom {
                    &CATMULL_ROM
                } else {
                    &B_SPLINE
                };
                for w in spheres.windows(4) {
                    let mut c = [DVec3::ZERO; 4];
                    let mut r = [0.0; 4];
                    for (i, row) in m.iter().enumerate() {
                        for (k, (center, radius)) in row.iter().zip(w) {
                            c[i] += k * *center;
                            r[i] += k * radius;
                        }
                    }
                    pieces.push(Piece::Spline(Segment::new(c, r)));
                }
            }
        }
        let bounds = pieces.iter().map(piece_bounds).reduce(Aabb::union)?;
        bounds.is_finite().then_some(SphereSweep { pieces, bounds })
    }

    /// Object-space bounds.
    pub(crate) fn bounds(&self) -> Aabb {
        self.bounds
    }

    fn size(&self) -> f64 {
        self.bounds
            .min
            .abs()
            .max(self.bounds.max.abs())
            .max_element()
    }

    /// The union's stretches along the line of `ray`, merged, in order: each an entry and an
    /// exit hit. Spline segments whose box the line meets only outside `(t_min, t_max)` are
    /// skipped: a part of the union wholly outside the window changes no boundary inside it.
    fn merged(&self, ray: &Ray, t_min: f64, t_max: f64) -> Vec<(Hit, Hit)> {
        let mut parts: Vec<(Hit, Hit)> = Vec::new();
        let len = ray.dir.norm();
        if len == 0.0 || !len.is_finite() {
            return parts;
        }
        let d = ray.dir / len;
        let mut pair = Vec::with_capacity(2);
        for piece in &self.pieces {
            match piece {
                Piece::Ball { center, radius } => {
                    pair.clear();
                    sphere::crossings(*center, *radius, ray, &mut pair);
                    if let [a, b] = pair[..] {
                        parts.push((a.hit, b.hit));
                    }
                }
                Piece::Frustum(cone) => {
                    pair.clear();
                    cone.crossings(ray, &mut pair);
                    if let [a, b] = pair[..] {
                        parts.push((a.hit, b.hit));
                    }
                }
                Piece::Spline(seg) => {
                    // Cheap rejection: the line misses the segment's bounding sphere.
                    let to = seg.bound_center - ray.origin;
                    let along = to.dot(d);
                    if (to - along * d).length_squared() > seg.bound_radius * seg.bound_radius {
                        continue;
                    }
                    // Then the segment's box (padded well beyond the stretches' rounding): the
                    // slab test rejects most rays the sphere lets through.
                    let pad = 1e-6 * seg.bound_radius;
                    let padded = Aabb::new(seg.bounds.min - pad, seg.bounds.max + pad);
                    if padded.hit_interval(ray, t_min, t_max).is_none() {
                        continue;
                    }
                    // From the line's point nearest the segment the numbers stay its size.
                    let o = ray.origin + along * d;
                    let hit = |(tau, s): (f64, f64)| {
                        let p = o + tau * d;
                        let normal = (p - seg.center(s)).try_unit().unwrap_or(DVec3::Y);
                        Hit {
                            t: (along + tau) / len,
                            normal,
                            uv: equirectangular_uv(normal),
                        }
                    };
                    seg.stretches(o, d, |a, b| parts.push((hit(a), hit(b))));
                }
            }
        }
        parts.sort_by(|a, b| a.0.t.total_cmp(&b.0.t));
        let mut out: Vec<(Hit, Hit)> = Vec::with_capacity(parts.len());
        for (a, b) in parts {
            match out.last_mut() {
                Some(last) if a.t <= last.1.t => {
                    if b.t > last.1.t {
                        last.1 = b;
                    }
                }
                _ => out.push((a, b)),
            }
        }
        for (a, b) in &mut out {
            // One uv for every piece: the direction of the normal, like a sphere's.
            a.uv = equirectangular_uv(a.normal);
            b.uv = equirectangular_uv(b.normal);
        }
        out
    }

    /// Nearest hit in (t_min, t_max).
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        // Rays that miss the whole sweep's box cost one slab test.
        self.bounds.hit_interval(ray, t_min, t_max)?;
        self.merged(ray, t_min, t_max)
            .into_iter()
            .flat_map(|(a, b)| [a, b])
            .find(|h| h.t > t_min)
            .filter(|h| h.t < t_max)
    }

    /// Boundary crossings along the whole line, in order.
    pub(crate) fn crossings(&self, ray: &Ray, out: &mut Vec<Crossing>) {
        for (a, b) in self.merged(ray, f64::NEG_INFINITY, f64::INFINITY) {
            out.push(Crossing {
                hit: a,
                entering: true,
            });
            out.push(Crossing {
                hit: b,
                entering: false,
            });
        }
    }

    /// True when `p` is inside or on one of the spheres.
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        if !self.bounds.contains(p, 0.0) {
            return false;
        }
        self.pieces.iter().any(|piece| match piece {
            Piece::Ball { center, radius } => sphere::contains(*center, *radius, p),
            Piece::Frustum(cone) => cone.contains(p),
            Piece::Spline(seg) => {
                if !seg.bounds.contains(p, 0.0) {
                    return false;
                }
                let f = seg.gap(p);
                eval(&f, 0.0) <= 0.0
                    || eval(&f, 1.0) <= 0.0
                    || roots_in(&f, 0.0, 1.0).iter().next().is_some()
            }
        })
    }

    /// Error bound of a computed point `p` on the surface: the smallest bound among the pieces
    /// (its distance to the nearest sphere of a spline segment), plus the rounding.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let size = self.size() + p.abs().max_element();
        let mut best = f64::INFINITY;
        for piece in &self.pieces {
            let e = match piece {
                Piece::Ball { center, radius } => {
                    sphere::point_error(*center, *radius, p).max_element()
                }
                Piece::Frustum(cone) => cone.point_error(p).max_element(),
                Piece::Spline(seg) => {
                    // Every sphere lies in the segment's box, so outside it the distance to the
                    // spheres is at least that to the box: a box farther than the best bound
                    // cannot lower it.
                    let b = &seg.bounds;
                    let gap = (b.min - p).max(p - b.max).max(DVec3::ZERO).norm();
                    if gap + 1e-9 * size >= best {
                        continue;
                    }
                    let f = seg.gap(p);
                    let candidates = roots_in(&derivative(&f), 0.0, 1.0);
                    let dist = [0.0, 1.0]
                        .into_iter()
                        .chain(candidates.iter().map(|r| r.t))
                        .map(|s| (p - seg.center(s)).norm() - eval(&seg.r, s).abs())
                        .fold(f64::INFINITY, f64::min);
                    // The degree-10 stationary points hold ~1e-12 of the segment's size.
                    dist.abs() + 1e-9 * size
                }
            };
            best = best.min(e);
        }
        rounding::from_residual(best, 64, size)
    }
}

/// The frustum tangent to both spheres, from the first's tangent circle to the second's;
/// `None` when one sphere holds the other (no frustum shows).
fn tangent_frustum(a: (DVec3, f64), b: (DVec3, f64)) -> Option<Cone> {
    let ((c0, r0), (c1, r1)) = (a, b);
    let axis = c1 - c0;
    let len = axis.norm();
    if len <= (r0 - r1).abs() {
        return None;
    }
    let dir = axis / len;
    // The cone's half-angle θ has sin θ = (r0 − r1)/len; each sphere's tangent circle lies
    // r·sin θ along the axis from its centre, with radius r·cos θ.
    let sin = (r0 - r1) / len;
    let cos = (1.0 - sin * sin).max(0.0).sqrt();
    Cone::new(
        c0 + dir * (r0 * sin),
        c1 + dir * (r1 * sin),
        r0 * cos,
        r1 * cos,
        true,
    )
}

fn piece_bounds(p: &Piece) -> Aabb {
    match p {
        Piece::Ball { center, radius } => sphere::bounds(*center, *radius),
        Piece::Frustum(cone) => cone.bounds(),
        Piece::Spline(seg) => seg.bounds,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_linear_sweep_of_equal_spheres_is_a_capsule() {
        let s = SphereSweep::new(
            &[(DVec3::ZERO, 0.5), (DVec3::new(2.0, 0.0, 0.0), 0.5)],
            SweepSpline::Linear,
        )
        .unwrap();
        // Across the middle: the cylinder.
        let r = Ray::new(DVec3::new(1.0, 5.0, 0.0), -DVec3::Y);
        let h = s.intersect(&r, 0.0, f64::INFINITY).unwrap();
        assert!((h.t - 4.5).abs() < 1e-12 && (h.normal - DVec3::Y).norm() < 1e-12);
        // Along the axis: the two caps only.
        let r = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
        let mut out = Vec::new();
        s.crossings(&r, &mut out);
        assert_eq!(out.len(), 2, "{out:?}");
        assert!((out[0].hit.t - 4.5).abs() < 1e-12 && (out[1].hit.t - 7.5).abs() < 1e-12);
        assert!(s.contains(DVec3::new(1.0, 0.4, 0.0)) && !s.contains(DVec3::new(1.0, 0.6, 0.0)));
    }

    #[test]
    fn a_straight_spline_sweep_of_equal_spheres_is_a_capsule_too() {
        // Evenly spaced collinear spheres: C(s) is linear on every segment, r constant.
        let spheres: Vec<(DVec3, f64)> = (0..5)
            .map(|i| (DVec3::new(f64::from(i), 0.0, 0.0), 0.5))
            .collect();
        for spline in [SweepSpline::CatmullRom, SweepSpline::BSpline] {
            let s = SphereSweep::new(&spheres, spline).unwrap();
            // Its centres run from 1 to 3 along x.
            let r = Ray::new(DVec3::new(2.0, 0.3, 5.0), -DVec3::Z);
            let h = s.intersect(&r, 0.0, f64::INFINITY).unwrap();
            let want = 5.0 - (0.25f64 - 0.09).sqrt();
            assert!((h.t - want).abs() < 1e-12, "{spline:?}: {}", h.t);
            assert!((h.normal - DVec3::new(0.0, 0.3, 0.4) / 0.5).norm() < 1e-9);
            let r = Ray::new(DVec3::new(-5.0, 0.1, 0.0), DVec3::X);
            let mut out = Vec::new();
            s.crossings(&r, &mut out);
            assert_eq!(out.len(), 2, "{spline:?}: {out:?}");
            let cap = (0.25f64 - 0.01).sqrt();
            assert!(
                (out[0].hit.t - (6.0 - cap)).abs() < 1e-9,
                "{}",
                out[0].hit.t
            );
            assert!(
                (out[1].hit.t - (8.0 + cap)).abs() < 1e-9,
                "{}",
                out[1].hit.t
            );
            // The first centre is at x = 1 (radius 0.5): x = 0.4 is beyond its cap.
            assert!(s.contains(DVec3::new(2.5, 0.0, 0.45)));
            assert!(!s.contains(DVec3::new(0.4, 0.0, 0.0)));
        }
    }
}
