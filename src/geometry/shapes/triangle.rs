//! Triangles and the watertight ray/triangle test (Woop, Benthin, Wald 2013).
//!
//! The test shears the ray to the +z axis and evaluates the three 2-D edge functions. The edge
//! function of an edge shared by two triangles is computed from the same products with the
//! operands swapped, so it is the exact negation in the neighbour: a ray through a shared edge
//! or vertex is inside at least one of the triangles (zero counts as inside). No cracks.

use crate::num::Norm;
use glam::{DVec2, DVec3, Vec3, Vec3A, Vec4};

use crate::geometry::{aabb::Aabb, ray::Hit, ray::Ray};

/// A single triangle in object space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Triangle {
    /// Corners, counter-clockwise seen from the front.
    v: [DVec3; 3],
    /// Unit front normal.
    normal: DVec3,
}

impl Triangle {
    /// A triangle from its corners; `None` when it has no area.
    pub(crate) fn new(v: [DVec3; 3]) -> Option<Triangle> {
        let n = (v[1] - v[0]).cross(v[2] - v[0]);
        let normal = n.try_unit()?;
        Some(Triangle { v, normal })
    }

    /// Nearest hit in (t_min, t_max); uv are the barycentric weights of v1 and v2.
    pub(crate) fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let (t, b) = watertight_f64(&self.v, ray.origin, ray.dir)?;
        (t > t_min && t < t_max).then_some(Hit {
            t,
            normal: self.normal,
            uv: DVec2::new(b[1], b[2]),
        })
    }

    /// Error bound of a computed point `p` on it: its residual off its plane.
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        crate::geometry::shapes::plane::point_error(self.v[0], self.normal, p)
    }

    /// Object-space bounds.
    pub(crate) fn bounds(&self) -> Aabb {
        Aabb::new(
            self.v[0].min(self.v[1]).min(self.v[2]),
            self.v[0].max(self.v[1]).max(self.v[2]),
        )
    }
}

/// Axis permutation and shear for one ray direction.
///
/// Components are chosen by comparisons, not indexed arrays: a ray's set-up then stays in
/// registers (measured: spilling the direction to index it stalled mesh packets' set-up on a
/// store-to-load forward, ~3% of the duck's render).
#[inline(always)]
fn shear_axes(d: DVec3) -> (usize, usize, usize) {
    let a = d.abs();
    let kz = if a.x > a.y {
        if a.x > a.z { 0 } else { 2 }
    } else if a.y > a.z {
        1
    } else {
        2
    };
    let mut kx = (kz + 1) % 3;
    let mut ky = (kx + 1) % 3;
    if pick(d, kz) < 0.0 {
        std::mem::swap(&mut kx, &mut ky);
    }
    (kx, ky, kz)
}

/// Component `k` (0, 1 or 2) of `v`.
#[inline(always)]
fn pick(v: DVec3, k: usize) -> f64 {
    match k {
        0 => v.x,
        1 => v.y,
        _ => v.z,
    }
}

/// Watertight test in f64 over the whole line: `(t, barycentrics)` or `None`.
pub(crate) fn watertight_f64(v: &[DVec3; 3], origin: DVec3, dir: DVec3) -> Option<(f64, [f64; 3])> {
    let (kx, ky, kz) = shear_axes(dir);
    let d = dir.to_array();
    if d[kz] == 0.0 {
        return None;
    }
    let (sx, sy, sz) = (d[kx] / d[kz], d[ky] / d[kz], 1.0 / d[kz]);
    let a = (v[0] - origin).to_array();
    let b = (v[1] - origin).to_array();
    let c = (v[2] - origin).to_array();
    let (ax, ay) = (a[kx] - sx * a[kz], a[ky] - sy * a[kz]);
    let (bx, by) = (b[kx] - sx * b[kz], b[ky] - sy * b[kz]);
    let (cx, cy) = (c[kx] - sx * c[kz], c[ky] - sy * c[kz]);
    let u = cx * by - cy * bx;
    let vv = ax * cy - ay * cx;
    let w = bx * ay - by * ax;
    finish(u, vv, w, sz * a[kz], sz * b[kz], sz * c[kz])
}

fn finish(u: f64, v: f64, w: f64, az: f64, bz: f64, cz: f64) -> Option<(f64, [f64; 3])> {
    if (u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0) {
        return None;
    }
    let det = u + v + w;
    if det == 0.0 {
        return None;
    }
    let t = (u * az + v * bz + w * cz) / det;
    Some((t, [u / det, v / det, w / det]))
}

/// A ray prepared for many f32 watertight triangle tests (meshes).
///
/// The axis permutation is an index per coordinate and the shear three factors, so a vertex's
/// sheared coordinates are `x' = p[kx] − sx·p[kz]`, `y' = p[ky] − sy·p[kz]`, `z' = sz·p[kz]`
/// with `p = v − origin`: every triangle sharing a vertex computes bit-identical coordinates
/// for it (what watertightness needs), in 8 operations per corner where a general 3×3 shear
/// matrix took 18 (its ones and zeros change no value, only perhaps the sign of a zero).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct ShearedRay {
    /// The axes (kx, ky, kz): kz the direction's dominant one.
    axes: [usize; 3],
    /// The origin's coordinates on those axes.
    origin: [f32; 3],
    /// The shear factors (sx, sy, sz).
    shear: [f32; 3],
}

impl ShearedRay {
    /// Prepares `origin + t·dir` (in the mesh's space); `None` for a zero direction. With
    /// `sheared` and `intersect`, the one-triangle reference the tests hold
    /// [`ShearedRay::intersect4`] to (meshes test whole blocks).
    #[cfg(test)]
    fn new(origin: DVec3, dir: DVec3) -> Option<ShearedRay> {
        Self::with_inverse(origin, dir, dir.recip())
    }

    /// Prepares `origin + t·dir` (in the mesh's space) with `dir.recip()` already known;
    /// `None` for a zero direction.
    #[inline(always)]
    pub(crate) fn with_inverse(origin: DVec3, dir: DVec3, recip: DVec3) -> Option<ShearedRay> {
        let (kx, ky, kz) = shear_axes(dir);
        if pick(dir, kz) == 0.0 {
            return None;
        }
        let inv = pick(recip, kz);
        let o = |k| pick(origin, k) as f32;
        Some(ShearedRay {
            axes: [kx, ky, kz],
            origin: [o(kx), o(ky), o(kz)],
            shear: [
                (pick(dir, kx) * inv) as f32,
                (pick(dir, ky) * inv) as f32,
                inv as f32,
            ],
        })
    }

    /// The sheared coordinates of the vertex `v`.
    #[cfg(test)]
    fn sheared(&self, v: Vec3A) -> Vec3A {
        let [kx, ky, kz] = self.axes;
        let [ox, oy, oz] = self.origin;
        let [sx, sy, sz] = self.shear;
        let pz = v[kz] - oz;
        Vec3A::new((v[kx] - ox) - sx * pz, (v[ky] - oy) - sy * pz, sz * pz)
    }

    /// Watertight test against one triangle: `(t, barycentrics)` over the whole line.
    ///
    /// Edge functions are evaluated in f32; when one is exactly zero (the ray passes through
    /// an edge or vertex) they are recomputed exactly in f64, as the paper prescribes.
    #[cfg(test)]
    fn intersect(&self, v: &[Vec3A; 3]) -> Option<(f32, [f32; 3])> {
        let [a, b, c] = v.map(|v| self.sheared(v));
        let (ax, ay, bx, by, cx, cy) = (a.x, a.y, b.x, b.y, c.x, c.y);
        let mut u = cx * by - cy * bx;
        let mut vv = ax * cy - ay * cx;
        let mut w = bx * ay - by * ax;
        if u == 0.0 || vv == 0.0 || w == 0.0 {
            // Rounding never flips the sign of a product difference, it can only reach zero;
            // then the same sheared coordinates give the exact value in f64 (products of two
            // f32 are exact there), so neighbours still agree on every shared edge.
            let exact =
                |p: f32, q: f32, r: f32, s: f32| (p as f64 * q as f64 - r as f64 * s as f64) as f32;
            u = exact(cx, by, cy, bx);
            vv = exact(ax, cy, ay, cx);
            w = exact(bx, ay, by, ax);
        }
        if (u < 0.0 || vv < 0.0 || w < 0.0) && (u > 0.0 || vv > 0.0 || w > 0.0) {
            return None;
        }
        let det = u + vv + w;
        if det == 0.0 {
            return None;
        }
        let t = (u * a.z + vv * b.z + w * c.z) / det;
        let inv = 1.0 / det;
        Some((t, [u * inv, vv * inv, w * inv]))
    }

    /// `ShearedRay::intersect` (the tests' one-triangle reference) on the first `lanes`
    /// triangles of a block at once.
    ///
    /// Every lane goes through the same f32 operations in the same order as the one-triangle
    /// test (the same shear and the same f64 recomputation of a zero edge function), so each
    /// lane's edge functions, and the `t` and barycentrics of [`Edges4::hit`], are
    /// bit-identical to it.
    #[inline(always)]
    pub(crate) fn intersect4(&self, block: &TriBlock, lanes: usize) -> Edges4 {
        let [kx, ky, kz] = self.axes;
        let [ox, oy, oz] = self.origin.map(Vec4::splat);
        let [sx, sy, sz] = self.shear.map(Vec4::splat);
        let shear = |k: usize| -> [Vec4; 3] {
            let v = &block.v[k];
            let pz = v[kz] - oz;
            [(v[kx] - ox) - sx * pz, (v[ky] - oy) - sy * pz, sz * pz]
        };
        let (a, b, c) = (shear(0), shear(1), shear(2));
        let mut u = c[0] * b[1] - c[1] * b[0];
        let mut v = a[0] * c[1] - a[1] * c[0];
        let mut w = b[0] * a[1] - b[1] * a[0];
        let used = (1u32 << lanes) - 1;
        let zero = Vec4::ZERO;
        let mut exact = (u.cmpeq(zero) | v.cmpeq(zero) | w.cmpeq(zero)).bitmask() & used;
        while exact != 0 {
            let l = exact.trailing_zeros() as usize;
            exact &= exact - 1;
            let (ax, ay, bx, by, cx, cy) = (a[0][l], a[1][l], b[0][l], b[1][l], c[0][l], c[1][l]);
            let exact =
                |p: f32, q: f32, r: f32, s: f32| (p as f64 * q as f64 - r as f64 * s as f64) as f32;
            u[l] = exact(cx, by, cy, bx);
            v[l] = exact(ax, cy, ay, cx);
            w[l] = exact(bx, ay, by, ax);
        }
        let negative = u.cmplt(zero) | v.cmplt(zero) | w.cmplt(zero);
        let positive = u.cmpgt(zero) | v.cmpgt(zero) | w.cmpgt(zero);
        let det = u + v + w;
        let inside = !(negative & positive) & det.cmpne(zero);
        Edges4 {
            u,
            v,
            w,
            z: [a[2], b[2], c[2]],
            mask: inside.bitmask() & used,
        }
    }
}

/// Four triangles' corners side by side for [`ShearedRay::intersect4`]: `v[corner][axis]`
/// holds that coordinate of the four triangles, one per lane.
#[derive(Clone, Copy, Debug)]
pub(crate) struct TriBlock {
    /// Corner coordinates, one triangle per lane.
    v: [[Vec4; 3]; 3],
}

impl TriBlock {
    /// A block with no triangles (NaN corners: unused lanes are masked, never tested).
    pub(crate) const EMPTY: TriBlock = TriBlock {
        v: [[Vec4::NAN; 3]; 3],
    };

    /// Stores a triangle's corners in `lane`.
    pub(crate) fn set(&mut self, lane: usize, corners: [Vec3; 3]) {
        for (k, p) in corners.iter().enumerate() {
            for axis in 0..3 {
                self.v[k][axis][lane] = p[axis];
            }
        }
    }

    /// The corners of the triangle in `lane`.
    #[inline]
    pub(crate) fn corners(&self, lane: usize) -> [Vec3A; 3] {
        self.v
            .map(|c| Vec3A::new(c[0][lane], c[1][lane], c[2][lane]))
    }
}

/// The edge functions of a block's triangles against one ray, and the lanes the ray meets.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Edges4 {
    u: Vec4,
    v: Vec4,
    w: Vec4,
    /// The sheared corners' z, per corner.
    z: [Vec4; 3],
    /// Bit `l` set: the line meets the triangle in lane `l`.
    pub(crate) mask: u32,
}

impl Edges4 {
    /// `(t, barycentrics)` of a lane in [`Edges4::mask`], as `ShearedRay::intersect` (the
    /// tests' reference) gives them.
    #[inline(always)]
    pub(crate) fn hit(&self, lane: usize) -> (f32, [f32; 3]) {
        let (u, vv, w) = (self.u[lane], self.v[lane], self.w[lane]);
        let det = u + vv + w;
        let t = (u * self.z[0][lane] + vv * self.z[1][lane] + w * self.z[2][lane]) / det;
        let inv = 1.0 / det;
        (t, [u * inv, vv * inv, w * inv])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 4-wide test gives every lane exactly what the one-triangle test gives: random
    /// triangles, and a grid of shared edges and vertices hit by rays through its vertices
    /// and edges (zero edge functions, the f64 recomputation).
    #[test]
    fn four_lanes_match_the_single_test_bit_for_bit() {
        let mut seed = 12345u64;
        let mut rnd = move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 40) as f32) / (1u64 << 24) as f32 * 2.0 - 1.0
        };
        let mut tris: Vec<[Vec3; 3]> = (0..40)
            .map(|_| [0; 3].map(|_| Vec3::new(rnd(), rnd(), rnd())))
            .collect();
        // A 3×3 grid of unit squares split into triangles, in the z = 0.5 plane.
        for i in 0..3 {
            for j in 0..3 {
                let p = |x: i32, y: i32| Vec3::new((i + x) as f32, (j + y) as f32, 0.5);
                tris.push([p(0, 0), p(1, 0), p(1, 1)]);
                tris.push([p(0, 0), p(1, 1), p(0, 1)]);
            }
        }
        tris.push([Vec3::ZERO, Vec3::X, Vec3::X * 2.0]); // no area
        let mut rays: Vec<(DVec3, DVec3)> = (0..300)
            .map(|_| {
                let o = DVec3::new(rnd() as f64, rnd() as f64, rnd() as f64) * 3.0;
                let d = DVec3::new(rnd() as f64, rnd() as f64, rnd() as f64);
                (o, d)
            })
            .collect();
        for x in 0..7 {
            for y in 0..7 {
                let target = DVec3::new(x as f64 * 0.5, y as f64 * 0.5, 0.5);
                for o in [DVec3::new(1.3, 1.7, 4.0), DVec3::new(0.0, 0.0, -2.0)] {
                    rays.push((o, target - o));
                }
                rays.push((target - DVec3::Z, DVec3::Z));
            }
        }
        for (o, d) in rays {
            let Some(sr) = ShearedRay::new(o, d) else {
                continue;
            };
            for chunk in tris.chunks(3).chain(tris.chunks(4)) {
                let mut block = TriBlock::EMPTY;
                for (lane, t) in chunk.iter().enumerate() {
                    block.set(lane, *t);
                }
                let e = sr.intersect4(&block, chunk.len());
                for (lane, t) in chunk.iter().enumerate() {
                    assert_eq!(block.corners(lane), t.map(Vec3A::from));
                    let want = sr.intersect(&t.map(Vec3A::from));
                    let got = (e.mask >> lane & 1 == 1).then(|| e.hit(lane));
                    let bits = |h: Option<(f32, [f32; 3])>| {
                        h.map(|(t, b)| (t.to_bits(), b.map(f32::to_bits)))
                    };
                    assert_eq!(bits(got), bits(want), "ray {o} {d}, triangle {t:?}");
                }
                assert_eq!(e.mask >> chunk.len(), 0);
            }
        }
    }
}
