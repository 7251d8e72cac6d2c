//! Height fields (POV-Ray's `height_field`): a grid of `nx × nz` heights over the unit square
//! x, z ∈ [0, 1], point `(i, j)` at `(i/(nx−1), h, j/(nz−1))`, each cell two triangles split
//! on the diagonal from `(i+1, j)` to `(i, j+1)` as POV-Ray splits it.
//!
//! The surface a ray sees is the triangles (POV-Ray shows no sides); `water_level` cuts away
//! what lies below it. The solid CSG classifies is POV-Ray's inside (below the surface, the
//! heights raised to the water level, within the square), closed by the four sides and the
//! bottom `y = 0`, so its crossings alternate and agree with `contains`. The triangles are
//! tested with the watertight ray/triangle test of [`crate::geometry::shapes::triangle`] on
//! corners computed the same way in every cell, so neighbours share their edges exactly.

use std::sync::Arc;

use glam::{DVec2, DVec3};

use crate::geometry::shapes::height_field_walk::{BLOCK, Blocks, GridRay, walk};
use crate::geometry::shapes::triangle::watertight_f64;
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::Ray, rounding};
use crate::num::Norm;

/// A height field in object space.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct HeightField {
    /// Points along x (≥ 2).
    nx: usize,
    /// Points along z (≥ 2).
    nz: usize,
    /// Heights in [0, 1], row by row from z = 0: `h[j·nx + i]`.
    h: Arc<[f32]>,
    /// Interpolate vertex normals.
    smooth: bool,
    /// Parts below this height are cut away (0: none).
    water: f64,
    /// Per-block height ranges for the walk.
    blocks: Blocks,
    /// The highest height.
    top: f64,
}

/// A triangle of the top a ray's line meets.
#[derive(Clone, Copy, Debug)]
struct TriHit {
    /// The line's parameter there.
    t: f64,
    /// The triangle's corners.
    v: [DVec3; 3],
    /// Their grid points.
    idx: [(usize, usize); 3],
    /// The hit's barycentric weights of the corners.
    bary: [f64; 3],
}

/// A triangle's corners and their grid points.
type Corners = ([DVec3; 3], [(usize, usize); 3]);

/// Which surface a query reads: the one a ray sees (the triangles as given) or the solid's top
/// (every height raised to the water level, as POV-Ray's inside test reads it).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Top {
    Seen,
    Solid,
}

impl HeightField {
    /// A field of `nx × nz` heights; `None` unless both are ≥ 2, `h` has `nx·nz` finite
    /// values in [0, 1] and `water` is finite.
    pub(crate) fn new(
        nx: usize,
        nz: usize,
        h: Arc<[f32]>,
        smooth: bool,
        water: f64,
    ) -> Option<HeightField> {
        let ok = nx >= 2
            && nz >= 2
            && nx.checked_mul(nz) == Some(h.len())
            && h.iter().all(|v| (0.0..=1.0).contains(v))
            && water.is_finite();
        if !ok {
            return None;
        }
        let blocks = Blocks::new(nx, nz, &h);
        let top = h.iter().fold(0.0f32, |m, &v| m.max(v));
        Some(HeightField {
            nx,
            nz,
            h,
            smooth,
            water: water.max(0.0),
            blocks,
            top: f64::from(top),
        })
    }

    /// Object-space bounds: the unit square, from the bottom to the highest point.
    pub(crate) fn bounds(&self) -> Aabb {
        Aabb::new(
            DVec3::ZERO,
            DVec3::new(1.0, self.top.max(self.water.min(1.0)), 1.0),
        )
    }

    /// The x of grid column `i` (computed one way everywhere, so shared corners agree).
    #[inline]
    fn gx(&self, i: usize) -> f64 {
        i as f64 / (self.nx - 1) as f64
    }

    /// The z of grid row `j`.
    #[inline]
    fn gz(&self, j: usize) -> f64 {
        j as f64 / (self.nz - 1) as f64
    }

    /// The height of point `(i, j)` on `top`.
    #[inline]
    fn height(&self, i: usize, j: usize, top: Top) -> f64 {
        let v = f64::from(self.h[j * self.nx + i]);
        match top {
            Top::Seen => v,
            Top::Solid => v.max(self.water),
        }
    }

    /// The corner `(i, j)` on `top`.
    #[inline]
    fn corner(&self, i: usize, j: usize, top: Top) -> DVec3 {
        DVec3::new(self.gx(i), self.height(i, j, top), self.gz(j))
    }

    /// The two triangles of cell `(i, j)`, counter-clockwise seen from above, with their grid
    /// points: `[(0,0), (0,1), (1,0)]` and `[(1,1), (1,0), (0,1)]`.
    #[inline]
    fn triangles(&self, i: usize, j: usize, top: Top) -> [Corners; 2] {
        let a = [(i, j), (i, j + 1), (i + 1, j)];
        let b = [(i + 1, j + 1), (i + 1, j), (i, j + 1)];
        let pts = |k: [(usize, usize); 3]| k.map(|(x, z)| self.corner(x, z, top));
        [(pts(a), a), (pts(b), b)]
    }

    /// The ray in grid units, and the t-interval where its line is over the square; `None`
    /// when it never is.
    fn grid_ray(&self, ray: &Ray) -> Option<(GridRay, f64, f64)> {
        let sx = (self.nx - 1) as f64;
        let sz = (self.nz - 1) as f64;
        let g = GridRay {
            p: DVec2::new(ray.origin.x * sx, ray.origin.z * sz),
            d: DVec2::new(ray.dir.x * sx, ray.dir.z * sz),
            y0: ray.origin.y,
            dy: ray.dir.y,
        };
        let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
        for (o, d, n) in [(g.p.x, g.d.x, sx), (g.p.y, g.d.y, sz)] {
            if d == 0.0 {
                if !(0.0..=n).contains(&o) {
                    return None;
                }
            } else {
                let (a, b) = ((0.0 - o) / d, (n - o) / d);
                t0 = t0.max(a.min(b));
                t1 = t1.min(a.max(b));
            }
        }
        (t0 <= t1).then_some((g, t0, t1))
    }

    /// Every triangle hit of the line of `ray` on `top` with t in `[t0, t1]` (clipped to the
    /// square), cell by cell along the ray; `f` returns `true` to stop after the cell it is in.
    fn walk_triangles(
        &self,
        ray: &Ray,
        t0: f64,
        t1: f64,
        top: Top,
        mut f: impl FnMut(&TriHit) -> bool,
    ) {
        let Some((g, a, b)) = self.grid_ray(ray) else {
            return;
        };
        let (t0, t1) = (t0.max(a), t1.min(b));
        let lift = if top == Top::Solid { self.water } else { 0.0 };
        let (cells_x, cells_z) = (self.nx - 1, self.nz - 1);
        let bs = BLOCK as f64;
        walk(
            g.p / bs,
            g.d / bs,
            self.blocks.cols,
            self.blocks.rows,
            t0,
            t1,
            |bi, bj, ta, tb| {
                let (lo, hi) = self.blocks.range[bj * self.blocks.cols + bi];
                let (lo, hi) = (f64::from(lo).max(lift), f64::from(hi).max(lift));
                if !g.meets(ta, tb, lo, hi) {
                    return false;
                }
                let (i0, j0) = (bi * BLOCK, bj * BLOCK);
                let origin = g.p - DVec2::new(i0 as f64, j0 as f64);
                let cols = BLOCK.min(cells_x - i0);
                let rows = BLOCK.min(cells_z - j0);
                let mut stop = false;
                walk(origin, g.d, cols, rows, ta, tb, |ci, cj, ca, cb| {
                    let (i, j) = (i0 + ci, j0 + cj);
                    let hs = [(i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)]
                        .map(|(x, z)| self.height(x, z, top));
                    let lo = hs.iter().copied().fold(f64::INFINITY, f64::min);
                    let hi = hs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                    if !g.meets(ca, cb, lo, hi) {
                        return false;
                    }
                    for (v, idx) in self.triangles(i, j, top) {
                        if let Some((t, bary)) = watertight_f64(&v, ray.origin, ray.dir) {
                            stop |= f(&TriHit { t, v, idx, bary });
                        }
                    }
                    stop
                });
                stop
            },
        );
    }

    /// Nearest hit on the surface a ray sees in (t_min, t_max); uv is (x, z).
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let mut best: Option<TriHit> = None;
        self.walk_triangles(ray, t_min, t_max, Top::Seen, |h| {
            let cut = self.water > 0.0 && ray.at(h.t).y < self.water;
            if h.t > t_min && h.t < t_max && !cut && best.is_none_or(|b| h.t < b.t) {
                best = Some(*h);
            }
            // A hit ends the walk after its cell: later cells lie farther along the ray.
            best.is_some()
        });
        Some(self.hit_at(ray, &best?, Top::Seen))
    }

    /// The hit `h` of `ray` on the top: the triangle's normal (flat as a [`Triangle`]'s, or
    /// its corners' normals blended by the hit's barycentrics when smooth) and uv (x, z).
    ///
    /// [`Triangle`]: crate::geometry::shapes::triangle::Triangle
    fn hit_at(&self, ray: &Ray, h: &TriHit, top: Top) -> Hit {
        let p = ray.at(h.t);
        let v = h.v;
        let flat = (v[1] - v[0]).cross(v[2] - v[0]).unit_or(DVec3::Y);
        let normal = if self.smooth && top == Top::Seen {
            let n = h
                .idx
                .iter()
                .zip(h.bary)
                .fold(DVec3::ZERO, |s, (&(x, z), k)| {
                    s + k * self.vertex_normal(x, z)
                });
            n.try_unit().unwrap_or(flat)
        } else {
            flat
        };
        let t = h.t;
        Hit {
            t,
            normal,
            uv: DVec2::new(p.x.clamp(0.0, 1.0), p.z.clamp(0.0, 1.0)),
        }
    }

    /// The cell under `(x, z)` (clamped into the grid) and the point's place in it.
    fn locate(&self, x: f64, z: f64) -> (usize, usize, f64, f64) {
        let one = |u: f64, n: usize| {
            let g = (u * (n - 1) as f64).clamp(0.0, (n - 1) as f64);
            let i = (g.floor() as usize).min(n - 2);
            (i, g - i as f64)
        };
        let (i, fx) = one(x, self.nx);
        let (j, fz) = one(z, self.nz);
        (i, j, fx, fz)
    }

    /// The unit normal at grid point `(i, j)` from the heights' central differences (one-sided
    /// at the border), for smooth shading.
    fn vertex_normal(&self, i: usize, j: usize) -> DVec3 {
        let slope = |a: usize, b: usize, ha: f64, hb: f64, n: usize| {
            (hb - ha) / ((b - a) as f64 / (n - 1) as f64)
        };
        let (xa, xb) = (i.saturating_sub(1), (i + 1).min(self.nx - 1));
        let (za, zb) = (j.saturating_sub(1), (j + 1).min(self.nz - 1));
        let dx = slope(
            xa,
            xb,
            self.height(xa, j, Top::Seen),
            self.height(xb, j, Top::Seen),
            self.nx,
        );
        let dz = slope(
            za,
            zb,
            self.height(i, za, Top::Seen),
            self.height(i, zb, Top::Seen),
            self.nz,
        );
        DVec3::new(-dx, 1.0, -dz).unit()
    }

    /// The solid's top at `(x, z)` in the square: the height of the triangle under it.
    fn surface(&self, x: f64, z: f64, top: Top) -> f64 {
        let (i, j, fx, fz) = self.locate(x, z);
        let h = |a, b| self.height(a, b, top);
        if fx + fz <= 1.0 {
            let h00 = h(i, j);
            h00 + (h(i + 1, j) - h00) * fx + (h(i, j + 1) - h00) * fz
        } else {
            let h11 = h(i + 1, j + 1);
            h11 + (h(i, j + 1) - h11) * (1.0 - fx) + (h(i + 1, j) - h11) * (1.0 - fz)
        }
    }

    /// Whether `q` is in the solid: over the square, above the bottom and under the top.
    pub(crate) fn contains(&self, q: DVec3) -> bool {
        (0.0..=1.0).contains(&q.x)
            && (0.0..=1.0).contains(&q.z)
            && q.y >= 0.0
            && q.y <= self.surface(q.x, q.z, Top::Solid)
    }

    /// Every crossing of the solid's boundary along the whole line of `r`, in order: the top's
    /// triangles, the four sides and the bottom. A line through a shared edge meets both
    /// triangles; crossings are kept only where they alternate, so each counts once.
    pub(crate) fn crossings(&self, r: &Ray, out: &mut Vec<Crossing>) {
        let mut all: Vec<Crossing> = Vec::new();
        let mut push = |hit: Hit| {
            all.push(Crossing {
                hit,
                entering: hit.normal.dot(r.dir) < 0.0,
            });
        };
        let mut tops = Vec::new();
        self.walk_triangles(r, f64::NEG_INFINITY, f64::INFINITY, Top::Solid, |h| {
            tops.push(*h);
            false
        });
        for h in &tops {
            push(self.hit_at(r, h, Top::Solid));
        }
        // The sides x = 0, x = 1, z = 0, z = 1 (up to the top's edge) and the bottom y = 0.
        let sides = [
            (0usize, 0.0, -DVec3::X),
            (0, 1.0, DVec3::X),
            (2, 0.0, -DVec3::Z),
            (2, 1.0, DVec3::Z),
            (1, 0.0, -DVec3::Y),
        ];
        for (axis, at, normal) in sides {
            let (o, d) = (r.origin[axis], r.dir[axis]);
            if d == 0.0 {
                continue;
            }
            let t = (at - o) / d;
            let p = r.at(t);
            let (x, z) = match axis {
                0 => (at, p.z),
                2 => (p.x, at),
                _ => (p.x, p.z),
            };
            let on = if axis == 1 {
                (0.0..=1.0).contains(&x) && (0.0..=1.0).contains(&z)
            } else {
                let along = if axis == 0 { z } else { x };
                (0.0..=1.0).contains(&along) && p.y >= 0.0 && p.y <= self.surface(x, z, Top::Solid)
            };
            if on {
                push(Hit {
                    t,
                    normal,
                    uv: DVec2::new(x.clamp(0.0, 1.0), z.clamp(0.0, 1.0)),
                });
            }
        }
        all.sort_by(|a, b| a.hit.t.total_cmp(&b.hit.t));
        let mut inside = false;
        for c in all {
            if c.entering != inside {
                inside = c.entering;
                out.push(c);
            }
        }
    }

    /// Error bound of a computed point `p` on it: its smallest residual off the top's plane
    /// under it, a side or the bottom, plus the rounding of computing it.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        let (i, j, fx, fz) = self.locate(p.x, p.z);
        let mut best = f64::INFINITY;
        for top in [Top::Seen, Top::Solid] {
            let [a, b] = self.triangles(i, j, top);
            let (v, _) = if fx + fz <= 1.0 { a } else { b };
            let n = (v[1] - v[0]).cross(v[2] - v[0]).unit_or(DVec3::Y);
            best = best.min((p - v[0]).dot(n).abs());
        }
        for r in [p.x, 1.0 - p.x, p.z, 1.0 - p.z, p.y] {
            best = best.min(r.abs());
        }
        rounding::from_residual(best, 12, p.abs().element_sum() + 1.0)
    }
}
