//! Triangles and the watertight ray/triangle test (Woop, Benthin, Wald 2013).
//!
//! The test shears the ray to the +z axis and evaluates the three 2-D edge functions. The edge
//! function of an edge shared by two triangles is computed from the same products with the
//! operands swapped, so it is the exact negation in the neighbour: a ray through a shared edge
//! or vertex is inside at least one of the triangles (zero counts as inside). No cracks.

use glam::{DVec2, DVec3, Mat3A, Vec3A};

use super::{Aabb, Hit, Ray};

/// A single triangle in object space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Triangle {
    /// Corners, counter-clockwise seen from the front.
    pub v: [DVec3; 3],
    /// Unit front normal.
    pub normal: DVec3,
}

impl Triangle {
    /// A triangle from its corners; `None` when it has no area.
    pub fn new(v: [DVec3; 3]) -> Option<Triangle> {
        let n = (v[1] - v[0]).cross(v[2] - v[0]);
        let normal = n.try_normalize()?;
        Some(Triangle { v, normal })
    }

    /// Nearest hit in (t_min, t_max); uv are the barycentric weights of v1 and v2.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        let (t, b) = watertight_f64(&self.v, ray.origin, ray.dir)?;
        (t > t_min && t < t_max).then_some(Hit {
            t,
            normal: self.normal,
            uv: DVec2::new(b[1], b[2]),
        })
    }

    /// Error bound of a computed point `p` on it: its residual off its plane.
    pub fn point_error(&self, p: DVec3) -> DVec3 {
        super::plane::point_error(self.v[0], self.normal, p)
    }

    /// Object-space bounds.
    pub fn bounds(&self) -> Aabb {
        Aabb::new(
            self.v[0].min(self.v[1]).min(self.v[2]),
            self.v[0].max(self.v[1]).max(self.v[2]),
        )
    }
}

/// Axis permutation and shear for one ray direction.
fn shear_axes(d: [f64; 3]) -> (usize, usize, usize) {
    let a = [d[0].abs(), d[1].abs(), d[2].abs()];
    let kz = if a[0] > a[1] {
        if a[0] > a[2] { 0 } else { 2 }
    } else if a[1] > a[2] {
        1
    } else {
        2
    };
    let mut kx = (kz + 1) % 3;
    let mut ky = (kx + 1) % 3;
    if d[kz] < 0.0 {
        std::mem::swap(&mut kx, &mut ky);
    }
    (kx, ky, kz)
}

/// Watertight test in f64 over the whole line: `(t, barycentrics)` or `None`.
pub fn watertight_f64(v: &[DVec3; 3], origin: DVec3, dir: DVec3) -> Option<(f64, [f64; 3])> {
    let d = dir.to_array();
    let (kx, ky, kz) = shear_axes(d);
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
/// The shear and axis permutation are folded into one matrix, so each vertex's sheared
/// coordinates are `shear * (v − origin)`: no per-triangle axis indexing, and every triangle
/// sharing a vertex computes bit-identical coordinates for it (what watertightness needs).
#[derive(Clone, Copy, Debug)]
pub struct ShearedRay {
    origin: Vec3A,
    shear: Mat3A,
}

impl ShearedRay {
    /// Prepares `origin + t·dir` (in the mesh's space); `None` for a zero direction.
    pub fn new(origin: DVec3, dir: DVec3) -> Option<ShearedRay> {
        Self::with_inverse(origin, dir, dir.recip())
    }

    /// Like [`ShearedRay::new`] with `dir.recip()` already known (saves a division).
    #[inline]
    pub fn with_inverse(origin: DVec3, dir: DVec3, recip: DVec3) -> Option<ShearedRay> {
        let d = dir.to_array();
        let (kx, ky, kz) = shear_axes(d);
        if d[kz] == 0.0 {
            return None;
        }
        let inv = recip.to_array()[kz];
        let (sx, sy, sz) = ((d[kx] * inv) as f32, (d[ky] * inv) as f32, inv as f32);
        // Columns of the matrix whose rows give x' = a[kx] − sx·a[kz], y' = a[ky] − sy·a[kz],
        // z' = sz·a[kz].
        let mut cols = [Vec3A::ZERO; 3];
        cols[kx] = Vec3A::X;
        cols[ky] = Vec3A::Y;
        cols[kz] = Vec3A::new(-sx, -sy, sz);
        Some(ShearedRay {
            origin: origin.as_vec3a(),
            shear: Mat3A::from_cols(cols[0], cols[1], cols[2]),
        })
    }

    /// Watertight test against one triangle: `(t, barycentrics)` over the whole line.
    ///
    /// Edge functions are evaluated in f32; when one is exactly zero (the ray passes through
    /// an edge or vertex) they are recomputed exactly in f64, as the paper prescribes.
    #[inline]
    pub fn intersect(&self, v: &[Vec3A; 3]) -> Option<(f32, [f32; 3])> {
        let a = self.shear * (v[0] - self.origin);
        let b = self.shear * (v[1] - self.origin);
        let c = self.shear * (v[2] - self.origin);
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
}
