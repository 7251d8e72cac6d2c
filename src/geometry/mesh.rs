//! Triangle meshes from OBJ files (tobj): triangulated, normals from the file or computed
//! (smooth with a crease angle), texture coordinates, MTL materials, one BVH per mesh.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use glam::{DVec2, DVec3, Vec2, Vec3, Vec3A};
use obvhs::BvhBuildParams;

use super::bvh::{Bvh, BvhRay};
use super::mesh_error::{MeshError, locate};
use super::triangle::ShearedRay;
use super::{Aabb, Ray};
use crate::ir::Material;

/// Faces meeting at less than this angle share smoothed normals; sharper edges stay creased.
pub const CREASE_ANGLE_DEG: f64 = 60.0;

/// Above this many triangles a mesh's BVH is built for speed rather than quality (obvhs's
/// `very_fast_build`: 0.35 s instead of 0.44 s for 1.1M triangles on 2 cores, about the same
/// tracing speed), because there the build dominates the time to first ray.
pub const LARGE_MESH: usize = 300_000;

use crate::ir::limits::MAX_TRIANGLES;
const _: () = assert!(MAX_TRIANGLES <= super::bvh::MAX_PRIMITIVES);

/// Most triangles in one BVH leaf.
const LEAF_TRIANGLES: u32 = 4;

/// A loaded mesh, shared (`Arc`) by every object that places the same file.
#[derive(Debug)]
pub struct MeshData {
    /// The file it came from.
    pub path: PathBuf,
    /// Triangles in BVH order.
    tris: Vec<[Vec3A; 3]>,
    /// Per-corner shading normals (empty for flat shading).
    normals: Vec<[Vec3; 3]>,
    /// Per-corner texture coordinates (empty when the file has none).
    uvs: Vec<[Vec2; 3]>,
    /// Per-triangle index into `materials` (`u32::MAX`: none); empty when no face has one.
    material_of: Vec<u32>,
    /// The file's MTL materials converted to rtc materials.
    pub materials: Vec<Material>,
    /// Warnings met while loading (a missing `.mtl`).
    pub warnings: Vec<String>,
    bvh: Bvh,
    bounds: Aabb,
    /// How far before the bounds a ray restarts (a thousandth of the diagonal).
    margin: f64,
    /// Hits closer than this to a ray's start are ignored: the f32 triangle test's error bound
    /// (a few ulps of the mesh's coordinates), so a ray leaving the surface cannot hit it again.
    self_hit: f64,
    closed: OnceLock<bool>,
    /// Time `load` took, BVH included.
    load_time: std::time::Duration,
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
    pub uv: DVec2,
    /// Index into [`MeshData::materials`], if the face has one.
    pub material: Option<u32>,
}

impl MeshData {
    /// Loads and prepares an OBJ file; `smooth` interpolates normals.
    pub fn load(path: &Path, smooth: bool) -> Result<MeshData, MeshError> {
        let start = std::time::Instant::now();
        // Separate index streams: `single_index` re-deduplicates every (position, uv, normal)
        // tuple through a hash map, the largest cost of loading a million triangles.
        let opts = tobj::LoadOptions {
            triangulate: true,
            single_index: false,
            ..Default::default()
        };
        let (models, mtl) = tobj::load_obj(path, &opts).map_err(|e| locate(path, e))?;
        let mut warnings = Vec::new();
        let materials = match mtl {
            Ok(m) => m.iter().map(convert_material).collect(),
            Err(e) => {
                warnings.push(format!("its material library could not be read ({e})"));
                Vec::new()
            }
        };
        let mut tris: Vec<[Vec3A; 3]> = Vec::new();
        let mut file_normals: Vec<Option<[Vec3; 3]>> = Vec::new();
        let mut uvs: Vec<[Vec2; 3]> = Vec::new();
        let mut material_of: Vec<u32> = Vec::new();
        let mut any_uv = false;
        let mut any_mat = false;
        for m in &models {
            let m = &m.mesh;
            let pos = |i: u32| -> Option<Vec3A> {
                let i = i as usize * 3;
                Some(Vec3A::new(
                    *m.positions.get(i)?,
                    *m.positions.get(i + 1)?,
                    *m.positions.get(i + 2)?,
                ))
            };
            let nrm = |i: u32| -> Option<Vec3> {
                let i = i as usize * 3;
                Some(Vec3::new(
                    *m.normals.get(i)?,
                    *m.normals.get(i + 1)?,
                    *m.normals.get(i + 2)?,
                ))
            };
            let tex = |i: u32| -> Option<Vec2> {
                let i = i as usize * 2;
                Some(Vec2::new(*m.texcoords.get(i)?, *m.texcoords.get(i + 1)?))
            };
            let mat = m
                .material_id
                .filter(|&i| i < materials.len())
                .map_or(u32::MAX, |i| i as u32);
            any_mat |= mat != u32::MAX;
            // Attribute indices per corner: their own stream, or the position's.
            let pick = |own: &'_ [u32], values: usize, per: usize| -> Option<Vec<u32>> {
                if own.len() == m.indices.len() {
                    Some(own.to_vec())
                } else if values > 0 && values / per == m.positions.len() / 3 {
                    Some(m.indices.clone())
                } else {
                    None
                }
            };
            // Only what will be used: file normals for smooth shading, uvs when present.
            let n_idx = if smooth {
                pick(&m.normal_indices, m.normals.len(), 3)
            } else {
                None
            };
            let t_idx = pick(&m.texcoord_indices, m.texcoords.len(), 2);
            for (k, f) in m.indices.chunks_exact(3).enumerate() {
                let corner = |idx: &Option<Vec<u32>>, c: usize| {
                    idx.as_ref().and_then(|v| v.get(3 * k + c).copied())
                };
                let (Some(a), Some(b), Some(c)) = (pos(f[0]), pos(f[1]), pos(f[2])) else {
                    return Err(MeshError::new("a face refers to a missing vertex", None));
                };
                if !(a.is_finite() && b.is_finite() && c.is_finite()) {
                    return Err(MeshError::new("a vertex coordinate is not finite", None));
                }
                // Faces without area can never be hit; dropping them keeps normals clean.
                if (b - a).cross(c - a) == Vec3A::ZERO {
                    continue;
                }
                tris.push([a, b, c]);
                if smooth {
                    let n = |c| corner(&n_idx, c).and_then(nrm);
                    file_normals.push(match (n(0), n(1), n(2)) {
                        (Some(x), Some(y), Some(z)) => Some([x, y, z]),
                        _ => None,
                    });
                }
                if t_idx.is_some() || any_uv {
                    let tc = |c| corner(&t_idx, c).and_then(tex);
                    let t = [tc(0), tc(1), tc(2)];
                    if !any_uv && t.iter().all(Option::is_some) {
                        // Earlier faces (in other groups) had none: pad them.
                        uvs.resize(tris.len() - 1, [Vec2::ZERO; 3]);
                        any_uv = true;
                    }
                    if any_uv {
                        uvs.push(t.map(|x| x.unwrap_or(Vec2::ZERO)));
                    }
                }
                if any_mat {
                    if material_of.len() + 1 < tris.len() {
                        material_of.resize(tris.len() - 1, u32::MAX);
                    }
                    material_of.push(mat);
                }
            }
        }
        if any_uv {
            uvs.resize(tris.len(), [Vec2::ZERO; 3]);
        }
        if any_mat {
            material_of.resize(tris.len(), u32::MAX);
        }
        if tris.is_empty() {
            return Err(MeshError::new("the file has no faces with area", None));
        }
        within_budget(tris.len(), MAX_TRIANGLES)?;
        let usable = |n: &Option<[Vec3; 3]>| {
            n.is_some_and(|n| n.iter().all(|v| v.is_finite() && *v != Vec3::ZERO))
        };
        let normals = if smooth {
            if file_normals.iter().all(usable) {
                file_normals.into_iter().flatten().collect()
            } else {
                let computed = smooth_normals(&tris);
                file_normals
                    .iter()
                    .zip(computed)
                    .map(|(f, c)| if usable(f) { f.unwrap_or(c) } else { c })
                    .collect()
            }
        } else {
            Vec::new()
        };
        let bounds = tris.iter().flatten().fold(Aabb::EMPTY, |b, p| {
            let p = p.as_dvec3();
            b.union(Aabb::new(p, p))
        });
        // Rays are traversed in f32 from near the mesh; pad every box by a few ulps of the
        // mesh's coordinates so rounding in the slab test cannot cull a triangle the exact
        // ray touches (a ray through a vertex at the corner of every adjacent box).
        let reach = bounds.min.abs().max(bounds.max.abs()).max_element()
            + (bounds.max - bounds.min).length();
        let pad = Vec3A::splat((4.0 * f32::EPSILON as f64 * reach) as f32);
        let boxes: Vec<_> = tris
            .iter()
            .map(|t| {
                let b = obvhs::aabb::Aabb::from_points(t);
                obvhs::aabb::Aabb::new(b.min - pad, b.max + pad)
            })
            .collect();
        let bvh = Bvh::build(
            &boxes,
            (0..tris.len() as u32).collect(),
            // Better trees pay off until the build itself dominates (time to first ray).
            BvhBuildParams {
                max_prims_per_leaf: LEAF_TRIANGLES,
                ..if tris.len() <= LARGE_MESH {
                    BvhBuildParams::medium_build()
                } else {
                    BvhBuildParams::very_fast_build()
                }
            },
        );
        // Per-triangle data in BVH slot order, so a leaf's triangles sit side by side.
        let tris2 = in_order(&tris, &bvh.order);
        let normals = in_order(&normals, &bvh.order);
        let uvs = in_order(&uvs, &bvh.order);
        let material_of = in_order(&material_of, &bvh.order);
        Ok(MeshData {
            path: path.to_path_buf(),
            tris: tris2,
            normals,
            uvs,
            material_of,
            materials,
            warnings,
            bvh,
            bounds,
            margin: 1e-3 * (bounds.max - bounds.min).length(),
            self_hit: 16.0 * f32::EPSILON as f64 * reach,
            closed: OnceLock::new(),
            load_time: start.elapsed(),
        })
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.tris.len()
    }

    /// Object-space bounds.
    pub fn bounds(&self) -> Aabb {
        self.bounds
    }

    /// BVH build time.
    pub fn build_time(&self) -> std::time::Duration {
        self.bvh.build_time
    }

    /// Time loading took: reading, normals and the BVH.
    pub fn load_time(&self) -> std::time::Duration {
        self.load_time
    }

    /// Approximate heap bytes.
    pub fn memory(&self) -> usize {
        self.tris.len() * std::mem::size_of::<[Vec3A; 3]>()
            + self.normals.len() * std::mem::size_of::<[Vec3; 3]>()
            + self.uvs.len() * std::mem::size_of::<[Vec2; 3]>()
            + self.material_of.len() * 4
            + self.bvh.memory()
    }

    /// True when every edge is shared by exactly two faces with opposite orientation (a
    /// closed, consistently oriented surface: a solid CSG can use).
    pub fn is_closed(&self) -> bool {
        *self.closed.get_or_init(|| {
            let mut ids: HashMap<[u32; 3], u32> = HashMap::new();
            let mut id = |p: Vec3A| {
                let n = ids.len() as u32;
                *ids.entry([p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
                    .or_insert(n)
            };
            let mut edges: HashMap<(u32, u32), i32> = HashMap::new();
            for t in &self.tris {
                let v = [id(t[0]), id(t[1]), id(t[2])];
                for k in 0..3 {
                    let (a, b) = (v[k], v[(k + 1) % 3]);
                    let e = edges.entry((a.min(b), a.max(b))).or_insert(0);
                    *e += if a < b { 1 } else { 1 << 16 };
                }
            }
            edges.values().all(|&c| c == 1 + (1 << 16))
        })
    }

    fn hit(&self, slot: usize, t: f32, b: [f32; 3]) -> MeshHit {
        let tri = &self.tris[slot];
        let geometric = (tri[1] - tri[0])
            .cross(tri[2] - tri[0])
            .as_dvec3()
            .normalize_or(DVec3::Y);
        let shading = match self.normals.get(slot) {
            Some(n) => (n[0] * b[0] + n[1] * b[1] + n[2] * b[2])
                .as_dvec3()
                .try_normalize()
                .unwrap_or(geometric),
            None => geometric,
        };
        let uv = match self.uvs.get(slot) {
            Some(u) => (u[0] * b[0] + u[1] * b[1] + u[2] * b[2]).as_dvec2(),
            None => DVec2::new(b[1] as f64, b[2] as f64),
        };
        MeshHit {
            t: t as f64,
            geometric,
            shading,
            uv,
            material: self
                .material_of
                .get(slot)
                .copied()
                .filter(|&m| m != u32::MAX),
        }
    }

    /// The ray restarted near the mesh: f32 traversal then only rounds coordinates of the
    /// mesh's own size. Returns the shift `s` (t = s + t'), the shifted ray and the f32 range.
    fn near(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<(f64, ShearedRay, BvhRay, f32)> {
        // Slab test against the mesh bounds, keeping the reciprocal for the f32 ray.
        let inv = ray.dir.recip();
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
        self.bvh
            .closest(&r, |slot, t_far| match sr.intersect(&self.tris[slot]) {
                Some((t, b)) if t > lo && t < t_far => {
                    best = Some((slot, t, b));
                    t
                }
                _ => f32::INFINITY,
            });
        let (slot, t, b) = best?;
        let mut h = self.hit(slot, t, b);
        h.t += s;
        (h.t > t_min && h.t < t_max).then_some(h)
    }

    /// True when some triangle lies in (t_min, t_max) (stops at the first).
    pub fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let Some((s, sr, r, lo)) = self.near(ray, t_min, t_max) else {
            return false;
        };
        let hi = (t_max - s) as f32;
        self.bvh.any(&r, |slot| {
            sr.intersect(&self.tris[slot])
                .is_some_and(|(t, _)| t > lo && t < hi)
        })
    }

    /// Every hit along the whole line, sorted by `t`, with `entering` from the winding.
    pub fn all_hits(&self, ray: &Ray, out: &mut Vec<(MeshHit, bool)>) {
        let Some((s, sr, r, _)) = self.near(ray, f64::NEG_INFINITY, f64::INFINITY) else {
            return;
        };
        let start = out.len();
        self.bvh.all(&r, |slot| {
            if let Some((t, b)) = sr.intersect(&self.tris[slot]) {
                let mut h = self.hit(slot, t, b);
                h.t += s;
                out.push((h, h.geometric.dot(ray.dir) < 0.0));
            }
        });
        out[start..].sort_by(|a, b| a.0.t.total_cmp(&b.0.t));
    }
}

/// Rejects a mesh of `count` triangles when it is over `max` (untrusted files have a budget).
fn within_budget(count: usize, max: usize) -> Result<(), MeshError> {
    if count <= max {
        return Ok(());
    }
    Err(MeshError {
        too_large: true,
        ..MeshError::new(
            format!("it has {count} triangles; at most {max} are supported in one file"),
            None,
        )
    })
}

/// `values` permuted into `order` (BVH slot → original index); empty stays empty (an attribute
/// the file does not have).
fn in_order<T: Copy>(values: &[T], order: &[u32]) -> Vec<T> {
    if values.is_empty() {
        return Vec::new();
    }
    order.iter().map(|&i| values[i as usize]).collect()
}

/// Converts an MTL material (Kd colour, Ka/Ks scaled to rtc's scalar coefficients, Ns, d, Ni).
fn convert_material(m: &tobj::Material) -> Material {
    let v = |c: [f32; 3]| DVec3::new(c[0] as f64, c[1] as f64, c[2] as f64);
    let mut out = Material::default();
    if let Some(kd) = m.diffuse {
        out.color = v(kd);
        out.kd = 1.0;
    }
    if let Some(ka) = m.ambient {
        let ka = v(ka).max_element();
        out.ka = ka;
    }
    if let Some(ks) = m.specular {
        out.ks = v(ks).max_element();
    }
    if let Some(ns) = m.shininess {
        out.n = (ns as f64).max(1.0);
    }
    if let Some(d) = m.dissolve
        && d < 1.0
    {
        out.refract = (1.0 - d as f64).clamp(0.0, 1.0);
    }
    if let Some(ni) = m.optical_density {
        out.eta = (ni as f64).max(1.0);
    }
    out
}

/// Area-weighted vertex normals over positions welded by value, averaging only faces within
/// [`CREASE_ANGLE_DEG`] of the face being shaded (so hard edges stay hard).
fn smooth_normals(tris: &[[Vec3A; 3]]) -> Vec<[Vec3; 3]> {
    let mut ids: HashMap<[u32; 3], u32> = HashMap::with_capacity(tris.len() / 2 + 1);
    let mut corner = Vec::with_capacity(tris.len() * 3);
    for t in tris {
        for p in t {
            let n = ids.len() as u32;
            corner.push(
                *ids.entry([p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
                    .or_insert(n),
            );
        }
    }
    let nv = ids.len();
    // Faces around each vertex (CSR).
    let mut start = vec![0u32; nv + 1];
    for &v in &corner {
        start[v as usize + 1] += 1;
    }
    for i in 0..nv {
        start[i + 1] += start[i];
    }
    let mut fill = start.clone();
    let mut faces = vec![0u32; corner.len()];
    for (c, &v) in corner.iter().enumerate() {
        faces[fill[v as usize] as usize] = (c / 3) as u32;
        fill[v as usize] += 1;
    }
    let area: Vec<Vec3A> = tris
        .iter()
        .map(|t| (t[1] - t[0]).cross(t[2] - t[0]))
        .collect();
    let unit: Vec<Vec3A> = area.iter().map(|a| a.normalize_or_zero()).collect();
    let cos = CREASE_ANGLE_DEG.to_radians().cos() as f32;
    (0..tris.len())
        .map(|f| {
            let mut out = [Vec3::ZERO; 3];
            for k in 0..3 {
                let v = corner[3 * f + k] as usize;
                let mut sum = Vec3A::ZERO;
                for &g in &faces[start[v] as usize..start[v + 1] as usize] {
                    if unit[g as usize].dot(unit[f]) >= cos {
                        sum += area[g as usize];
                    }
                }
                out[k] = Vec3::from(sum.normalize_or(unit[f]));
            }
            out
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The triangle budget lets the limit through and rejects one more, flagged as too large.
    #[test]
    fn the_triangle_budget_is_enforced() {
        assert!(within_budget(MAX_TRIANGLES, MAX_TRIANGLES).is_ok());
        let e = within_budget(11, 10).unwrap_err();
        assert!(e.too_large && !e.missing, "{e:?}");
        assert!(e.message.contains("11 triangles") && e.message.contains("at most 10"));
    }
}
