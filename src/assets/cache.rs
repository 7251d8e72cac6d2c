//! Loaded assets shared across the whole process: evaluation (a mesh's `.bounds`), `rtc check`
//! and the preparation stage ask for the same file, and it is read and decoded once. A file is
//! known by its path, its size and its modification time, so a changed file loads again (what
//! `rtc watch` needs); failures are not kept, so a fixed file loads on the next call. Loading a
//! new version of a path drops the older ones, so a long-lived process (`rtc watch` re-rendering
//! an edited texture) keeps one version per path instead of every version it ever saw.

use std::collections::HashMap;
use std::hash::Hash;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};
use std::time::SystemTime;

/// A file as it was when loaded, with the loader's variant (a mesh's `smooth`).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct FileKey {
    path: PathBuf,
    variant: bool,
    len: u64,
    modified: Option<SystemTime>,
}

impl FileKey {
    /// The key of `path` as it is now on disk.
    pub fn of(path: &Path, variant: bool) -> FileKey {
        let meta = std::fs::metadata(path).ok();
        FileKey {
            path: path.to_path_buf(),
            variant,
            len: meta.as_ref().map_or(0, |m| m.len()),
            modified: meta.and_then(|m| m.modified().ok()),
        }
    }

    /// Whether `other` is an older or newer version of the same path (either variant).
    fn supersedes(&self, other: &FileKey) -> bool {
        self.path == other.path && (self.len, self.modified) != (other.len, other.modified)
    }
}

/// A process-wide map from file to loaded value.
pub struct Cache<T> {
    map: OnceLock<Mutex<HashMap<FileKey, Arc<T>>>>,
}

impl<T> Default for Cache<T> {
    fn default() -> Cache<T> {
        Cache::new()
    }
}

impl<T> Cache<T> {
    /// An empty cache (usable in a `static`).
    pub const fn new() -> Cache<T> {
        Cache {
            map: OnceLock::new(),
        }
    }

    fn map(&self) -> std::sync::MutexGuard<'_, HashMap<FileKey, Arc<T>>> {
        // A poisoned lock only means another thread panicked mid-insert; the map is still sound.
        self.map
            .get_or_init(Default::default)
            .lock()
            .unwrap_or_else(|e| e.into_inner())
    }

    /// The value for `key` if it is loaded.
    pub fn get(&self, key: &FileKey) -> Option<Arc<T>> {
        self.map().get(key).cloned()
    }

    /// The value for `key`, loading it with `load` the first time.
    pub fn get_or_load<E>(
        &self,
        key: FileKey,
        load: impl FnOnce() -> Result<T, E>,
    ) -> Result<Arc<T>, E> {
        if let Some(v) = self.map().get(&key) {
            return Ok(v.clone());
        }
        // Loaded outside the lock: two threads may both load a new file, and the first one kept.
        let v = Arc::new(load()?);
        let mut map = self.map();
        map.retain(|k, _| !key.supersedes(k));
        Ok(map.entry(key).or_insert(v).clone())
    }

    /// Forgets every value (they stay alive while others hold them).
    pub fn clear(&self) {
        self.map().clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every edit of a file is a new version; only the newest stays cached, in both variants.
    #[test]
    fn a_new_version_drops_the_older_ones() {
        let dir = std::env::temp_dir().join(format!("rtc-cache-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (a, b) = (dir.join("a.txt"), dir.join("b.txt"));
        std::fs::write(&b, "other file").unwrap();
        let cache: Cache<usize> = Cache::new();
        let load = |p: &Path| std::fs::read(p).map(|bytes| bytes.len());
        let other = cache.get_or_load(FileKey::of(&b, false), || load(&b));
        assert_eq!(*other.unwrap(), 10);
        for n in 1..=5 {
            // A different size each time: a new version even where the clock is too coarse to
            // tell the writes apart.
            std::fs::write(&a, "x".repeat(n)).unwrap();
            for smooth in [false, true] {
                let got = cache.get_or_load(FileKey::of(&a, smooth), || load(&a));
                assert_eq!(*got.unwrap(), n);
            }
        }
        // `b` once, `a` in its newest version twice (both variants); not 1 + 2 × 5.
        assert_eq!(cache.map().len(), 3);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
