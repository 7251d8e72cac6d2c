//! Triangle meshes from OBJ files (tobj): triangulated, faces without area dropped, normals from
//! the file or computed (smooth with a crease angle), texture coordinates, MTL materials. The
//! result is plain data in file order; geometry builds its BVH from it.

use crate::num::Norm;
use std::cell::RefCell;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use std::time::Duration;

use glam::{DVec3, Vec2, Vec3, Vec3A};

use rayon::prelude::*;

use super::embedded::ImageSource;
use super::mesh_data::{Faces, within_budget};
use super::obj_error::{MeshError, locate};
use crate::ir::Material;
use crate::ir::limits::{MAX_MESH_FILE_BYTES, MAX_TRIANGLES};

/// Faces meeting at less than this angle share smoothed normals; sharper edges stay creased.
const CREASE_ANGLE_DEG: f64 = 60.0;

/// A loaded OBJ file, shared (`Arc`) through the asset cache.
#[derive(Debug)]
pub struct MeshAsset {
    /// The file it came from.
    pub(crate) path: PathBuf,
    /// Vertex positions the triangles index (unreferenced ones may be among them).
    pub vertices: Vec<Vec3>,
    /// Triangles in file order (faces with area only), as indices into `vertices`.
    pub triangles: Vec<[u32; 3]>,
    /// Per-corner shading normals (empty unless loaded smooth).
    pub normals: Vec<[Vec3; 3]>,
    /// Per-corner texture coordinates (empty when the file has none).
    pub uvs: Vec<[Vec2; 3]>,
    /// Per-triangle index into `materials` (`u32::MAX`: none); empty when no face has one.
    pub material_of: Vec<u32>,
    /// The file's MTL materials converted to rtc materials.
    pub materials: Vec<Material>,
    /// Per material, the image of its base colour, if it names one (`map_Kd`, glTF's
    /// `baseColorTexture`: a file beside the mesh or an image inside a glTF file): the
    /// preparation stage gives the material that image on the mesh's texture coordinates.
    pub images: Vec<Option<ImageSource>>,
    /// Per-corner vertex colours, one per triangle (empty when the file has none): with
    /// `use_mtl` they replace the material's colour (and tint its texture).
    pub colors: Vec<[Vec3; 3]>,
    /// Warnings met while loading (a missing `.mtl`).
    pub warnings: Vec<String>,
    /// The material libraries its `mtllib` lines name, read or not (the cache reloads the mesh
    /// when one of them changes).
    pub(crate) libraries: Vec<PathBuf>,
    /// Smallest corner of the vertices' bounds (object space).
    pub min: DVec3,
    /// Largest corner of the vertices' bounds.
    pub max: DVec3,
    /// Time `load` took.
    pub(crate) load_time: Duration,
    closed: OnceLock<bool>,
}

impl MeshAsset {
    /// Reads a mesh file, its format chosen by its extension: OBJ (and its MTL library), STL
    /// or PLY; `smooth` computes per-corner normals (where the file has none).
    pub fn load(path: &Path, smooth: bool) -> Result<MeshAsset, MeshError> {
        match super::indexed::Format::of(path) {
            super::indexed::Format::Obj => Self::load_by(path, smooth, true),
            format => {
                let start = std::time::Instant::now();
                let faces = super::indexed::read(path, format, smooth)?;
                Self::finish(path, faces, smooth, start)
            }
        }
    }

    /// The mesh a scene writes inline, through the same finish as a file's (faces without
    /// area dropped, smooth normals, bounds); `path` stays empty.
    pub fn inline(mesh: &crate::ir::InlineMesh, smooth: bool) -> Result<MeshAsset, MeshError> {
        let start = std::time::Instant::now();
        let faces = super::indexed::inline(mesh, smooth)?;
        Self::finish(Path::new(""), faces, smooth, start)
    }

    /// [`MeshAsset::load`] through tobj alone (what the parallel reader must agree with).
    pub fn load_general(path: &Path, smooth: bool) -> Result<MeshAsset, MeshError> {
        Self::load_by(path, smooth, false)
    }

    /// Loads with the parallel reader first (when `fast`) and tobj for what it leaves.
    fn load_by(path: &Path, smooth: bool, fast: bool) -> Result<MeshAsset, MeshError> {
        let start = std::time::Instant::now();
        if let Ok(meta) = std::fs::metadata(path) {
            within_budget(meta.len(), MAX_MESH_FILE_BYTES, "bytes")?;
        }
        let read = super::obj_count::read_counted(path, MAX_MESH_FILE_BYTES, MAX_TRIANGLES as u64);
        let text = read.map_err(|e| {
            if e.kind() == std::io::ErrorKind::NotFound {
                locate(path, tobj::LoadError::OpenFileFailed)
            } else {
                // A device, a FIFO or a folder: say so rather than "cannot be read".
                MeshError {
                    message: format!("the file cannot be read: {e}"),
                    ..locate(path, tobj::LoadError::OpenFileFailed)
                }
            }
        })?;
        let text = match text {
            super::obj_count::Counted::Text(text) => text,
            super::obj_count::Counted::TooMany(e) => return Err(e),
        };
        let faces = match fast.then(|| read_fast(path, &text, smooth)).flatten() {
            Some(faces) => faces?,
            None => read_tobj(path, &text, smooth)?,
        };
        drop(text);
        Self::finish(path, faces, smooth, start)
    }

    /// The corners of triangle `i`.
    #[inline]
    pub fn corners(&self, i: usize) -> [Vec3A; 3] {
        self.triangles[i].map(|v| Vec3A::from(self.vertices[v as usize]))
    }

    /// Budget, normals and bounds: the steps after either reader.
    fn finish(
        path: &Path,
        faces: Faces,
        smooth: bool,
        start: std::time::Instant,
    ) -> Result<MeshAsset, MeshError> {
        let Faces {
            vertices,
            triangles,
            file_normals,
            uvs,
            colors,
            material_of,
            materials,
            images,
            warnings,
            libraries,
        } = faces;
        if triangles.is_empty() {
            return Err(MeshError {
                fix: Some(
                    "a mesh needs at least one face of three corners that are not in a line; \
                     check that the file holds the model"
                        .into(),
                ),
                ..MeshError::new("the file has no faces with area", None)
            });
        }
        within_budget(triangles.len() as u64, MAX_TRIANGLES as u64, "triangles")?;
        let usable = |n: &Option<[Vec3; 3]>| {
            n.is_some_and(|n| n.iter().all(|v| v.is_finite() && *v != Vec3::ZERO))
        };
        let normals = if smooth {
            if file_normals.par_iter().all(usable) {
                file_normals.into_iter().flatten().collect()
            } else {
                let computed = smooth_normals(&vertices, &triangles);
                file_normals
                    .iter()
                    .zip(computed)
                    .map(|(f, c)| if usable(f) { f.unwrap_or(c) } else { c })
                    .collect()
            }
        } else {
            Vec::new()
        };
        // Bounds of the vertices the triangles use (a file may hold others), folded in order
        // as always (the sign of a zero bound depends on it).
        let (min, max) = triangles.iter().flatten().fold(
            (DVec3::INFINITY, DVec3::NEG_INFINITY),
            |(lo, hi), &v| {
                let p = vertices[v as usize].as_dvec3();
                (lo.min(p), hi.max(p))
            },
        );
        Ok(MeshAsset {
            path: path.to_path_buf(),
            vertices,
            triangles,
            normals,
            uvs,
            colors,
            material_of,
            materials,
            images,
            warnings,
            libraries,
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
            let ids = weld(&self.vertices);
            let mut edges: HashMap<(u32, u32), i32> = HashMap::new();
            for t in &self.triangles {
                let v = t.map(|i| ids[i as usize]);
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

/// The material libraries' result as the asset keeps it: rtc materials and their `map_Kd`
/// images (resolved beside the OBJ file `path`), or a warning.
fn convert_materials(
    path: &Path,
    mtl: super::obj_file::Materials,
    warnings: &mut Vec<String>,
) -> (Vec<Material>, Vec<Option<ImageSource>>) {
    match mtl {
        Ok(m) => {
            let dir = path.parent().unwrap_or(Path::new(""));
            (
                m.iter().map(super::mtl::convert).collect(),
                m.iter()
                    .map(|m| super::mtl::image(m, dir).map(ImageSource::File))
                    .collect(),
            )
        }
        Err(e) => {
            warnings.push(format!("its material library could not be read: {e}"));
            (Vec::new(), Vec::new())
        }
    }
}

/// The parallel reader's mesh (`None`: the file is outside its subset); tobj's load of the
/// same file gives the same triangles, attributes and materials (tests/obj_fast.rs).
fn read_fast(path: &Path, text: &[u8], smooth: bool) -> Option<Result<Faces, MeshError>> {
    let libs = RefCell::new(super::obj_file::Libraries::new(path));
    let data = super::obj_fast::read(text, &mut |lib| libs.borrow_mut().add(lib), &mut |name| {
        libs.borrow().find(name)
    })?;
    let mut warnings = Vec::new();
    let (materials, images) = convert_materials(path, libs.borrow_mut().merged(), &mut warnings);
    let libraries = libs.borrow().files();
    let super::obj_fast::ObjData {
        positions,
        texcoords,
        normals,
        triangles,
        tex_of,
        normal_of,
        material_of,
        last_material,
    } = data;
    let valid = |m: &Option<usize>| {
        m.filter(|&i| i < materials.len())
            .map_or(u32::MAX, |i| i as u32)
    };
    // tobj's last group (possibly empty) carries the last material: with one, every triangle
    // gets a slot (as from the other reader).
    let any_mat =
        valid(&last_material) != u32::MAX || material_of.par_iter().any(|m| valid(m) != u32::MAX);
    // Faces without area can never be hit; dropping them keeps normals clean.
    let kept: Result<Vec<u32>, ()> = triangles
        .par_iter()
        .enumerate()
        .filter_map(|(k, t)| {
            let [a, b, c] = t.map(|v| Vec3A::from(positions[v as usize]));
            if !(a.is_finite() && b.is_finite() && c.is_finite()) {
                return Some(Err(()));
            }
            ((b - a).cross(c - a) != Vec3A::ZERO).then_some(Ok(k as u32))
        })
        .collect();
    let Ok(kept) = kept else {
        return Some(Err(MeshError::new(
            "a vertex coordinate is not finite",
            None,
        )));
    };
    let uvs = if tex_of.is_empty() {
        Vec::new()
    } else {
        kept.par_iter()
            .map(|&k| tex_of[k as usize].map(|i| texcoords[i as usize]))
            .collect()
    };
    let file_normals = if !smooth {
        Vec::new()
    } else if normal_of.is_empty() {
        vec![None; kept.len()]
    } else {
        kept.par_iter()
            .map(|&k| Some(normal_of[k as usize].map(|i| normals[i as usize])))
            .collect()
    };
    let material_of = if any_mat {
        kept.par_iter()
            .map(|&k| material_of.get(k as usize).map_or(u32::MAX, valid))
            .collect()
    } else {
        Vec::new()
    };
    let triangles = kept.par_iter().map(|&k| triangles[k as usize]).collect();
    Some(Ok(Faces {
        vertices: positions,
        triangles,
        file_normals,
        uvs,
        colors: Vec::new(),
        material_of,
        materials,
        images,
        warnings,
        libraries,
    }))
}

/// tobj's load (the general case, and every diagnostic): its models' vertices end to end.
fn read_tobj(path: &Path, text: &[u8], smooth: bool) -> Result<Faces, MeshError> {
    // Separate index streams: `single_index` re-deduplicates every (position, uv, normal)
    // tuple through a hash map, the largest cost of loading a million triangles.
    let opts = tobj::LoadOptions {
        triangulate: true,
        single_index: false,
        ..Default::default()
    };
    let libs = super::obj_file::Libraries::new(path);
    let (models, mtl) =
        super::obj_file::read_text(&libs, text, &opts).map_err(|e| locate(path, e))?;
    let libraries = libs.files();
    let mut warnings = Vec::new();
    let (materials, images) = convert_materials(path, mtl, &mut warnings);
    let mut vertices: Vec<Vec3> = Vec::new();
    let mut tris: Vec<[u32; 3]> = Vec::new();
    let mut file_normals: Vec<Option<[Vec3; 3]>> = Vec::new();
    let mut uvs: Vec<[Vec2; 3]> = Vec::new();
    let mut material_of: Vec<u32> = Vec::new();
    let mut any_uv = false;
    let mut any_mat = false;
    for m in models {
        let m = m.mesh;
        let offset = vertices.len() as u32;
        vertices.extend(m.positions.chunks_exact(3).map(Vec3::from_slice));
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
            tris.push([f[0], f[1], f[2]].map(|i| i + offset));
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

    Ok(Faces {
        vertices,
        triangles: tris,
        file_normals,
        uvs,
        colors: Vec::new(),
        material_of,
        materials,
        images,
        warnings,
        libraries,
    })
}

/// For each vertex, an id shared by every vertex with the same coordinates (bit for bit).
fn weld(vertices: &[Vec3]) -> Vec<u32> {
    let mut ids: HashMap<[u32; 3], u32> = HashMap::with_capacity(vertices.len());
    vertices
        .iter()
        .map(|p| {
            let n = ids.len() as u32;
            *ids.entry(p.to_array().map(f32::to_bits)).or_insert(n)
        })
        .collect()
}

/// Area-weighted vertex normals over positions welded by value, averaging only faces within
/// [`CREASE_ANGLE_DEG`] of the face being shaded (so hard edges stay hard).
fn smooth_normals(vertices: &[Vec3], triangles: &[[u32; 3]]) -> Vec<[Vec3; 3]> {
    let ids = weld(vertices);
    let corner: Vec<u32> = triangles
        .iter()
        .flat_map(|t| t.map(|i| ids[i as usize]))
        .collect();
    let tris: Vec<[Vec3A; 3]> = triangles
        .iter()
        .map(|t| t.map(|i| Vec3A::from(vertices[i as usize])))
        .collect();
    let nv = ids.iter().max().map_or(0, |&m| m as usize + 1);
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
    let unit: Vec<Vec3A> = area.iter().map(|a| a.unit_or(Default::default())).collect();
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
                out[k] = Vec3::from(sum.unit_or(unit[f]));
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
