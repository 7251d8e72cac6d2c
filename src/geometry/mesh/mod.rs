//! Triangle meshes ready for rays: the triangles of a loaded OBJ file (see `assets::obj`) in
//! the order of their own BVH, four to a block for the 4-wide test, with per-corner normals and
//! uvs and per-triangle material slots (in file order, read once per hit).

mod bvh;

use crate::num::Norm;
use glam::{DVec2, DVec3, Vec2, Vec3, Vec3A};
use rayon::prelude::*;

use crate::geometry::bvh::packet::PACKET;
use crate::geometry::bvh::{BLOCK, Bvh, BvhRay};
use crate::geometry::lanes::RayLanes;
use crate::geometry::shapes::triangle::{ShearedRay, TriBlock};
use crate::geometry::{aabb::Aabb, ray::Ray};
use crate::ir::limits::MAX_TRIANGLES;
use crate::lanes::{self, V3};

const _: () = assert!(MAX_TRIANGLES <= crate::geometry::bvh::MAX_PRIMITIVES);

/// A mesh's data in file order, as loaded (borrowed from the asset that holds it).
#[derive(Clone, Copy, Debug)]
pub struct MeshParts<'a> {
    /// Vertex positions the triangles index.
    pub vertices: &'a [Vec3],
    /// Triangles as indices into `vertices` (at most [`MAX_TRIANGLES`], each with area).
    pub triangles: &'a [[u32; 3]],
    /// Per-corner shading normals, one per triangle, or empty for flat shading.
    pub normals: &'a [[Vec3; 3]],
    /// Per-corner texture coordinates, one per triangle, or empty.
    pub uvs: &'a [[Vec2; 3]],
    /// Per-corner vertex colours, one per triangle, or empty.
    pub colors: &'a [[Vec3; 3]],
    /// Per-triangle material slot (`u32::MAX`: none), one per triangle, or empty.
    pub material_of: &'a [u32],
}

/// A mesh with its BVH, shared (`Arc`) by every object that places the same file.
#[derive(Debug)]
pub struct Mesh {
    /// Triangles' corners in BVH order, four side by side per block (a BVH leaf starts a
    /// block, so a leaf of up to four triangles is one 4-wide test); slot `s` is lane `s % 4`
    /// of block `s / 4`.
    blocks: Vec<TriBlock>,
    /// Number of triangles.
    triangles: usize,
    /// Per-corner shading normals in file order (empty for flat shading).
    normals: Vec<[Vec3; 3]>,
    /// Per-corner texture coordinates in file order (empty when the file has none).
    uvs: Vec<[Vec2; 3]>,
    /// Per-corner vertex colours in file order (empty when the file has none: a mesh
    /// without them takes no memory for them).
    colors: Vec<[Vec3; 3]>,
    /// Per-triangle material slot in file order (`u32::MAX`: none); empty when no face has one.
    material_of: Vec<u32>,
    /// The tree, its leaves in blocks ([`Bvh::into_blocks`]); `order` maps a slot to its
    /// triangle's index in the file.
    bvh: Bvh,
    bounds: Aabb,
    /// How far before the bounds a ray restarts (a thousandth of the diagonal).
    margin: f64,
    /// Hits closer than this to a ray's start are ignored: the f32 triangle test's error bound
    /// (a few ulps of the mesh's coordinates), so a ray leaving the surface cannot hit it again.
    self_hit: f64,
}

/// A hit on a mesh in its own space.
#[derive(Clone, Copy, Debug)]
pub struct MeshHit {
    /// Ray parameter.
    pub t: f64,
    /// Unit geometric normal (winding order).
    pub geometric: DVec3,
    /// Unit shading normal.
    pub shading: DVec3,
    /// Texture coordinates.
    pub(crate) uv: DVec2,
    /// The face's material slot (an index into the file's MTL materials), if it has one.
    pub(crate) material: Option<u32>,
    /// The vertex colours interpolated at the hit (the same barycentrics as the normal), if
    /// the mesh has them.
    pub(crate) color: Option<Vec3>,
    /// Per-axis bound on how far the object-space hit point lies off the triangle's plane.
    pub(crate) error: DVec3,
}

impl Mesh {
    /// Builds the BVH over `parts` and stores the triangles in its order.
    pub fn build(parts: MeshParts<'_>) -> Mesh {
        Self::build_with(parts, crate::geometry::mesh::bvh::build)
    }

    /// [`Mesh::build`] with the tree made by `tree(parts, pad)` (its ids index
    /// `parts.triangles`; `pad` widens each triangle's box): tests choose the clustered or the
    /// per-triangle build regardless of the mesh's size.
    fn build_with(parts: MeshParts<'_>, tree: impl FnOnce(&MeshParts<'_>, Vec3A) -> Bvh) -> Mesh {
        let corners = |t: &[u32; 3]| t.map(|i| parts.vertices[i as usize]);
        // Minima and maxima are exact, so the parallel fold's grouping cannot change them.
        let bounds = parts
            .triangles
            .par_iter()
            .fold(
                || Aabb::EMPTY,
                |b, t| {
                    corners(t).iter().fold(b, |b, p| {
                        let p = p.as_dvec3();
                        b.union(Aabb::new(p, p))
                    })
                },
            )
            .reduce(|| Aabb::EMPTY, Aabb::union);
        // Rays are traversed in f32 from near the mesh; pad every box by a few ulps of the
        // mesh's coordinates so rounding in the slab test cannot cull a triangle the exact
        // ray touches (a ray through a vertex at the corner of every adjacent box).
        let reach =
            bounds.min.abs().max(bounds.max.abs()).max_element() + (bounds.max - bounds.min).norm();
        let pad = Vec3A::splat((4.0 * f32::EPSILON as f64 * reach) as f32);
        let bvh = tree(&parts, pad).into_blocks();
        // Corners in BVH slot order, so a leaf's triangles sit side by side.
        let blocks = bvh
            .order
            .par_chunks(BLOCK)
            .map(|ids| {
                let mut block = TriBlock::EMPTY;
                for (lane, &i) in ids.iter().enumerate() {
                    if let Some(t) = parts.triangles.get(i as usize) {
                        block.set(lane, corners(t));
                    }
                }
                block
            })
            .collect();
        Mesh {
            blocks,
            triangles: parts.triangles.len(),
            normals: parts.normals.to_vec(),
            uvs: parts.uvs.to_vec(),
            colors: parts.colors.to_vec(),
            material_of: parts.material_of.to_vec(),
            bvh,
            bounds,
            margin: 1e-3 * (bounds.max - bounds.min).norm(),
            self_hit: 16.0 * f32::EPSILON as f64 * reach,
        }
    }

    /// Whether the triangles carry vertex colours.
    pub(crate) fn has_colors(&self) -> bool {
        !self.colors.is_empty()
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.triangles
    }

    /// Object-space bounds.
    pub fn bounds(&self) -> Aabb {
        self.bounds
    }

    /// BVH build time.
    pub(crate) fn build_time(&self) -> std::time::Duration {
        self.bvh.build_time
    }

    /// Approximate heap bytes.
    pub fn memory(&self) -> usize {
        self.blocks.len() * std::mem::size_of::<TriBlock>()
            + self.normals.len() * std::mem::size_of::<[Vec3; 3]>()
            + self.uvs.len() * std::mem::size_of::<[Vec2; 3]>()
            + self.colors.len() * std::mem::size_of::<[Vec3; 3]>()
            + self.material_of.len() * 4
            + self.bvh.memory()
    }

    /// The corners of the triangle in `slot`.
    #[inline]
    fn corners(&self, slot: usize) -> [Vec3A; 3] {
        self.blocks[slot / BLOCK].corners(slot % BLOCK)
    }

    fn hit(&self, slot: usize, t: f32, b: [f32; 3]) -> MeshHit {
        let tri = self.corners(slot);
        // The triangle's index in the file, for its attributes.
        let file = self.bvh.order[slot] as usize;
        let geometric = (tri[1] - tri[0])
            .cross(tri[2] - tri[0])
            .as_dvec3()
            .unit_or(DVec3::Y);
        let shading = match self.normals.get(file) {
            Some(n) => (n[0] * b[0] + n[1] * b[1] + n[2] * b[2])
                .as_dvec3()
                .try_unit()
                .unwrap_or(geometric),
            None => geometric,
        };
        let uv = match self.uvs.get(file) {
            Some(u) => (u[0] * b[0] + u[1] * b[1] + u[2] * b[2]).as_dvec2(),
            None => DVec2::new(b[1] as f64, b[2] as f64),
        };
        let color = self
            .colors
            .get(file)
            .map(|c| c[0] * b[0] + c[1] * b[1] + c[2] * b[2]);
        MeshHit {
            t: t as f64,
            geometric,
            shading,
            uv,
            material: self
                .material_of
                .get(file)
                .copied()
                .filter(|&m| m != u32::MAX),
            color,
            error: DVec3::ZERO,
        }
    }

    /// Error bound of the computed point `p` on the triangle in `slot`: its residual off the
    /// triangle's plane, evaluated in f64 from the stored corners.
    fn point_error(&self, slot: usize, p: DVec3) -> DVec3 {
        let [a, b, c] = self.corners(slot).map(|v| v.as_dvec3());
        let n = (b - a).cross(c - a).unit_or(DVec3::Y);
        crate::geometry::shapes::plane::point_error(a, n, p)
    }

    /// Where `ray` meets the plane of triangle `slot`, in f64 (`fallback` when parallel), and
    /// that point's error bound ([`Mesh::point_error`]'s), from one read of the corners.
    fn on_plane(&self, slot: usize, ray: &Ray, fallback: f64) -> (f64, DVec3) {
        let [a, b, c] = self.corners(slot).map(|v| v.as_dvec3());
        let n = (b - a).cross(c - a);
        let t = n.dot(a - ray.origin) / n.dot(ray.dir);
        let t = if t.is_finite() { t } else { fallback };
        let error = crate::geometry::shapes::plane::point_error(a, n.unit_or(DVec3::Y), ray.at(t));
        (t, error)
    }

    /// The ray restarted near the mesh: f32 traversal then only rounds coordinates of the
    /// mesh's own size. Returns the shift `s` (t = s + t'), the shifted ray and the f32 range.
    #[inline(always)]
    fn near(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(f64, ShearedRay, BvhRay, f32)> {
        self.near_with(ray, ray.dir.recip(), t_min, t_max)
    }

    /// [`Mesh::near`] given `inv = ray.dir.recip()`.
    #[inline(always)]
    fn near_with(
        &self,
        ray: &Ray,
        inv: DVec3,
        t_min: f64,
        t_max: f64,
    ) -> Option<(f64, ShearedRay, BvhRay, f32)> {
        // Slab test against the mesh bounds, keeping the reciprocal for the f32 ray.
        let t0 = (self.bounds.min - ray.origin) * inv;
        let t1 = (self.bounds.max - ray.origin) * inv;
        let entry = t0.min(t1).max_element().max(t_min);
        let exit = t0.max(t1).min_element().min(t_max);
        if entry > exit {
            return None;
        }
        // The margin in units of t; it need not be exact, so f32 keeps the division short.
        let len = (ray.dir.length_squared() as f32)
            .sqrt()
            .max(f32::MIN_POSITIVE);
        let per_t = (1.0 / len) as f64;
        let margin = self.margin * per_t;
        let s = (entry - margin).max(t_min);
        let origin = ray.at(s);
        let sr = ShearedRay::with_inverse(origin, ray.dir, inv)?;
        let far = (t_max.min(exit + margin) - s).max(0.0);
        let r = BvhRay::with_inverse(origin, ray.dir, inv, 0.0, far)?;
        // Past t_min by the self-hit distance (t_min is where a secondary ray leaves a surface).
        let lo = t_min - s + self.self_hit * per_t;
        Some((s, sr, r, lo as f32))
    }

    /// Nearest hit in (t_min, t_max).
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<MeshHit> {
        let (s, sr, r, lo) = self.near(ray, t_min, t_max)?;
        let mut best: Option<(usize, f32, [f32; 3])> = None;
        // Each leaf's triangles in slot order, each against the nearest hit so far, as a
        // triangle-by-triangle loop would test them (the first of equally near hits wins).
        self.bvh.closest_leaves(&r, |first, count, mut t_far| {
            for (slot, e) in self.leaf(&sr, first, count) {
                let mut mask = e.mask;
                while mask != 0 {
                    let lane = mask.trailing_zeros() as usize;
                    mask &= mask - 1;
                    let (t, b) = e.hit(lane);
                    if t > lo && t < t_far {
                        best = Some((slot + lane, t, b));
                        t_far = t;
                    }
                }
            }
            t_far
        });
        let (slot, t, b) = best?;
        self.finish(ray, t_min, t_max, s, slot, t, b)
    }

    /// The hit of the ray restarted at `s` on the triangle in `slot` at `t` (relative to `s`)
    /// with barycentrics `b`, if it lies in (t_min, t_max).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn finish(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        s: f64,
        slot: usize,
        t: f32,
        b: [f32; 3],
    ) -> Option<MeshHit> {
        let mut h = self.hit(slot, t, b);
        h.t += s;
        h.error = self.point_error(slot, ray.at(h.t));
        (h.t > t_min && h.t < t_max).then_some(h)
    }

    /// [`Mesh::intersect`] of up to [`PACKET`] rays at once: `hit(i, h)` for each ray `i` that
    /// has a hit, `h` bit for bit `intersect(&rays[i], t_min[i], t_max[i])`.
    ///
    /// The rays' set-ups run one after the other (their divisions and square roots overlap)
    /// and the rays then walk the tree as a packet. Each finds the nearest `t` it would find
    /// alone; only which of two triangles at exactly that `t` wins depends on the visiting
    /// order, so a ray that met such a tie is traced again alone.
    pub(crate) fn intersect_packet(
        &self,
        rays: &[Ray],
        t_min: &[f64],
        t_max: &[f64],
        mut hit: impl FnMut(usize, MeshHit),
    ) {
        assert!(rays.len() <= PACKET, "a packet holds at most {PACKET} rays");
        let n = rays.len();
        let mut shift = [0.0; PACKET];
        let mut sheared = [ShearedRay::default(); PACKET];
        let mut bvh_rays = [BvhRay::default(); PACKET];
        let mut lo = [0.0; PACKET];
        let mut far = [0.0; PACKET];
        let mut active = 0u32;
        let inv = recips(rays);
        for i in 0..n {
            if let Some((s, sr, r, l)) = self.near_with(&rays[i], inv[i], t_min[i], t_max[i]) {
                (shift[i], sheared[i], lo[i], far[i]) = (s, sr, l, r.t_max);
                bvh_rays[i] = r;
                active |= 1 << i;
            }
        }
        let mut best: [Option<(usize, f32, [f32; 3])>; PACKET] = [None; PACKET];
        // The last `t` at which a ray met a second triangle as near as its nearest so far.
        let mut tie = [f32::NAN; PACKET];
        self.bvh.closest_leaves_packet(
            &bvh_rays[..n],
            active,
            &mut far,
            |r, first, count, mut t_far| {
                for (slot, e) in self.leaf(&sheared[r], first, count) {
                    let mut mask = e.mask;
                    while mask != 0 {
                        let lane = mask.trailing_zeros() as usize;
                        mask &= mask - 1;
                        let (t, b) = e.hit(lane);
                        if t > lo[r] && t < t_far {
                            best[r] = Some((slot + lane, t, b));
                            t_far = t;
                        } else if t == t_far && best[r].is_some() {
                            tie[r] = t;
                        }
                    }
                }
                t_far
            },
        );
        for i in 0..n {
            let h = match best[i] {
                Some((_, t, _)) if tie[i] == t => self.intersect(&rays[i], t_min[i], t_max[i]),
                Some((slot, t, b)) => {
                    self.finish(&rays[i], t_min[i], t_max[i], shift[i], slot, t, b)
                }
                None => None,
            };
            if let Some(h) = h {
                hit(i, h);
            }
        }
    }

    /// [`Mesh::occluded`] of the rays of `active` (bits, up to [`PACKET`] rays) at once: the
    /// rays it holds for, as a mask.
    pub(crate) fn occluded_packet(
        &self,
        rays: &[Ray],
        t_min: &[f64],
        t_max: &[f64],
        active: u32,
    ) -> u32 {
        assert!(rays.len() <= PACKET, "a packet holds at most {PACKET} rays");
        let n = rays.len();
        let mut sheared = [ShearedRay::default(); PACKET];
        let mut bvh_rays = [BvhRay::default(); PACKET];
        let (mut lo, mut hi) = ([0.0; PACKET], [0.0; PACKET]);
        let mut traced = 0u32;
        let inv = recips(rays);
        for i in (0..n).filter(|i| active >> i & 1 == 1) {
            if let Some((s, sr, r, l)) = self.near_with(&rays[i], inv[i], t_min[i], t_max[i]) {
                (sheared[i], bvh_rays[i], lo[i]) = (sr, r, l);
                hi[i] = (t_max[i] - s) as f32;
                traced |= 1 << i;
            }
        }
        self.bvh
            .any_leaves_packet(&bvh_rays[..n], traced, |r, first, count| {
                self.leaf(&sheared[r], first, count).any(|(_, e)| {
                    let mut mask = e.mask;
                    while mask != 0 {
                        let lane = mask.trailing_zeros() as usize;
                        mask &= mask - 1;
                        let (t, _) = e.hit(lane);
                        if t > lo[r] && t < hi[r] {
                            return true;
                        }
                    }
                    false
                })
            })
    }

    /// True when some triangle lies in (t_min, t_max) (stops at the first).
    pub fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let Some((s, sr, r, lo)) = self.near(ray, t_min, t_max) else {
            return false;
        };
        let hi = (t_max - s) as f32;
        self.bvh.any_leaves(&r, |first, count| {
            self.leaf(&sr, first, count).any(|(_, e)| {
                let mut mask = e.mask;
                while mask != 0 {
                    let lane = mask.trailing_zeros() as usize;
                    mask &= mask - 1;
                    let (t, _) = e.hit(lane);
                    if t > lo && t < hi {
                        return true;
                    }
                }
                false
            })
        })
    }

    /// The 4-wide tests of a leaf (`count` triangles from block `first`): per block, its first
    /// slot and the edge functions of its used lanes.
    #[inline(always)]
    fn leaf<'a>(
        &'a self,
        sr: &'a ShearedRay,
        first: usize,
        count: usize,
    ) -> impl Iterator<Item = (usize, crate::geometry::shapes::triangle::Edges4)> + 'a {
        let blocks = &self.blocks[first..first + count.div_ceil(BLOCK)];
        blocks.iter().enumerate().map(move |(k, block)| {
            let lanes = (count - k * BLOCK).min(BLOCK);
            ((first + k) * BLOCK, sr.intersect4(block, lanes))
        })
    }

    /// Every hit along the whole line, sorted by `t`, with `entering` from the winding.
    pub fn all_hits(&self, ray: &Ray, out: &mut Vec<(MeshHit, bool)>) {
        let Some((s, sr, r, _)) = self.near(ray, f64::NEG_INFINITY, f64::INFINITY) else {
            return;
        };
        let start = out.len();
        self.bvh.any_leaves(&r, |first, count| {
            for (slot, e) in self.leaf(&sr, first, count) {
                for lane in (0..BLOCK).filter(|l| e.mask >> l & 1 == 1) {
                    let (t, b) = e.hit(lane);
                    let mut h = self.hit(slot + lane, t, b);
                    // The f32 test's t, shifted back, is off by rounding of the shift's size:
                    // more than the error bound the CSG walk and a secondary ray's offset
                    // rely on (a shadow ray found its own face again). The plane's t in f64
                    // is as exact as an analytic shape's.
                    (h.t, h.error) = self.on_plane(slot + lane, ray, h.t + s);
                    out.push((h, h.geometric.dot(ray.dir) < 0.0));
                }
            }
            false
        });
        out[start..].sort_by(|a, b| a.0.t.total_cmp(&b.0.t));
    }
}

/// `dir.recip()` of each ray of a packet, the divisions side by side in lanes (one by one,
/// each ray's set-up waited on its three).
#[inline(always)]
fn recips(rays: &[Ray]) -> [DVec3; PACKET] {
    let packet = RayLanes::of(rays);
    let d = &packet.dir;
    let inv = V3 {
        x: lanes::map(|i| 1.0 / d.x[i]),
        y: lanes::map(|i| 1.0 / d.y[i]),
        z: lanes::map(|i| 1.0 / d.z[i]),
    };
    std::array::from_fn(|i| inv.get(i))
}

// A mesh packet fits the lanes.
const _: () = assert!(PACKET == lanes::WIDTH);

#[cfg(test)]
mod tests;
