//! The plain data every mesh reader hands on: an indexed mesh (STL, PLY, glTF), the
//! per-corner form `MeshAsset`'s common finish takes, and the budget errors. A leaf of the
//! asset room, so the readers and the dispatch by format need not import each other.

use std::path::PathBuf;

use glam::{Vec2, Vec3};

use super::embedded::ImageSource;
use super::obj_error::MeshError;
use crate::ir::Material;

/// What every reader gives before the common finish: triangles with area, per-triangle
/// attributes alongside.
pub(crate) struct Faces {
    pub(crate) vertices: Vec<Vec3>,
    pub(crate) triangles: Vec<[u32; 3]>,
    /// Per-triangle normals from the file (smooth only; `None` where a corner has none).
    pub(crate) file_normals: Vec<Option<[Vec3; 3]>>,
    pub(crate) uvs: Vec<[Vec2; 3]>,
    /// Per-corner vertex colours (linear, as image texels are read), or empty.
    pub(crate) colors: Vec<[Vec3; 3]>,
    pub(crate) material_of: Vec<u32>,
    pub(crate) materials: Vec<Material>,
    /// Per material, the image of its base colour (MTL `map_Kd`, glTF `baseColorTexture`):
    /// a file resolved beside the mesh file, or an image inside a glTF file.
    pub(crate) images: Vec<Option<ImageSource>>,
    pub(crate) warnings: Vec<String>,
    pub(crate) libraries: Vec<PathBuf>,
}

/// A mesh as STL and PLY store it: shared vertices and triangles indexing them.
#[derive(Debug, Default, PartialEq)]
pub struct Indexed {
    /// Vertex positions.
    pub vertices: Vec<Vec3>,
    /// Triangles (faces fanned from their first corner), every index below `vertices.len()`.
    pub triangles: Vec<[u32; 3]>,
    /// Per-vertex normals (empty when the file has none).
    pub normals: Vec<Vec3>,
    /// Per-vertex texture coordinates (empty when the file has none).
    pub uvs: Vec<Vec2>,
    /// Per-vertex colours, channels in [0, 1] as image texels are read (empty when the file
    /// has none).
    pub colors: Vec<Vec3>,
}

/// Rejects a mesh of `count` triangles when it is over `max` (untrusted files have a budget):
/// `count` of `what` (bytes of the file, triangles) within the budget `max`.
pub(crate) fn within_budget(count: u64, max: u64, what: &str) -> Result<(), MeshError> {
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

/// A budget error: a file that says it holds more triangles than one mesh may have.
pub(crate) fn too_many_triangles(count: u64, max: usize) -> MeshError {
    MeshError {
        too_large: true,
        ..MeshError::new(
            format!("it has {count} triangles; at most {max} are supported in one file"),
            None,
        )
    }
}
