//! A scene's fingerprint: the SHA-256 of everything that decides its pixels. The IR is the
//! whole input of the renderer, so the fingerprint hashes the IR's debug form (shapes, materials,
//! lights, camera, settings, spans) and the bytes of every file the renderer will read: image
//! textures, OBJ meshes and the material libraries (`mtllib`) they name. Shards of one render
//! carry it so `rtc merge` can refuse parts of an edited scene.

use std::path::{Path, PathBuf};

use sha2::{Digest, Sha256};

use crate::ir::{Object, Scene, Shape, Texture};

/// The hex SHA-256 fingerprint of `scene` and the files it reads (a missing file hashes as
/// absent: the render itself reports it).
pub fn scene(scene: &Scene) -> String {
    let mut h = Sha256::new();
    h.update(format!("{scene:?}").as_bytes());
    for path in files_read(scene) {
        h.update(path.to_string_lossy().as_bytes());
        // Only regular files (a FIFO would block): the render itself reports the others.
        match crate::source::read_regular(&path, crate::ir::limits::MAX_MESH_FILE_BYTES) {
            Ok(bytes) => {
                h.update((bytes.len() as u64).to_le_bytes());
                h.update(&bytes);
            }
            Err(_) => h.update(b"absent"),
        }
    }
    hex(&h.finalize())
}

/// The hex SHA-256 of `bytes`.
pub fn bytes(bytes: &[u8]) -> String {
    hex(&Sha256::digest(bytes))
}

fn hex(digest: &[u8]) -> String {
    digest.iter().map(|b| format!("{b:02x}")).collect()
}

/// Every file the renderer reads for `scene` (textures, meshes and their `mtllib` files) and
/// height fields' images, in a fixed order.
pub fn files_read(scene: &Scene) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for t in &scene.textures {
        if let Texture::Image { path, .. } = t {
            out.push(path.clone());
        }
    }
    let (mut meshes, mut maps) = (Vec::new(), Vec::new());
    for o in &scene.objects {
        collect_meshes(o, &mut meshes, &mut maps);
    }
    for m in meshes {
        out.extend(material_libraries(&m));
        out.push(m);
    }
    // Height fields' images (read when the scene is evaluated: their heights are in the IR).
    out.extend(maps);
    out
}

fn collect_meshes(o: &Object, meshes: &mut Vec<PathBuf>, maps: &mut Vec<PathBuf>) {
    match &o.shape {
        Shape::Mesh {
            source: crate::ir::MeshSource::File(path),
            ..
        } => meshes.push(path.clone()),
        Shape::HeightField {
            image: Some(path), ..
        } => maps.push(path.clone()),
        Shape::Csg { children, .. } => children
            .iter()
            .for_each(|c| collect_meshes(c, meshes, maps)),
        _ => {}
    }
}

/// The `mtllib` files an OBJ names, resolved beside it as the OBJ loader does (one rule:
/// `assets::obj_file::library_paths`).
/// A glTF file's other files are its `.bin` buffers; STL and PLY files have none.
fn material_libraries(obj: &Path) -> Vec<PathBuf> {
    use crate::assets::indexed::Format;
    let format = Format::of(obj);
    if matches!(format, Format::Stl | Format::Ply) {
        return Vec::new();
    }
    let Ok(text) = crate::source::read_regular(obj, crate::ir::limits::MAX_MESH_FILE_BYTES) else {
        return Vec::new();
    };
    match format {
        Format::Gltf => crate::assets::gltf_buffer_paths(obj, &text),
        _ => crate::assets::obj_file::library_paths(obj, &text),
    }
}
