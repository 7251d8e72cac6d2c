//! Where a triangle mesh's data comes from: a file the asset service reads (OBJ, STL, PLY,
//! glTF) or vertices and faces written in the scene itself (an inline mesh, POV-Ray's `mesh`
//! and `mesh2`).

use std::path::PathBuf;
use std::sync::Arc;

use glam::{DVec2, DVec3};

/// A mesh's data: a file or the scene's own lists.
#[derive(Clone, Debug, PartialEq)]
pub enum MeshSource {
    /// A mesh file (resolved path), loaded when the scene is prepared and shared by every
    /// object that names it.
    File(PathBuf),
    /// Vertices and triangles given in the scene; objects placing the same value share one
    /// loaded mesh.
    Inline(Arc<InlineMesh>),
}

impl MeshSource {
    /// How messages name the mesh: "the mesh `path`" or "the inline mesh".
    pub fn describe(&self) -> String {
        match self {
            MeshSource::File(path) => format!("the mesh `{}`", path.display()),
            MeshSource::Inline(m) => {
                format!("the inline mesh of {} triangles", m.triangles.len())
            }
        }
    }

    /// The file, if the mesh is read from one.
    pub fn path(&self) -> Option<&std::path::Path> {
        match self {
            MeshSource::File(path) => Some(path),
            MeshSource::Inline(_) => None,
        }
    }
}

/// A mesh written in the scene: shared vertices, triangles indexing them (polygons were fanned
/// from their first corner when the scene was evaluated), optional per-vertex normals and
/// texture coordinates. Every index is below `vertices.len()` and every coordinate finite (the
/// constructor's checks).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct InlineMesh {
    /// Vertex positions.
    pub vertices: Vec<DVec3>,
    /// Triangles as indices into `vertices`.
    pub triangles: Vec<[u32; 3]>,
    /// One normal per vertex (empty: none; smooth shading then averages face normals).
    pub normals: Vec<DVec3>,
    /// One texture coordinate per vertex (empty: none).
    pub uvs: Vec<DVec2>,
}
