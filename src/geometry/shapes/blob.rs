//! Blobs (metaballs): the surface where `Σ sᵢ·(1 − dᵢ(p)²/Rᵢ²)²` (over the components whose
//! region of influence holds p) equals the threshold; `dᵢ` is the distance to a sphere
//! component's centre, or to a cylinder component's segment (POV-Ray's blob `cylinder`: round
//! at both ends).
//!
//! Along a ray every component contributes a quartic in t inside its region (a cylinder: one
//! for its side, where the distance is to the axis line, and one for each round end), so
//! between two consecutive entry/exit events the field is one quartic: the roots are found
//! exactly per segment by isolation ([`crate::geometry::shapes::quartic`]), never by marching with a step that could
//! jump over a thin feature.

use crate::num::Norm;
use glam::DVec3;

use crate::geometry::shapes::quartic::roots_in;
use crate::geometry::shapes::sphere;
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};
use crate::ir::BlobComponent;

/// Metaballs in object space.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Blob {
    parts: Vec<BlobComponent>,
    threshold: f64,
    bounds: Aabb,
}

impl Blob {
    /// A blob; `None` unless the threshold is positive, every radius positive, and some
    /// component positive (else the surface is empty or unbounded).
    pub(crate) fn new(parts: &[BlobComponent], threshold: f64) -> Option<Blob> {
        let ok = threshold > 0.0
            && threshold.is_finite()
            && parts
                .iter()
                .all(|c| c.radius > 0.0 && c.radius.is_finite() && c.strength.is_finite());
        if !ok {
            return None;
        }
        let bounds = parts
            .iter()
            .filter(|c| c.strength > 0.0)
            .fold(Aabb::EMPTY, |b, c| {
                let round = sphere::bounds(c.center, c.radius);
                // A capsule lies within the box of its two end balls.
                let end = c.end.map_or(Aabb::EMPTY, |e| sphere::bounds(e, c.radius));
                b.union(round).union(end)
            });
        (!bounds.is_empty()).then(|| Blob {
            parts: parts.to_vec(),
            threshold,
            bounds,
        })
    }

    /// The field value at `p`.
    fn field(&self, p: DVec3) -> f64 {
        self.parts
            .iter()
            .map(|c| {
                let q = 1.0 - (p - nearest(c, p)).length_squared() / (c.radius * c.radius);
                if q > 0.0 { c.strength * q * q } else { 0.0 }
            })
            .sum()
    }

    /// Object-space bounds.
    pub(crate) fn bounds(&self) -> Aabb {
        self.bounds
    }

    /// Error bound of a computed point `p` on the surface: the field's residual over its
    /// gradient (the first-order distance; doubled for the curvature it ignores) plus the
    /// rounding of evaluating the field, in distance the same way.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let slope = self.gradient(p).norm();
        let mut size = self.threshold;
        for c in &self.parts {
            let s = (p - nearest(c, p)).length_squared() / (c.radius * c.radius);
            if s < 1.0 {
                size += c.strength.abs() * (1.0 + s) * (1.0 + s);
            }
        }
        if slope.is_nan() || slope <= 0.0 {
            return DVec3::splat(f64::INFINITY);
        }
        let residual = 2.0 * (self.field(p) - self.threshold) / slope;
        rounding::from_residual(residual, 16, size / slope)
            + rounding::gamma(4) * p.abs().max_element()
    }

    /// True when `p` is inside or on the surface.
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        self.field(p) >= self.threshold
    }

    fn gradient(&self, p: DVec3) -> DVec3 {
        self.parts
            .iter()
            .map(|c| {
                let w = p - nearest(c, p);
                let r2 = c.radius * c.radius;
                let q = 1.0 - w.length_squared() / r2;
                if q > 0.0 {
                    -4.0 * c.strength * q * w / r2
                } else {
                    DVec3::ZERO
                }
            })
            .sum()
    }

    /// Every sign-changing root along the whole line; `rising` means the field rises through
    /// the threshold there (the ray enters).
    fn roots(&self, ray: &Ray, mut f: impl FnMut(f64, bool)) {
        let len = ray.dir.norm();
        if len == 0.0 || !len.is_finite() {
            return;
        }
        let Some((t0, _)) = self
            .bounds
            .hit_interval(ray, f64::NEG_INFINITY, f64::INFINITY)
        else {
            return;
        };
        let d = ray.dir / len;
        let o = ray.at(t0);
        // Per component: the interval inside its sphere and the quartic q(s)² there.
        let mut spans: Vec<(f64, f64, [f64; 5])> = Vec::with_capacity(self.parts.len());
        let mut events: Vec<f64> = Vec::with_capacity(2 * self.parts.len());
        for c in &self.parts {
            let Some(end) = c.end else {
                if let Some(span) = ball_span(c.center, c, o, d, f64::NEG_INFINITY, f64::INFINITY) {
                    spans.push(span);
                    events.extend([span.0, span.1]);
                }
                continue;
            };
            for span in capsule_spans(c, end, o, d).into_iter().flatten() {
                spans.push(span);
                events.extend([span.0, span.1]);
            }
        }
        events.sort_by(f64::total_cmp);
        events.dedup();
        for w in events.windows(2) {
            let (sa, sb) = (w[0], w[1]);
            let mid = 0.5 * (sa + sb);
            let mut poly = [-self.threshold, 0.0, 0.0, 0.0, 0.0];
            let mut any = false;
            for (s0, s1, p) in &spans {
                if *s0 <= mid && mid <= *s1 {
                    any = true;
                    for (acc, k) in poly.iter_mut().zip(p) {
                        *acc += k;
                    }
                }
            }
            if any {
                for r in roots_in(&poly, sa, sb).iter() {
                    f(t0 + r.t / len, r.rising);
                }
            }
        }
    }

    fn hit(&self, ray: &Ray, t: f64) -> Hit {
        let p = ray.at(t);
        let normal = (-self.gradient(p))
            .try_unit()
            .unwrap_or_else(|| -ray.dir.unit_or(Default::default()));
        Hit {
            t,
            normal,
            uv: crate::geometry::ray::equirectangular_uv(normal),
        }
    }

    /// Nearest hit in (t_min, t_max).
    ///
    /// A hit's t is a root of a quartic formed at the bounds' entry, known only to ~2¹⁴ ε of the
    /// blob's size (worst seen in tests/numerics_invariants.rs: 9·10⁻¹³), far less exactly than
    /// the hit point: roots that close to `t_min` are the surface a spawned ray just left
    /// (seen as speckles in the gallery), not hits.
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let roots = rounding::gamma(1 << 14) * (self.bounds.max - self.bounds.min).norm();
        let t_min = t_min + roots / ray.dir.norm();
        crate::geometry::shapes::quartic::nearest_root(t_min, t_max, |visit| self.roots(ray, visit))
            .map(|t| self.hit(ray, t))
    }

    /// Boundary crossings along the whole line.
    pub(crate) fn crossings(&self, ray: &Ray, out: &mut Vec<Crossing>) {
        self.roots(ray, |t, rising| {
            out.push(Crossing {
                hit: self.hit(ray, t),
                entering: rising,
            });
        });
    }
}

/// One component's field along the line `o + s·d` over `(s0, s1)`: the quartic's coefficients.
type Span = (f64, f64, [f64; 5]);

/// The point of component `c` nearest `p`: its centre, or a cylinder's nearest axis point.
fn nearest(c: &BlobComponent, p: DVec3) -> DVec3 {
    let Some(end) = c.end else {
        return c.center;
    };
    let axis = end - c.center;
    let len2 = axis.length_squared();
    if len2 == 0.0 {
        return c.center;
    }
    c.center + axis * ((p - c.center).dot(axis) / len2).clamp(0.0, 1.0)
}

/// The field `s·q(s)²` of a ball around `at` (radius and strength `c`'s) along the line
/// `o + s·d` (unit `d`), where `q = 1 − |o + s·d − at|²/R²` is positive, cut to `(lo, hi)`.
fn ball_span(at: DVec3, c: &BlobComponent, o: DVec3, d: DVec3, lo: f64, hi: f64) -> Option<Span> {
    let w = o - at;
    let inv = 1.0 / (c.radius * c.radius);
    let (a, b, g) = (-inv, -2.0 * w.dot(d) * inv, 1.0 - w.length_squared() * inv);
    quadratic_span(a, b, g, c.strength, lo, hi)
}

/// The field `k·q(s)²` for `q(s) = a·s² + b·s + g` (a < 0) where `q` is positive, cut to
/// `(lo, hi)`; `None` when that is empty.
fn quadratic_span(a: f64, b: f64, g: f64, k: f64, lo: f64, hi: f64) -> Option<Span> {
    let (s0, s1) = crate::geometry::shapes::quartic::quadratic(-a, -b, -g)?;
    let (s0, s1) = (s0.max(lo), s1.min(hi));
    if s0 >= s1 {
        return None;
    }
    let poly = [
        k * g * g,
        k * 2.0 * b * g,
        k * (b * b + 2.0 * a * g),
        k * 2.0 * a * b,
        k * a * a,
    ];
    Some((s0, s1, poly))
}

/// A cylinder component's pieces along the line `o + s·d` (unit `d`): the side, where the
/// nearest point is on the axis between the ends (the distance is to the axis line), and the
/// round ends beyond them (the distance is to the end point).
fn capsule_spans(c: &BlobComponent, end: DVec3, o: DVec3, d: DVec3) -> [Option<Span>; 3] {
    let axis = end - c.center;
    let len = axis.norm();
    if len == 0.0 || !len.is_finite() {
        return [
            ball_span(c.center, c, o, d, f64::NEG_INFINITY, f64::INFINITY),
            None,
            None,
        ];
    }
    let u = axis / len;
    let w = o - c.center;
    // Where along the axis the line's point projects: h(s) = h0 + s·hd.
    let (h0, hd) = (w.dot(u), d.dot(u));
    // The s range over which 0 ≤ h(s) ≤ len (all or nothing when the line is across the axis).
    let (before, after) = if hd == 0.0 {
        if (0.0..=len).contains(&h0) {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else if h0 < 0.0 {
            (f64::INFINITY, f64::INFINITY)
        } else {
            (f64::NEG_INFINITY, f64::NEG_INFINITY)
        }
    } else {
        let (s_start, s_end) = (-h0 / hd, (len - h0) / hd);
        (s_start.min(s_end), s_start.max(s_end))
    };
    let inv = 1.0 / (c.radius * c.radius);
    let (wp, dp) = (w - h0 * u, d - hd * u);
    let side = quadratic_span(
        -dp.length_squared() * inv,
        -2.0 * wp.dot(dp) * inv,
        1.0 - wp.length_squared() * inv,
        c.strength,
        before,
        after,
    );
    // Beyond `before` the line is past one end, beyond `after` past the other.
    let (first, last) = if hd >= 0.0 {
        (c.center, end)
    } else {
        (end, c.center)
    };
    [
        side,
        ball_span(first, c, o, d, f64::NEG_INFINITY, before),
        ball_span(last, c, o, d, after, f64::INFINITY),
    ]
}
