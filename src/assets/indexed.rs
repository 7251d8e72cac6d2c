//! Mesh formats besides OBJ, chosen by the file's extension: STL ([`super::stl`]), PLY
//! ([`super::ply`]) and glTF 2.0 ([`super::gltf`]). Each reader gives an indexed mesh (shared vertices, triangles, optional
//! per-vertex normals and texture coordinates); this module reads the file within the asset
//! budgets and turns that into the per-corner data every reader hands to `MeshAsset`'s common
//! finish, with the rules of the OBJ readers (faces without area dropped, a coordinate that is
//! not finite refused).

use std::path::Path;

use glam::Vec3A;

pub use super::mesh_data::Indexed;
use super::mesh_data::{Faces, within_budget};
use super::obj_error::MeshError;
use crate::ir::limits::{MAX_MESH_FILE_BYTES, MAX_TRIANGLES};

/// A mesh file's format, by its extension (any case).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Wavefront OBJ (`.obj`).
    Obj,
    /// STL, ASCII or binary (`.stl`).
    Stl,
    /// PLY, ASCII or binary of either byte order (`.ply`).
    Ply,
    /// glTF 2.0, JSON with its buffers (`.gltf`) or binary (`.glb`).
    Gltf,
}

impl Format {
    /// The format `path`'s extension names (OBJ for any other: `mesh(path)` refuses those
    /// before anything is loaded).
    pub(crate) fn of(path: &Path) -> Format {
        match Self::known(path) {
            Some(f) => f,
            None => Format::Obj,
        }
    }

    /// The format `path`'s extension names, if rtc reads it.
    pub(crate) fn known(path: &Path) -> Option<Format> {
        let ext = path.extension()?.to_string_lossy().to_ascii_lowercase();
        match ext.as_str() {
            "obj" => Some(Format::Obj),
            "stl" => Some(Format::Stl),
            "ply" => Some(Format::Ply),
            "gltf" | "glb" => Some(Format::Gltf),
            _ => None,
        }
    }
}

/// Reads the STL or PLY file `path` (within the file-size budget) into the common form.
pub(super) fn read(path: &Path, format: Format, smooth: bool) -> Result<Faces, MeshError> {
    if let Ok(meta) = std::fs::metadata(path) {
        within_budget(meta.len(), MAX_MESH_FILE_BYTES, "bytes")?;
    }
    let bytes = crate::source::read_regular(path, MAX_MESH_FILE_BYTES).map_err(|e| {
        let message = if e.kind() == std::io::ErrorKind::NotFound {
            "the file cannot be read".to_owned()
        } else {
            format!("the file cannot be read: {e}")
        };
        MeshError {
            missing: true,
            ..MeshError::new(message, None)
        }
    })?;
    if format == Format::Gltf {
        let g = super::gltf::parse(path, &bytes, MAX_TRIANGLES)?;
        drop(bytes);
        let mut f = faces(g.mesh, g.material_of, smooth)?;
        f.materials = g.materials;
        f.images = g.images;
        f.libraries = g.buffers;
        f.warnings = g.warnings;
        return Ok(f);
    }
    let indexed = parse(&bytes, format)?;
    drop(bytes);
    faces(indexed, Vec::new(), smooth)
}

/// An inline mesh in the common form (its coordinates in single precision, as a file's).
pub(super) fn inline(mesh: &crate::ir::InlineMesh, smooth: bool) -> Result<Faces, MeshError> {
    let indexed = Indexed {
        vertices: mesh.vertices.iter().map(|v| v.as_vec3()).collect(),
        triangles: mesh.triangles.clone(),
        normals: mesh.normals.iter().map(|v| v.as_vec3()).collect(),
        uvs: mesh.uvs.iter().map(|v| v.as_vec2()).collect(),
        colors: Vec::new(),
    };
    faces(indexed, Vec::new(), smooth)
}

/// The mesh in a file's bytes, read as `format` (STL or PLY; a glTF file's other buffers are
/// looked for relative to the working directory).
pub fn parse(bytes: &[u8], format: Format) -> Result<Indexed, MeshError> {
    match format {
        Format::Stl => super::stl::parse(bytes, MAX_TRIANGLES),
        Format::Ply => super::ply::parse(bytes, MAX_TRIANGLES),
        Format::Gltf => super::gltf::parse(Path::new(""), bytes, MAX_TRIANGLES).map(|g| g.mesh),
        Format::Obj => Err(MeshError::new(
            "OBJ files are read by `MeshAsset::load`",
            None,
        )),
    }
}

/// How many triangles with area the STL, PLY or glTF file `bytes` gives, through the reader
/// and the common finish's rules (what the fuzzers run without touching the file system).
pub fn triangles_in(bytes: &[u8], format: Format) -> Result<usize, MeshError> {
    let mesh = parse(bytes, format)?;
    Ok(faces(mesh, Vec::new(), true)?.triangles.len())
}

/// The per-corner form of `mesh`: triangles with area only, file normals (for `smooth`),
/// texture coordinates and vertex colours per corner, and each triangle's material slot from `material_of` (one
/// per triangle, or empty).
pub(super) fn faces(
    mesh: Indexed,
    material_of: Vec<u32>,
    smooth: bool,
) -> Result<Faces, MeshError> {
    let Indexed {
        vertices,
        triangles,
        normals,
        uvs,
        colors,
    } = mesh;
    let mut kept = Vec::with_capacity(triangles.len());
    let mut materials = Vec::with_capacity(material_of.len());
    for (k, t) in triangles.into_iter().enumerate() {
        let [a, b, c] = t.map(|v| Vec3A::from(vertices[v as usize]));
        if !(a.is_finite() && b.is_finite() && c.is_finite()) {
            return Err(MeshError::new("a vertex coordinate is not finite", None));
        }
        // Faces without area can never be hit; dropping them keeps normals clean.
        if (b - a).cross(c - a) != Vec3A::ZERO {
            kept.push(t);
            if let Some(&m) = material_of.get(k) {
                materials.push(m);
            }
        }
    }
    let file_normals = if !smooth {
        Vec::new()
    } else if normals.is_empty() {
        vec![None; kept.len()]
    } else {
        kept.iter()
            .map(|t| Some(t.map(|v| normals[v as usize])))
            .collect()
    };
    let uvs = if uvs.is_empty() {
        Vec::new()
    } else {
        kept.iter().map(|t| t.map(|v| uvs[v as usize])).collect()
    };
    let colors = if colors.is_empty() {
        Vec::new()
    } else {
        kept.iter().map(|t| t.map(|v| colors[v as usize])).collect()
    };
    Ok(Faces {
        vertices,
        triangles: kept,
        file_normals,
        uvs,
        colors,
        material_of: materials,
        materials: Vec::new(),
        images: Vec::new(),
        warnings: Vec::new(),
        libraries: Vec::new(),
    })
}
