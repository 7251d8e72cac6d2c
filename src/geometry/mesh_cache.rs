//! Loaded meshes shared across the whole process: the evaluator's `.bounds` query and the
//! geometry build both ask for a mesh, and the file is read and its BVH built only once.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};
use std::time::SystemTime;

use super::mesh::MeshData;
use super::mesh_error::MeshError;

/// A file as it was when loaded: a changed file (size or modification time) loads again.
type Key = (PathBuf, bool, u64, Option<SystemTime>);

fn cache() -> &'static Mutex<HashMap<Key, Arc<MeshData>>> {
    static CACHE: OnceLock<Mutex<HashMap<Key, Arc<MeshData>>>> = OnceLock::new();
    CACHE.get_or_init(Default::default)
}

/// The mesh in `path` (with smoothed normals if `smooth`), loaded once per process.
/// Failures are not cached, so a fixed file loads on the next call.
pub fn load(path: &Path, smooth: bool) -> Result<Arc<MeshData>, MeshError> {
    let meta = std::fs::metadata(path).ok();
    let key = (
        path.to_path_buf(),
        smooth,
        meta.as_ref().map_or(0, |m| m.len()),
        meta.and_then(|m| m.modified().ok()),
    );
    // A poisoned lock only means another thread panicked mid-insert; the map is still sound.
    if let Some(m) = cache().lock().unwrap_or_else(|e| e.into_inner()).get(&key) {
        return Ok(m.clone());
    }
    // Loaded outside the lock: two threads may both load a new file, and the first one kept.
    let m = Arc::new(MeshData::load(path, smooth)?);
    let mut map = cache().lock().unwrap_or_else(|e| e.into_inner());
    Ok(map.entry(key).or_insert(m).clone())
}

/// Forgets every cached mesh (they stay alive while worlds still hold them); benchmarks use it
/// to time loading afresh.
pub fn clear() {
    cache().lock().unwrap_or_else(|e| e.into_inner()).clear();
}
