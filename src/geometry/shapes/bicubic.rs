//! A bicubic Bézier patch (POV-Ray's `bicubic_patch`), intersected directly rather than
//! tessellated.
//!
//! The patch is `S(s, t) = Σ Bᵢ(s)·Bⱼ(t)·P[i][j]` over a 4 × 4 grid of control points, `i`
//! the row (POV-Ray's first index, its `u`) and `j` the column. When it is made, the patch is
//! split by de Casteljau's rule into a quad tree of sub-patches until each is nearly flat
//! (every control point within a tenth of its size of the plane-like bilinear patch of its
//! corners); each node is bounded by the box of its control points, which holds the
//! sub-patch by the convex hull property (padded for the rounding of the splits). A ray walks
//! the tree; in each leaf it meets, Newton's method solves `S(s, t) = o + τ·d` in `(s, t, τ)`
//! from the point where the ray meets the leaf's corner triangles. Being nearly flat, a leaf
//! is met at most once away from grazing, and Newton converges from there in a few steps to
//! the rounding of the evaluation; a root is kept only when its residual is that small. POV-Ray's
//! `type`, `flatness`, `u_steps` and `v_steps` choose its tessellation and mean nothing here.

use crate::num::Norm;
use glam::{DVec2, DVec3};

use crate::geometry::rounding::{self, gamma};
use crate::geometry::{aabb::Aabb, ray::Hit, ray::Ray};

/// The deepest subdivision (4⁶ leaves at most; a strongly curved patch is flat at 4).
const MAX_DEPTH: u32 = 6;
/// How far a leaf's control points may stray from its corners' bilinear patch, as a share of
/// the leaf's diagonal.
const FLATNESS: f64 = 0.1;
/// Newton steps at most per leaf (it converges in 3 to 6 from a flat leaf's guess).
const NEWTON_STEPS: usize = 24;

/// A 4 × 4 grid of control points, `[row][column]`.
type Grid = [[DVec3; 4]; 4];

/// A bicubic patch in object space, with its quad tree of sub-patches.
#[derive(Clone, Debug)]
pub(crate) struct BicubicPatch {
    /// The control points.
    p: Grid,
    /// The quad tree; node 0 is the whole patch, a node's children are four in a row.
    nodes: Vec<Node>,
    /// The diagonal of the control points' box (tolerances scale with it).
    extent: f64,
    /// The largest coordinate magnitude of a control point (the evaluation's rounding).
    magnitude: f64,
}

/// A sub-patch: its box, its parameter rectangle and where its children are.
#[derive(Clone, Copy, Debug)]
struct Node {
    /// The box of its control points, padded.
    lo: DVec3,
    /// Upper corner of that box.
    hi: DVec3,
    /// `[s0, s1, t0, t1]`.
    range: [f64; 4],
    /// Index of the first of its four children; 0 for a leaf.
    first: u32,
}

/// Position and first derivatives of the patch at `(s, t)`.
#[derive(Clone, Copy, Debug)]
struct Jet {
    p: DVec3,
    ds: DVec3,
    dt: DVec3,
}

impl BicubicPatch {
    /// A patch from its control points (finite); `None` when it has no area (every sampled
    /// tangent plane degenerate: all points on one line, or every row the same curve).
    pub(crate) fn new(p: Grid) -> Option<BicubicPatch> {
        let flat: Vec<DVec3> = p.iter().flatten().copied().collect();
        let lo = flat.iter().fold(DVec3::INFINITY, |a, &b| a.min(b));
        let hi = flat.iter().fold(DVec3::NEG_INFINITY, |a, &b| a.max(b));
        let extent = (hi - lo).norm();
        let magnitude = lo.abs().max(hi.abs()).max_element();
        if !(extent > 0.0 && extent.is_finite()) {
            return None;
        }
        let mut patch = BicubicPatch {
            p,
            nodes: Vec::new(),
            extent,
            magnitude,
        };
        // |S_s × S_t| is a polynomial of degree 5 in each of s and t: unless it is zero
        // everywhere it cannot vanish on a 7 × 7 grid, so this finds any patch with an area.
        let some_area = (0..7).any(|a| {
            (0..7).any(|b| {
                let j = patch.jet(f64::from(a) / 6.0, f64::from(b) / 6.0);
                j.ds.cross(j.dt).norm() > 1e-12 * extent * extent
            })
        });
        if !some_area {
            return None;
        }
        patch.nodes.push(Node {
            lo,
            hi,
            range: [0.0, 1.0, 0.0, 1.0],
            first: 0,
        });
        patch.build(0, p, 0);
        Some(patch)
    }

    /// Splits node `at` (control points `g`) until its leaves are flat.
    fn build(&mut self, at: usize, g: Grid, depth: u32) {
        let pad = gamma(16) * (self.magnitude + self.extent) * 4.0;
        let (lo, hi) = grid_box(&g);
        self.nodes[at].lo = lo - DVec3::splat(pad);
        self.nodes[at].hi = hi + DVec3::splat(pad);
        if depth >= MAX_DEPTH || is_flat(&g) {
            return;
        }
        let [s0, s1, t0, t1] = self.nodes[at].range;
        let (sm, tm) = (0.5 * (s0 + s1), 0.5 * (t0 + t1));
        let first = self.nodes.len();
        self.nodes[at].first = first as u32;
        let (low_s, high_s) = split_rows(&g);
        let quarters = [
            (split_columns(&low_s), [s0, sm]),
            (split_columns(&high_s), [sm, s1]),
        ];
        let mut children = Vec::with_capacity(4);
        for ((low_t, high_t), [a, b]) in quarters {
            children.push((low_t, [a, b, t0, tm]));
            children.push((high_t, [a, b, tm, t1]));
        }
        for (_, range) in &children {
            self.nodes.push(Node {
                lo,
                hi,
                range: *range,
                first: 0,
            });
        }
        for (k, (grid, _)) in children.into_iter().enumerate() {
            self.build(first + k, grid, depth + 1);
        }
    }

    /// Object-space bounds: the control points' box (the patch lies in their convex hull).
    pub(crate) fn bounds(&self) -> Aabb {
        Aabb::new(self.nodes[0].lo, self.nodes[0].hi)
    }

    /// Nearest hit in (t_min, t_max); uv are POV-Ray's: `u` along a row (the column
    /// parameter), `v` across the rows.
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let inv = ray.dir.recip();
        let mut best: Option<(f64, f64, f64)> = None;
        let mut far = t_max;
        let mut stack = [0u32; 4 * MAX_DEPTH as usize + 4];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let node = &self.nodes[stack[top] as usize];
            let t0 = (node.lo - ray.origin) * inv;
            let t1 = (node.hi - ray.origin) * inv;
            let near = t0.min(t1).max_element().max(t_min);
            let exit = t0.max(t1).min_element().min(far);
            // NaN (a zero direction component on a slab's plane) keeps the node: a missed
            // prune costs time, a wrong one a hole.
            if near > exit {
                continue;
            }
            if node.first != 0 {
                for k in 0..4 {
                    stack[top] = node.first + k;
                    top += 1;
                }
                continue;
            }
            if let Some((tau, s, t)) = self.solve(node, ray, near)
                && tau > t_min
                && tau < far
            {
                far = tau;
                best = Some((tau, s, t));
            }
        }
        let (tau, s, t) = best?;
        Some(Hit {
            t: tau,
            normal: self.normal(s, t),
            uv: DVec2::new(t, s),
        })
    }

    /// Newton's method in `(s, t, τ)` on one leaf, from where the ray meets its corner
    /// triangles (`entry` when it meets neither plane): the root, if it converges to one on
    /// the patch with a residual at the rounding of the evaluation.
    fn solve(&self, leaf: &Node, ray: &Ray, entry: f64) -> Option<(f64, f64, f64)> {
        let [s0, s1, t0, t1] = leaf.range;
        let (ws, wt) = (s1 - s0, t1 - t0);
        let corner = |a: f64, b: f64| self.jet(s0 + a * ws, t0 + b * wt).p;
        let (c00, c10, c11, c01) = (
            corner(0.0, 0.0),
            corner(1.0, 0.0),
            corner(1.0, 1.0),
            corner(0.0, 1.0),
        );
        let (a, b, mut tau) = guess([c00, c10, c11, c01], ray).unwrap_or((0.5, 0.5, entry));
        let mut s = s0 + a.clamp(0.0, 1.0) * ws;
        let mut t = t0 + b.clamp(0.0, 1.0) * wt;
        // Iterates stay within a leaf's width of the leaf: a root farther away is another
        // leaf's to find.
        let (lo_s, hi_s) = ((s0 - ws).max(0.0), (s1 + ws).min(1.0));
        let (lo_t, hi_t) = ((t0 - wt).max(0.0), (t1 + wt).min(1.0));
        let mut converged = false;
        for _ in 0..NEWTON_STEPS {
            let j = self.jet(s, t);
            let f = j.p - ray.at(tau);
            let (ca, cb, cc) = (j.ds, j.dt, -ray.dir);
            let (bc, ca_x, ab) = (cb.cross(cc), cc.cross(ca), ca.cross(cb));
            let det = ca.dot(bc);
            if det == 0.0 || !det.is_finite() {
                return None;
            }
            let (ds, dt, dtau) = (-f.dot(bc) / det, -f.dot(ca_x) / det, -f.dot(ab) / det);
            s = (s + ds).clamp(lo_s, hi_s);
            t = (t + dt).clamp(lo_t, hi_t);
            tau += dtau;
            if !tau.is_finite() {
                return None;
            }
            if ds.abs() <= 1e-14 && dt.abs() <= 1e-14 {
                converged = true;
                break;
            }
        }
        let f = self.jet(s, t).p - ray.at(tau);
        let scale = self.magnitude
            + self.extent
            + ray.origin.abs().max_element()
            + ray.at(tau).abs().max_element();
        let tolerance = 1e-9 * self.extent + gamma(64) * scale;
        let close = f.abs().max_element() <= tolerance;
        (close && (converged || f.abs().max_element() <= gamma(64) * scale)).then_some((tau, s, t))
    }

    /// The unit front normal `S_s × S_t` at `(s, t)` (POV-Ray's orientation). Where a
    /// tangent vanishes (an edge collapsed to a point) the normal is the limit along the
    /// patch: the vanishing tangent is replaced by the mixed derivative it grows with, signed
    /// by the side of the edge; elsewhere degenerate (a fold, a corner where both vanish) it
    /// is the normal of a point slightly inside. Never NaN.
    pub(crate) fn normal(&self, s: f64, t: f64) -> DVec3 {
        let tiny = 1e-8 * self.extent;
        let j = self.jet(s, t);
        let n = j.ds.cross(j.dt);
        if j.ds.norm() > tiny && j.dt.norm() > tiny && n.norm() > 1e-8 * j.ds.norm() * j.dt.norm() {
            return n.unit();
        }
        let st = self.mixed(s, t);
        let limit = if j.dt.norm() <= tiny && j.ds.norm() > tiny {
            // S_t ≈ (s − edge)·S_st near a collapsed row.
            j.ds.cross(st) * if s < 0.5 { 1.0 } else { -1.0 }
        } else if j.ds.norm() <= tiny && j.dt.norm() > tiny {
            // S_s ≈ (t − edge)·S_st near a collapsed column.
            st.cross(j.dt) * if t < 0.5 { 1.0 } else { -1.0 }
        } else {
            DVec3::ZERO
        };
        if let Some(n) = limit.try_unit() {
            return n;
        }
        for step in [1e-6, 1e-4, 1e-2, 0.5] {
            let j = self.jet(s + step * (0.5 - s), t + step * (0.5 - t));
            if let Some(n) = j.ds.cross(j.dt).try_unit() {
                return n;
            }
        }
        DVec3::Y
    }

    /// Error bound of a computed point `p` on the patch: its distance to the nearest point
    /// of the patch found by projecting it in the leaves whose boxes hold it (any point of the
    /// patch bounds the distance from above), plus the rounding of evaluating that point.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let slack = 1e-9 * self.extent;
        let mut best = f64::INFINITY;
        let mut stack = vec![0usize];
        while let Some(k) = stack.pop() {
            let node = &self.nodes[k];
            let gap = (node.lo - p).max(p - node.hi).max(DVec3::ZERO).norm();
            if gap > slack || gap >= best {
                continue;
            }
            if node.first != 0 {
                let f = node.first as usize;
                stack.extend(f..f + 4);
                continue;
            }
            best = best.min(self.project(node, p));
        }
        if !best.is_finite() {
            // Off every leaf's box: the whole box bounds the distance.
            best = self.extent + (p - self.nodes[0].lo).abs().max_element();
        }
        let magnitude = self.magnitude + p.abs().max_element();
        rounding::from_residual(best, 64, magnitude)
    }

    /// The distance from `p` to the point of a leaf that Gauss-Newton's closest-point
    /// iteration reaches from its centre.
    fn project(&self, leaf: &Node, p: DVec3) -> f64 {
        let [s0, s1, t0, t1] = leaf.range;
        let (mut s, mut t) = (0.5 * (s0 + s1), 0.5 * (t0 + t1));
        let mut best = f64::INFINITY;
        for _ in 0..12 {
            let j = self.jet(s, t);
            let r = p - j.p;
            best = best.min(r.norm());
            let (a, b, c) = (j.ds.dot(j.ds), j.ds.dot(j.dt), j.dt.dot(j.dt));
            let det = a * c - b * b;
            if det.is_nan() || det <= 0.0 {
                break;
            }
            let (gs, gt) = (j.ds.dot(r), j.dt.dot(r));
            let (ds, dt) = ((c * gs - b * gt) / det, (a * gt - b * gs) / det);
            s = (s + ds).clamp(s0, s1);
            t = (t + dt).clamp(t0, t1);
            if ds.abs() <= 1e-15 && dt.abs() <= 1e-15 {
                break;
            }
        }
        best.min((p - self.jet(s, t).p).norm())
    }

    /// The point of the patch at `(s, t)`.
    #[cfg(test)]
    fn point(&self, s: f64, t: f64) -> DVec3 {
        self.jet(s, t).p
    }

    /// Position and first derivatives at `(s, t)`.
    fn jet(&self, s: f64, t: f64) -> Jet {
        let (bs, dbs) = (bernstein(s), bernstein_d(s));
        let (bt, dbt) = (bernstein(t), bernstein_d(t));
        let mut j = Jet {
            p: DVec3::ZERO,
            ds: DVec3::ZERO,
            dt: DVec3::ZERO,
        };
        for ((row_p, &b), &db) in self.p.iter().zip(&bs).zip(&dbs) {
            let (mut row, mut row_dt) = (DVec3::ZERO, DVec3::ZERO);
            for ((p, &c), &dc) in row_p.iter().zip(&bt).zip(&dbt) {
                row += c * *p;
                row_dt += dc * *p;
            }
            j.p += b * row;
            j.ds += db * row;
            j.dt += b * row_dt;
        }
        j
    }

    /// The mixed derivative `S_st` at `(s, t)`.
    fn mixed(&self, s: f64, t: f64) -> DVec3 {
        let (dbs, dbt) = (bernstein_d(s), bernstein_d(t));
        let mut m = DVec3::ZERO;
        for (row, &a) in self.p.iter().zip(&dbs) {
            for (p, &b) in row.iter().zip(&dbt) {
                m += (a * b) * *p;
            }
        }
        m
    }
}

/// The cubic Bernstein basis at `x`.
fn bernstein(x: f64) -> [f64; 4] {
    let y = 1.0 - x;
    [y * y * y, 3.0 * x * y * y, 3.0 * x * x * y, x * x * x]
}

/// The derivatives of the cubic Bernstein basis at `x`.
fn bernstein_d(x: f64) -> [f64; 4] {
    let y = 1.0 - x;
    [
        -3.0 * y * y,
        3.0 * y * y - 6.0 * x * y,
        6.0 * x * y - 3.0 * x * x,
        3.0 * x * x,
    ]
}

/// The box of a grid's points.
fn grid_box(g: &Grid) -> (DVec3, DVec3) {
    let mut lo = DVec3::INFINITY;
    let mut hi = DVec3::NEG_INFINITY;
    for p in g.iter().flatten() {
        lo = lo.min(*p);
        hi = hi.max(*p);
    }
    (lo, hi)
}

/// Whether every control point lies within [`FLATNESS`] of the grid's diagonal from the
/// bilinear patch of its corners at the point's own parameters.
fn is_flat(g: &Grid) -> bool {
    let (lo, hi) = grid_box(g);
    let limit = FLATNESS * (hi - lo).norm();
    g.iter().enumerate().all(|(i, row)| {
        row.iter().enumerate().all(|(k, p)| {
            let (a, b) = (i as f64 / 3.0, k as f64 / 3.0);
            let bilinear = (1.0 - a) * ((1.0 - b) * g[0][0] + b * g[0][3])
                + a * ((1.0 - b) * g[3][0] + b * g[3][3]);
            (*p - bilinear).norm() <= limit
        })
    })
}

/// A cubic Bézier curve split at its middle (de Casteljau).
fn halves(c: [DVec3; 4]) -> ([DVec3; 4], [DVec3; 4]) {
    let ab = 0.5 * (c[0] + c[1]);
    let bc = 0.5 * (c[1] + c[2]);
    let cd = 0.5 * (c[2] + c[3]);
    let abc = 0.5 * (ab + bc);
    let bcd = 0.5 * (bc + cd);
    let mid = 0.5 * (abc + bcd);
    ([c[0], ab, abc, mid], [mid, bcd, cd, c[3]])
}

/// The grid split at `s = 1/2` (across the rows): the halves with the low and high `s`.
fn split_rows(g: &Grid) -> (Grid, Grid) {
    let mut low = *g;
    let mut high = *g;
    for k in 0..4 {
        let (a, b) = halves(g.map(|row| row[k]));
        for (i, (x, y)) in a.into_iter().zip(b).enumerate() {
            low[i][k] = x;
            high[i][k] = y;
        }
    }
    (low, high)
}

/// The grid split at `t = 1/2` (along each row): the halves with the low and high `t`.
fn split_columns(g: &Grid) -> (Grid, Grid) {
    let mut low = *g;
    let mut high = *g;
    for ((l, h), row) in low.iter_mut().zip(high.iter_mut()).zip(g) {
        (*l, *h) = halves(*row);
    }
    (low, high)
}

/// Where the ray's line meets the leaf's corner triangles `(c00, c10, c11)` and `(c00, c11,
/// c01)`, as leaf parameters `(a, b)` and `τ`: the triangle whose barycentrics are the most
/// inside (extended past its edges when the ray misses both); `None` when the ray is parallel
/// to both planes.
fn guess(c: [DVec3; 4], ray: &Ray) -> Option<(f64, f64, f64)> {
    let [c00, c10, c11, c01] = c;
    let mut best: Option<(f64, f64, f64, f64)> = None;
    for (k, (p1, p2)) in [(c10, c11), (c11, c01)].into_iter().enumerate() {
        let (e1, e2) = (p1 - c00, p2 - c00);
        let h = ray.dir.cross(e2);
        let det = e1.dot(h);
        if det == 0.0 || !det.is_finite() {
            continue;
        }
        let q = ray.origin - c00;
        let b1 = q.dot(h) / det;
        let qe = q.cross(e1);
        let b2 = ray.dir.dot(qe) / det;
        let tau = e2.dot(qe) / det;
        let inside = b1.min(b2).min(1.0 - b1 - b2);
        let (a, b) = if k == 0 { (b1 + b2, b2) } else { (b1, b1 + b2) };
        if best.is_none_or(|x| inside > x.3) {
            best = Some((a, b, tau, inside));
        }
    }
    best.map(|(a, b, tau, _)| (a, b, tau))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A dome over the unit square with one edge collapsed to a point.
    fn dome(collapsed: bool) -> BicubicPatch {
        let mut g = [[DVec3::ZERO; 4]; 4];
        for (i, row) in g.iter_mut().enumerate() {
            for (k, p) in row.iter_mut().enumerate() {
                let (x, z) = (k as f64 / 3.0, i as f64 / 3.0);
                let h = if (1..3).contains(&i) && (1..3).contains(&k) {
                    1.0
                } else {
                    0.0
                };
                *p = DVec3::new(x, h, z);
            }
        }
        if collapsed {
            g[0] = [DVec3::new(0.5, 0.0, 0.0); 4];
        }
        BicubicPatch::new(g).expect("a patch")
    }

    #[test]
    fn a_ray_down_meets_the_dome_on_its_surface() {
        for collapsed in [false, true] {
            let d = dome(collapsed);
            for (x, z) in [(0.5, 0.5), (0.2, 0.7), (0.9, 0.1), (0.5, 0.02)] {
                let r = Ray::new(DVec3::new(x, 5.0, z), -DVec3::Y);
                let Some(h) = d.intersect(&r, 0.0, f64::INFINITY) else {
                    continue;
                };
                let q = d.point(h.uv.y, h.uv.x);
                assert!((q - r.at(h.t)).norm() < 1e-12, "{q} {}", r.at(h.t));
                assert!(h.normal.is_finite() && (h.normal.norm() - 1.0).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn a_collapsed_edge_has_a_finite_normal_at_its_point() {
        let d = dome(true);
        for t in [0.0, 0.3, 1.0] {
            let n = d.normal(0.0, t);
            assert!(n.is_finite() && (n.norm() - 1.0).abs() < 1e-12, "{n}");
            // The dome's normal at its pinched edge leans towards −y.. the side the patch's
            // orientation picks, the same as just inside it.
            let inside = d.normal(1e-3, t);
            assert!(n.dot(inside) > 0.5, "{n} vs {inside}");
        }
    }

    #[test]
    fn points_on_a_line_have_no_area() {
        let g = [[0, 1, 2, 3].map(|k| DVec3::X * f64::from(k)); 4];
        assert!(BicubicPatch::new(g).is_none());
        assert!(BicubicPatch::new([[DVec3::ONE; 4]; 4]).is_none());
    }
}
