//! The shared core of `prism` and `text`: a closed 2-D outline of polynomial segments (degree
//! ≤ 3) swept along an axis, linearly between two heights or conically from an apex at the
//! origin, intersected analytically. Per segment the ray's 2-D line (or, for a conic sweep, the
//! plane through the apex and the ray) against the segment's curve is a polynomial of degree
//! ≤ 3 in the curve parameter, solved by [`super::quartic::roots_in`]; caps test the outline by
//! counting crossings (even-odd, as POV-Ray's prism) or by winding (nonzero, as TrueType).
//!
//! The outline lives in a canonical frame `(a, b)` with the height `h` as the third axis; an
//! [`Axes`] maps it onto object space. Segments are grouped in clusters (a glyph, a prism's
//! outline) with their own boxes so a long string costs a few box tests per ray, not a root
//! solve per segment.

use crate::num::Norm;
use glam::{DVec2, DVec3};

use super::quartic::{eval, roots_in};
use crate::geometry::rounding;
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray};

/// A curve `(a(s), b(s))`, `s ∈ [0, 1]`, each coordinate a cubic with coefficients lowest
/// degree first.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Segment {
    /// Coefficients of `a(s)`.
    pub(crate) a: [f64; 4],
    /// Coefficients of `b(s)`.
    pub(crate) b: [f64; 4],
}

impl Segment {
    /// A straight segment from `p` to `q`.
    pub(crate) fn line(p: DVec2, q: DVec2) -> Segment {
        Segment::from_power([p, q - p, DVec2::ZERO, DVec2::ZERO])
    }

    /// A quadratic Bézier curve with control points `p0, p1, p2`.
    pub(crate) fn quad_bezier(p0: DVec2, p1: DVec2, p2: DVec2) -> Segment {
        Segment::from_power([p0, 2.0 * (p1 - p0), p0 - 2.0 * p1 + p2, DVec2::ZERO])
    }

    /// A cubic Bézier curve with control points `p0 … p3`.
    pub(crate) fn cubic_bezier(p0: DVec2, p1: DVec2, p2: DVec2, p3: DVec2) -> Segment {
        Segment::from_power([
            p0,
            3.0 * (p1 - p0),
            3.0 * p0 - 6.0 * p1 + 3.0 * p2,
            p3 - 3.0 * p2 + 3.0 * p1 - p0,
        ])
    }

    /// A curve from its power-basis coefficients (`c[0] + c[1]·s + c[2]·s² + c[3]·s³`).
    pub(crate) fn from_power(c: [DVec2; 4]) -> Segment {
        Segment {
            a: [c[0].x, c[1].x, c[2].x, c[3].x],
            b: [c[0].y, c[1].y, c[2].y, c[3].y],
        }
    }

    /// The point at `s`.
    pub(crate) fn at(&self, s: f64) -> DVec2 {
        DVec2::new(eval(&self.a, s), eval(&self.b, s))
    }

    /// The tangent at `s`.
    fn tangent(&self, s: f64) -> DVec2 {
        let d = |c: &[f64; 4]| c[1] + s * (2.0 * c[2] + s * 3.0 * c[3]);
        DVec2::new(d(&self.a), d(&self.b))
    }

    /// The exact 2-D box of the curve on `[0, 1]` (ends and the derivative's roots).
    fn bounds(&self) -> (DVec2, DVec2) {
        let mut lo = self.at(0.0).min(self.at(1.0));
        let mut hi = self.at(0.0).max(self.at(1.0));
        for c in [&self.a, &self.b] {
            let d = [c[1], 2.0 * c[2], 3.0 * c[3]];
            for r in roots_in(&d, 0.0, 1.0).iter() {
                let p = self.at(r.t);
                lo = lo.min(p);
                hi = hi.max(p);
            }
            // A derivative that only touches zero leaves the extremes at the ends.
        }
        (lo, hi)
    }

    /// The control points of the curve as a cubic Bézier curve.
    fn bezier(&self) -> [DVec2; 4] {
        let c = |k: usize| DVec2::new(self.a[k], self.b[k]);
        [
            c(0),
            c(0) + c(1) / 3.0,
            c(0) + (2.0 * c(1) + c(2)) / 3.0,
            c(0) + c(1) + c(2) + c(3),
        ]
    }

    /// Whether every coefficient is finite.
    pub(crate) fn is_finite(&self) -> bool {
        self.a.iter().chain(&self.b).all(|c| c.is_finite())
    }
}

/// How the inside of a 2-D outline is decided.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum FillRule {
    /// Inside where a ray from the point crosses the outline an odd number of times (POV-Ray).
    EvenOdd,
    /// Inside where the outline winds round the point a non-zero number of times (TrueType).
    NonZero,
}

/// How the outline is swept.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Sweep {
    /// The outline unchanged from `h0` to `h1`.
    Linear,
    /// The outline scaled by the height: a cone from the apex at the origin (`0 ≤ h0 < h1`).
    Conic,
}

/// Which object-space axes the canonical `(a, b, h)` frame is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Axes {
    /// `(a, b, h) = (x, z, y)`: the outline in the ground plane, swept up (prism).
    GroundUp,
    /// `(a, b, h) = (x, y, −z)`: the outline facing +z, swept back into −z (text).
    FrontBack,
}

impl Axes {
    /// Object space to canonical (its own inverse up to the sign of `h`).
    fn to_canon(self, v: DVec3) -> DVec3 {
        match self {
            Axes::GroundUp => DVec3::new(v.x, v.z, v.y),
            Axes::FrontBack => DVec3::new(v.x, v.y, -v.z),
        }
    }

    /// Canonical to object space.
    fn to_object(self, v: DVec3) -> DVec3 {
        match self {
            Axes::GroundUp => DVec3::new(v.x, v.z, v.y),
            Axes::FrontBack => DVec3::new(v.x, v.y, -v.z),
        }
    }
}

/// A segment ready for intersection: its curve, its 3-D box in the canonical frame and which
/// side of it is solid.
#[derive(Clone, Debug)]
struct Edge {
    curve: Segment,
    /// The curve's Bézier control points: its hull rejects the lines that miss it.
    hull: [DVec2; 4],
    lo2: DVec2,
    hi2: DVec2,
    lo: DVec3,
    hi: DVec3,
    /// +1 when the right-hand normal `(b', −a')` points out of the solid, −1 when it points in,
    /// 0 when the solid is on both sides or neither (no surface there: overlapping contours).
    outward: f64,
}

/// A group of closed contours with one box (a glyph; a prism's whole outline).
#[derive(Clone, Debug)]
struct Cluster {
    lo2: DVec2,
    hi2: DVec2,
    lo: DVec3,
    hi: DVec3,
    edges: std::ops::Range<usize>,
}

/// A swept outline in object space.
#[derive(Clone, Debug)]
pub(crate) struct Extrusion {
    edges: Vec<Edge>,
    clusters: Vec<Cluster>,
    rule: FillRule,
    sweep: Sweep,
    axes: Axes,
    h0: f64,
    h1: f64,
    /// The outline's 2-D box (uv of the caps).
    lo2: DVec2,
    size2: DVec2,
    /// Canonical 3-D box.
    lo: DVec3,
    hi: DVec3,
    /// The largest coordinate magnitude (error bounds).
    magnitude: f64,
}

/// A hit in the canonical frame: its parameter, normal (not unit), uv.
struct CanonHit {
    t: f64,
    normal: DVec3,
    uv: DVec2,
}

impl Extrusion {
    /// Builds the solid from clusters of closed contours (each a list of segments), or `None`
    /// when it has no area. `h0 < h1`; for a conic sweep `h0 ≥ 0`.
    pub(crate) fn new(
        clusters: &[Vec<Segment>],
        rule: FillRule,
        sweep: Sweep,
        axes: Axes,
        h0: f64,
        h1: f64,
    ) -> Option<Extrusion> {
        let mut out = Extrusion {
            edges: Vec::new(),
            clusters: Vec::new(),
            rule,
            sweep,
            axes,
            h0,
            h1,
            lo2: DVec2::ZERO,
            size2: DVec2::ONE,
            lo: DVec3::INFINITY,
            hi: DVec3::NEG_INFINITY,
            magnitude: 0.0,
        };
        let (mut lo2, mut hi2) = (DVec2::INFINITY, DVec2::NEG_INFINITY);
        for segs in clusters {
            let start = out.edges.len();
            let (mut clo, mut chi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
            let (mut clo2, mut chi2) = (DVec2::INFINITY, DVec2::NEG_INFINITY);
            for s in segs {
                let (l, h) = s.bounds();
                lo2 = lo2.min(l);
                hi2 = hi2.max(h);
                clo2 = clo2.min(l);
                chi2 = chi2.max(h);
                let (elo, ehi) = out.box3(l, h);
                clo = clo.min(elo);
                chi = chi.max(ehi);
                out.edges.push(Edge {
                    curve: *s,
                    hull: s.bezier(),
                    lo2: l,
                    hi2: h,
                    lo: elo,
                    hi: ehi,
                    outward: 0.0,
                });
            }
            if out.edges.len() > start {
                out.clusters.push(Cluster {
                    lo2: clo2,
                    hi2: chi2,
                    lo: clo,
                    hi: chi,
                    edges: start..out.edges.len(),
                });
                out.lo = out.lo.min(clo);
                out.hi = out.hi.max(chi);
            }
        }
        let size = hi2 - lo2;
        if out.edges.is_empty() || !(size.x > 0.0 && size.y > 0.0) {
            return None;
        }
        out.lo2 = lo2;
        out.size2 = size;
        out.magnitude =
            lo2.abs().max(hi2.abs()).max_element() * h1.abs().max(1.0) + h0.abs().max(h1.abs());
        // Which side of each edge is solid, sampled a little off three points along it.
        let step = 1e-7 * size.max_element();
        for i in 0..out.edges.len() {
            let c = out.edges[i].curve;
            let mut vote = 0.0;
            for s in [0.31, 0.5, 0.73] {
                let Some(n) = DVec2::new(c.tangent(s).y, -c.tangent(s).x).try_unit() else {
                    continue;
                };
                let p = c.at(s);
                let right = out.inside2(p + step * n);
                let left = out.inside2(p - step * n);
                vote += match (left, right) {
                    (true, false) => 1.0,
                    (false, true) => -1.0,
                    _ => 0.0,
                };
            }
            out.edges[i].outward = if vote > 0.0 {
                1.0
            } else if vote < 0.0 {
                -1.0
            } else {
                0.0
            };
        }
        Some(out)
    }

    /// The canonical 3-D box of a 2-D box swept.
    fn box3(&self, l: DVec2, h: DVec2) -> (DVec3, DVec3) {
        match self.sweep {
            Sweep::Linear => (DVec3::new(l.x, l.y, self.h0), DVec3::new(h.x, h.y, self.h1)),
            Sweep::Conic => {
                let lo = (l * self.h0).min(l * self.h1);
                let hi = (h * self.h0).max(h * self.h1);
                (
                    DVec3::new(lo.x, lo.y, self.h0),
                    DVec3::new(hi.x, hi.y, self.h1),
                )
            }
        }
    }

    /// Whether the 2-D point `q` is inside the outline by the fill rule.
    fn inside2(&self, q: DVec2) -> bool {
        let mut winding = 0i32;
        for c in &self.clusters {
            // A closed contour neither crosses nor winds round a point outside its box.
            if q.x > c.hi2.x || q.y < c.lo2.y || q.y > c.hi2.y {
                continue;
            }
            for e in &self.edges[c.edges.clone()] {
                if q.y < e.lo2.y || q.y > e.hi2.y || q.x > e.hi2.x {
                    continue;
                }
                if q.x < e.lo2.x {
                    // Every crossing is to the right: their sum is the change of side from
                    // one end to the other, with no root to find.
                    let above = |s: f64| i32::from(eval(&e.curve.b, s) > q.y);
                    winding += above(1.0) - above(0.0);
                    continue;
                }
                let mut b = e.curve.b;
                b[0] -= q.y;
                for r in crossings_of(&b) {
                    if e.curve.at(r.0).x > q.x {
                        winding += if r.1 { 1 } else { -1 };
                    }
                }
            }
        }
        match self.rule {
            FillRule::EvenOdd => winding % 2 != 0,
            FillRule::NonZero => winding != 0,
        }
    }

    /// Every hit with `t` in `(t_min, t_max)`, in no particular order.
    fn hits(&self, ray: &Ray, t_min: f64, t_max: f64, f: &mut dyn FnMut(CanonHit)) {
        let o = self.axes.to_canon(ray.origin);
        let d = self.axes.to_canon(ray.dir);
        let r = Ray::new(o, d);
        let whole = Aabb::new(self.lo, self.hi);
        let Some((t0, t1)) = whole.hit_interval(&r, t_min, t_max) else {
            return;
        };
        // Caps.
        if d.z != 0.0 {
            for (hc, sign) in [(self.h0, -1.0), (self.h1, 1.0)] {
                let t = (hc - o.z) / d.z;
                if !(t > t_min && t < t_max) || hc == 0.0 && self.sweep == Sweep::Conic {
                    continue;
                }
                let p = DVec2::new(o.x + t * d.x, o.y + t * d.y);
                let q = match self.sweep {
                    Sweep::Linear => p,
                    Sweep::Conic => p / hc,
                };
                if self.inside2(q) {
                    f(CanonHit {
                        t,
                        normal: DVec3::new(0.0, 0.0, sign),
                        uv: ((q - self.lo2) / self.size2).clamp(DVec2::ZERO, DVec2::ONE),
                    });
                }
            }
        }
        let n_edges = self.edges.len() as f64;
        for c in &self.clusters {
            if Aabb::new(c.lo, c.hi).hit_interval(&r, t0, t1).is_none() {
                continue;
            }
            for (k, e) in self.edges[c.edges.clone()].iter().enumerate() {
                if e.outward == 0.0 || Aabb::new(e.lo, e.hi).hit_interval(&r, t0, t1).is_none() {
                    continue;
                }
                let index = (c.edges.start + k) as f64;
                self.edge_hits(e, &r, t_min, t_max, &mut |t, s, normal, h| {
                    let v = ((h - self.h0) / (self.h1 - self.h0)).clamp(0.0, 1.0);
                    f(CanonHit {
                        t,
                        normal,
                        uv: DVec2::new(((index + s) / n_edges).clamp(0.0, 1.0), v),
                    })
                });
            }
        }
    }

    /// The hits of the canonical ray `r` on one edge's side surface.
    fn edge_hits(
        &self,
        e: &Edge,
        r: &Ray,
        t_min: f64,
        t_max: f64,
        f: &mut dyn FnMut(f64, f64, DVec3, f64),
    ) {
        let (o, d) = (r.origin, r.dir);
        let c = &e.curve;
        // The curve's points that lie in the plane of the ray and the sweep direction.
        let n = match self.sweep {
            // Plane through the ray parallel to h: normal (d.b, −d.a, 0).
            Sweep::Linear => DVec3::new(d.y, -d.x, 0.0),
            // Plane through the ray and the apex.
            Sweep::Conic => o.cross(d),
        };
        if n.x == 0.0 && n.y == 0.0 && (self.sweep == Sweep::Linear || n.z == 0.0) {
            return;
        }
        let offset = match self.sweep {
            Sweep::Linear => n.x * o.x + n.y * o.y,
            Sweep::Conic => 0.0,
        };
        // The curve lies in its control points' hull: a plane with all of them on one side
        // misses it.
        let lift = if self.sweep == Sweep::Conic { n.z } else { 0.0 };
        let side = |p: &DVec2| n.x * p.x + n.y * p.y + lift - offset;
        if e.hull.iter().all(|p| side(p) > 0.0) || e.hull.iter().all(|p| side(p) < 0.0) {
            return;
        }
        let mut poly = [0.0; 4];
        for (i, p) in poly.iter_mut().enumerate() {
            *p = n.x * c.a[i] + n.y * c.b[i];
        }
        if self.sweep == Sweep::Conic {
            // Surface point h·(a, b, 1): the plane's equation n·(a, b, 1) = 0.
            poly[0] += n.z;
        }
        poly[0] -= offset;
        for (s, _) in crossings_of(&poly) {
            let p = c.at(s);
            let tan = c.tangent(s);
            let (t, h, normal) = match self.sweep {
                Sweep::Linear => {
                    let d2 = DVec2::new(d.x, d.y);
                    let t = (p - DVec2::new(o.x, o.y)).dot(d2) / d2.length_squared();
                    let h = o.z + t * d.z;
                    (t, h, DVec3::new(tan.y, -tan.x, 0.0))
                }
                Sweep::Conic => {
                    let q = DVec3::new(p.x, p.y, 1.0);
                    let dq = d.cross(q);
                    let dd = dq.length_squared();
                    if dd == 0.0 {
                        continue;
                    }
                    let t = -o.cross(q).dot(dq) / dd;
                    let h = o.z + t * d.z;
                    (t, h, DVec3::new(tan.y, -tan.x, tan.x * p.y - tan.y * p.x))
                }
            };
            if !(t > t_min && t < t_max && h >= self.h0 && h <= self.h1) {
                continue;
            }
            let normal = if normal.truncate() == DVec2::ZERO {
                // A cusp: the chord's normal.
                let ch = c.at((s + 1e-6).min(1.0)) - c.at((s - 1e-6).max(0.0));
                DVec3::new(ch.y, -ch.x, 0.0)
            } else {
                normal
            };
            f(t, s, e.outward * normal, h);
        }
    }

    /// Nearest hit in (t_min, t_max).
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let mut best: Option<CanonHit> = None;
        self.hits(ray, t_min, t_max, &mut |h| {
            if best.as_ref().is_none_or(|b| h.t < b.t) {
                best = Some(h);
            }
        });
        best.map(|h| self.to_hit(h))
    }

    fn to_hit(&self, h: CanonHit) -> Hit {
        Hit {
            t: h.t,
            normal: self.axes.to_object(h.normal).unit_or(DVec3::Y),
            uv: h.uv,
        }
    }

    /// Every boundary crossing along the whole line of `r`.
    pub(crate) fn crossings(&self, ray: &Ray, out: &mut Vec<Crossing>) {
        self.hits(ray, f64::NEG_INFINITY, f64::INFINITY, &mut |h| {
            let hit = self.to_hit(h);
            out.push(Crossing {
                entering: hit.normal.dot(ray.dir) < 0.0,
                hit,
            });
        });
    }

    /// Point membership.
    pub(crate) fn contains(&self, p: DVec3) -> bool {
        let q = self.axes.to_canon(p);
        if !(q.z >= self.h0 && q.z <= self.h1) {
            return false;
        }
        match self.sweep {
            Sweep::Linear => self.inside2(q.truncate()),
            Sweep::Conic => q.z > 0.0 && self.inside2(q.truncate() / q.z),
        }
    }

    /// Object-space bounds.
    pub(crate) fn bounds(&self) -> Aabb {
        let a = self.axes.to_object(self.lo);
        let b = self.axes.to_object(self.hi);
        Aabb::new(a.min(b), a.max(b))
    }

    /// Error bound of a computed hit point: the rounding of the root solve and the projection,
    /// relative to the largest coordinate in play.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        rounding::from_residual(0.0, 256, p.abs().max_element() + self.magnitude)
    }
}

/// Where the cubic `c` changes between `≤ 0` and `> 0` on `[0, 1]`, with whether it rises
/// there. A zero counts as `≤ 0`, so a zero at a joint between two segments of a closed chain
/// counts once when the chain crosses there and not at all when it only touches.
fn crossings_of(c: &[f64; 4]) -> impl Iterator<Item = (f64, bool)> {
    let mut out = [(0.0, false); 4];
    let mut n = 0;
    let above = |v: f64| v > 0.0;
    let (v0, v1) = (c[0], eval(c, 1.0));
    let mut state = above(v0);
    for r in roots_in(c, 0.0, 1.0).iter() {
        if n < 3 {
            out[n] = (r.t, r.rising);
            n += 1;
            state = r.rising;
        }
    }
    if state != above(v1) {
        // The flip the strict interior roots miss is at an end where the value is zero.
        let s = if v0 == 0.0 { 0.0 } else { 1.0 };
        let flip = (s, above(v1));
        if s == 0.0 {
            out.copy_within(0..n, 1);
            out[0] = flip;
        } else {
            out[n] = flip;
        }
        n += 1;
    }
    out.into_iter().take(n)
}
