//! The files a watched scene depends on and their content hashes: the scene, every module it
//! imported, every mesh (with the MTL files it names) and texture image it loads. A change is a
//! changed hash, not a changed modification time, so an editor that rewrites a file unchanged
//! (or touches it) does not cost a render.

use std::collections::{BTreeMap, BTreeSet};
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};

use rtc::ir::Scene;
use rtc::source::SourceMap;

/// A path's content hash; `None` when it cannot be read (missing, being replaced).
type ContentHash = Option<u64>;

/// Hashes a file's bytes (SipHash from std: no collision matters here, only change).
fn hash_file(path: &Path) -> ContentHash {
    let bytes = rtc::source::read_regular(path, rtc::ir::limits::MAX_MESH_FILE_BYTES).ok()?;
    let mut h = std::collections::hash_map::DefaultHasher::new();
    bytes.hash(&mut h);
    Some(h.finish())
}

/// Every file an evaluation read or a render will read: the scene, the source files in
/// `sources` that exist on disk (the built-in `std.*` modules do not), meshes, their MTL
/// files and texture images.
pub(crate) fn dependencies(
    scene_file: &Path,
    sources: &SourceMap,
    scene: Option<&Scene>,
) -> BTreeSet<PathBuf> {
    let mut out = BTreeSet::new();
    out.insert(scene_file.to_path_buf());
    for f in sources.files() {
        if f.path.is_file() {
            out.insert(f.path.clone());
        }
    }
    if let Some(scene) = scene {
        out.extend(rtc::opt::fingerprint::files_read(scene));
    }
    out
}

/// The folder to watch for a file: its parent, `.` for a bare name. Editors save by writing a
/// new file and renaming it over the old one, which replaces the watched inode; watching the
/// folder sees the rename.
pub(crate) fn folder_of(path: &Path) -> PathBuf {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// The last seen content of every dependency.
#[derive(Debug, Default)]
pub(crate) struct Snapshot {
    hashes: BTreeMap<PathBuf, ContentHash>,
}

impl Snapshot {
    /// Hashes every file in `files` now.
    pub(crate) fn take(files: &BTreeSet<PathBuf>) -> Snapshot {
        Snapshot {
            hashes: files.iter().map(|p| (p.clone(), hash_file(p))).collect(),
        }
    }

    /// The files whose content differs between this snapshot and `now` (added, removed or
    /// changed), in path order.
    pub(crate) fn changed(&self, now: &Snapshot) -> Vec<PathBuf> {
        let mut out: BTreeSet<PathBuf> = BTreeSet::new();
        for (path, hash) in &self.hashes {
            if now.hashes.get(path) != Some(hash) {
                out.insert(path.clone());
            }
        }
        for path in now.hashes.keys() {
            if !self.hashes.contains_key(path) {
                out.insert(path.clone());
            }
        }
        out.into_iter().collect()
    }

    /// The files recorded.
    pub(crate) fn files(&self) -> BTreeSet<PathBuf> {
        self.hashes.keys().cloned().collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bare_file_name_is_watched_through_the_current_folder() {
        assert_eq!(folder_of(Path::new("scene.rtc")), PathBuf::from("."));
        assert_eq!(folder_of(Path::new("a/scene.rtc")), PathBuf::from("a"));
    }

    #[test]
    fn a_rewrite_with_the_same_bytes_is_no_change() {
        let dir = std::env::temp_dir().join(format!("rtc-watch-files-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let f = dir.join("s.rtc");
        std::fs::write(&f, "a").unwrap();
        let files: BTreeSet<PathBuf> = [f.clone()].into();
        let before = Snapshot::take(&files);
        std::fs::write(&f, "a").unwrap();
        assert!(before.changed(&Snapshot::take(&files)).is_empty());
        std::fs::write(&f, "b").unwrap();
        assert_eq!(before.changed(&Snapshot::take(&files)), vec![f.clone()]);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
