//! Triangle meshes from OBJ files (tobj): triangulated, faces without area dropped, normals from
//! the file or computed (smooth with a crease angle), texture coordinates, MTL materials. The
//! result is plain data in file order; geometry builds its BVH from it.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::time::Duration;

use glam::{DVec3, Vec2, Vec3, Vec3A};

use super::obj_error::{MeshError, locate};
use crate::ir::Material;
use crate::ir::limits::{MAX_MESH_FILE_BYTES, MAX_TRIANGLES};

/// Faces meeting at less than this angle share smoothed normals; sharper edges stay creased.
pub const CREASE_ANGLE_DEG: f64 = 60.0;

/// A loaded OBJ file, shared (`Arc`) through the asset cache.
#[derive(Debug)]
pub struct MeshAsset {
    /// The file it came from.
    pub path: PathBuf,
    /// Triangles in file order (faces with area only).
    pub triangles: Vec<[Vec3A; 3]>,
    /// Per-corner shading normals (empty unless loaded smooth).
    pub normals: Vec<[Vec3; 3]>,
    /// Per-corner texture coordinates (empty when the file has none).
    pub uvs: Vec<[Vec2; 3]>,
    /// Per-triangle index into `materials` (`u32::MAX`: none); empty when no face has one.
    pub material_of: Vec<u32>,
    /// The file's MTL materials converted to rtc materials.
    pub materials: Vec<Material>,
    /// Warnings met while loading (a missing `.mtl`).
    pub warnings: Vec<String>,
    /// Smallest corner of the vertices' bounds (object space).
    pub min: DVec3,
    /// Largest corner of the vertices' bounds.
    pub max: DVec3,
    /// Time `load` took.
    pub load_time: Duration,
    closed: OnceLock<bool>,
}

impl MeshAsset {
    /// Reads an OBJ file (and its MTL library); `smooth` computes per-corner normals.
    pub fn load(path: &Path, smooth: bool) -> Result<MeshAsset, MeshError> {
        let start = std::time::Instant::now();
        // Separate index streams: `single_index` re-deduplicates every (position, uv, normal)
        // tuple through a hash map, the largest cost of loading a million triangles.
        let opts = tobj::LoadOptions {
            triangulate: true,
            single_index: false,
            ..Default::default()
        };
        if let Ok(meta) = std::fs::metadata(path) {
            within_budget(meta.len(), MAX_MESH_FILE_BYTES, "bytes")?;
        }
        let (models, mtl) = super::obj_file::read(path, &opts).map_err(|e| locate(path, e))?;
        let mut warnings = Vec::new();
        let materials = match mtl {
            Ok(m) => m.iter().map(super::mtl::convert).collect(),
            Err(e) => {
                warnings.push(format!("its material library could not be read: {e}"));
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
        within_budget(tris.len() as u64, MAX_TRIANGLES as u64, "triangles")?;
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
        let (min, max) =
            tris.iter()
                .flatten()
                .fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(lo, hi), p| {
                    let p = p.as_dvec3();
                    (lo.min(p), hi.max(p))
                });
        Ok(MeshAsset {
            path: path.to_path_buf(),
            triangles: tris,
            normals,
            uvs,
            material_of,
            materials,
            warnings,
            min,
            max,
            load_time: start.elapsed(),
            closed: OnceLock::new(),
        })
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
            for t in &self.triangles {
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
}

/// Rejects a mesh of `count` triangles when it is over `max` (untrusted files have a budget).
/// `count` of `what` (bytes of the file, triangles) within the budget `max`.
fn within_budget(count: u64, max: u64, what: &str) -> Result<(), MeshError> {
    if count <= max {
        return Ok(());
    }
    Err(MeshError {
        too_large: true,
        ..MeshError::new(
            format!("it has {count} {what}; at most {max} are supported in one file"),
            None,
        )
    })
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
    let cos = libm::cos(CREASE_ANGLE_DEG.to_radians()) as f32;
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
        let max = MAX_TRIANGLES as u64;
        assert!(within_budget(max, max, "triangles").is_ok());
        let e = within_budget(11, 10, "triangles").unwrap_err();
        assert!(e.too_large && !e.missing, "{e:?}");
        assert!(e.message.contains("11 triangles") && e.message.contains("at most 10"));
    }
}
