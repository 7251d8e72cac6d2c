//! The asset service: every file a scene names besides its own text. Paths are resolved in one
//! documented order for the scene language and the course formats ([`search`]); OBJ meshes with
//! their MTL materials ([`obj`], [`mtl`]), STL, PLY and glTF meshes ([`indexed`]), texture images ([`image`]) and fonts ([`font`]) are read and decoded
//! once per process ([`cache`]) whoever asks first: evaluation (a mesh's `.bounds`), `rtc check`
//! or the preparation stage. Loading errors become diagnostics here, one kind per problem.
//!
//! The service depends only on the IR (materials it creates) and the diagnostic leaves; it knows
//! nothing of BVHs or rendering: geometry builds its structures from the plain data loaded here.

mod cache;
mod embedded;
mod font;
mod gltf;
mod gltf_accessor;
mod gltf_image;
mod image;
pub mod indexed;
mod mesh_data;
mod mipmap;
mod mtl;
mod obj;
pub mod obj_count;
mod obj_error;
pub mod obj_fast;
pub(crate) mod obj_file;
mod obj_inside;
mod ply;
mod ply_header;
pub(crate) mod search;
mod stl;

use std::path::Path;
use std::sync::Arc;

pub use self::embedded::{EmbeddedImage, ImageSource};
pub use self::font::FontAsset;
pub(crate) use self::font::{FontError, MAX_TEXT_CHARS};
pub(crate) use self::image::ImageError;
pub use self::image::Picture;
pub use self::mipmap::MipChain;
pub use obj::MeshAsset;
pub(crate) use obj_error::MeshError;

use cache::{Cache, FileKey};

static MESHES: Cache<MeshAsset> = Cache::new();
static PICTURES: Cache<Picture> = Cache::new();
static MIPS: Cache<MipChain> = Cache::new();
static FONTS: Cache<FontAsset> = Cache::new();

/// The font at `path` (the built-in DejaVu Sans for `None`), read and checked once per
/// process (again when the file changes).
pub(crate) fn font(path: Option<&Path>) -> Result<Arc<FontAsset>, FontError> {
    static BUILTIN: std::sync::OnceLock<Arc<FontAsset>> = std::sync::OnceLock::new();
    match path {
        None => Ok(BUILTIN
            .get_or_init(|| Arc::new(FontAsset::builtin()))
            .clone()),
        Some(path) => FONTS.get_or_load(
            FileKey::of(path, false),
            || FontAsset::load(path),
            |_| Vec::new(),
        ),
    }
}

/// The mesh file at `path` (OBJ, STL, PLY or glTF by its extension; with smoothed normals if
/// `smooth`), loaded once per process (again when it or one of its material libraries changes).
pub(crate) fn mesh(path: &Path, smooth: bool) -> Result<Arc<MeshAsset>, MeshError> {
    MESHES.get_or_load(
        FileKey::of(path, smooth),
        || MeshAsset::load(path, smooth),
        |m| m.libraries.clone(),
    )
}

/// The mesh `source` names (with smoothed normals if `smooth`): a file through [`mesh`], an
/// inline mesh built once per value (objects placing one value share it; a value no object
/// holds any more is forgotten).
pub(crate) fn mesh_of(
    source: &crate::ir::MeshSource,
    smooth: bool,
) -> Result<Arc<MeshAsset>, MeshError> {
    match source {
        crate::ir::MeshSource::File(path) => mesh(path, smooth),
        crate::ir::MeshSource::Inline(m) => inline_mesh(m, smooth),
    }
}

/// Inline meshes built so far, by value: the weak reference tells whether the address still
/// holds the same value (while it can be upgraded, the allocation is alive and unmoved).
type InlineEntry = (std::sync::Weak<crate::ir::InlineMesh>, bool, Arc<MeshAsset>);
static INLINE: std::sync::Mutex<Vec<InlineEntry>> = std::sync::Mutex::new(Vec::new());

fn inline_mesh(m: &Arc<crate::ir::InlineMesh>, smooth: bool) -> Result<Arc<MeshAsset>, MeshError> {
    let found = |cache: &mut Vec<InlineEntry>| {
        cache.retain(|(w, _, _)| w.strong_count() > 0);
        cache
            .iter()
            .find(|(w, s, _)| *s == smooth && w.upgrade().is_some_and(|v| Arc::ptr_eq(&v, m)))
            .map(|(_, _, a)| a.clone())
    };
    if let Some(a) = found(&mut INLINE.lock().unwrap_or_else(|e| e.into_inner())) {
        return Ok(a);
    }
    // Built outside the lock: a large mesh must not stall other threads' lookups.
    let asset = Arc::new(MeshAsset::inline(m, smooth)?);
    let mut cache = INLINE.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(a) = found(&mut cache) {
        return Ok(a);
    }
    cache.push((Arc::downgrade(m), smooth, asset.clone()));
    Ok(asset)
}

/// The `.bin` buffer files the glTF file `path` (its bytes `bytes`) names, resolved beside it
/// as the loader resolves them (none when it does not parse).
pub(crate) fn gltf_buffer_paths(path: &Path, bytes: &[u8]) -> Vec<std::path::PathBuf> {
    gltf::buffer_paths(path, bytes)
}

/// Bytes the image at `path` takes decoded: from the cache if it is there, else from its
/// header's size (nothing is decoded). 0 when the header cannot be read: decoding will say why.
pub(crate) fn picture_bytes(path: &Path) -> u64 {
    match PICTURES.get(&FileKey::of(path, false)) {
        Some(p) => p.memory() as u64,
        None => image::header_bytes(path).unwrap_or(0),
    }
}

/// The width and height of the image at `path`: from the cache if it is there, else from its
/// header (nothing is decoded); `None` when the header cannot be read.
pub(crate) fn picture_size(path: &Path) -> Option<(u32, u32)> {
    match PICTURES.get(&FileKey::of(path, false)) {
        Some(p) => Some(p.size()),
        None => image::header_size(path),
    }
}

/// The image at `path`, decoded once per process (again when it changes).
pub fn picture(path: &Path) -> Result<Arc<Picture>, ImageError> {
    PICTURES.get_or_load(
        FileKey::of(path, false),
        || Picture::load(path),
        |_| Vec::new(),
    )
}

/// The mip chain of the image at `path` ([`picture`]'s, halved down to a texel), built once
/// per process (again when the file changes).
pub fn mip_chain(path: &Path) -> Result<Arc<MipChain>, ImageError> {
    let picture = picture(path)?;
    MIPS.get_or_load(
        FileKey::of(path, false),
        || Ok(MipChain::of(&picture)),
        |_| Vec::new(),
    )
}

/// Forgets the loads of `path` and of every mesh that read it as a material library: for a
/// file whose content changed though its size and modification time did not (`rtc watch`
/// compares contents; a file system's clock may be too coarse to tell two writes apart).
pub fn forget(path: &Path) {
    MESHES.forget(path);
    PICTURES.forget(path);
    MIPS.forget(path);
    FONTS.forget(path);
}

/// How many loads of `path` the process keeps (versions, and a mesh's smooth and flat
/// variants): one per variant however often the file changed.
pub fn cached_loads(path: &Path) -> usize {
    MESHES.count(path) + PICTURES.count(path) + FONTS.count(path)
}

/// Forgets every cached asset (benchmarks use it to time loading afresh).
pub fn clear_cache() {
    MESHES.clear();
    INLINE.lock().unwrap_or_else(|e| e.into_inner()).clear();
    PICTURES.clear();
    FONTS.clear();
}
