//! Loaded assets shared across the whole process: evaluation (a mesh's `.bounds`), `rtc check`
//! and the preparation stage ask for the same file, and it is read and decoded once. A file is
//! known by its path, its size and its modification time, so a changed file loads again (what
//! `rtc watch` needs); so does a value whose other files (a mesh's material libraries) changed.
//! Failures are not kept, so a fixed file loads on the next call. Loading a new version of a
//! path drops the older ones, so a long-lived process (`rtc watch` re-rendering an edited
//! texture) keeps one version per path instead of every version it ever saw; a value still in
//! use (by a render) lives on until that use ends, through its `Arc`. [`Cache::forget`] drops
//! a path whose content changed without its size or time showing it.

use std::collections::HashMap;
use std::hash::Hash;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};
use std::time::SystemTime;

/// A file as it was when loaded, with the loader's variant (a mesh's `smooth`).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) struct FileKey {
    path: PathBuf,
    variant: bool,
    len: u64,
    modified: Option<SystemTime>,
}

impl FileKey {
    /// The key of `path` as it is now on disk.
    pub(crate) fn of(path: &Path, variant: bool) -> FileKey {
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

    /// Whether the file is still as it was when this key was taken.
    fn is_current(&self) -> bool {
        *self == FileKey::of(&self.path, self.variant)
    }
}

/// A loaded value and the other files it was read from, as they were then.
struct Entry<T> {
    value: Arc<T>,
    also: Vec<FileKey>,
}

impl<T> Entry<T> {
    /// Whether none of the other files changed since.
    fn is_current(&self) -> bool {
        self.also.iter().all(FileKey::is_current)
    }
}

/// A process-wide map from file to loaded value.
pub(crate) struct Cache<T> {
    map: OnceLock<Mutex<HashMap<FileKey, Entry<T>>>>,
}

impl<T> Default for Cache<T> {
    fn default() -> Cache<T> {
        Cache::new()
    }
}

impl<T> Cache<T> {
    /// An empty cache (usable in a `static`).
    pub(crate) const fn new() -> Cache<T> {
        Cache {
            map: OnceLock::new(),
        }
    }

    fn map(&self) -> std::sync::MutexGuard<'_, HashMap<FileKey, Entry<T>>> {
        // A poisoned lock only means another thread panicked mid-insert; the map is still sound.
        self.map
            .get_or_init(Default::default)
            .lock()
            .unwrap_or_else(|e| e.into_inner())
    }

    /// The value for `key` if it is loaded and still current.
    pub(crate) fn get(&self, key: &FileKey) -> Option<Arc<T>> {
        self.map()
            .get(key)
            .filter(|e| e.is_current())
            .map(|e| e.value.clone())
    }

    /// The value for `key`, loading it with `load` the first time (and again when a file
    /// `also` names for the loaded value, such as a mesh's material library, has changed).
    pub(crate) fn get_or_load<E>(
        &self,
        key: FileKey,
        load: impl FnOnce() -> Result<T, E>,
        also: impl FnOnce(&T) -> Vec<PathBuf>,
    ) -> Result<Arc<T>, E> {
        if let Some(e) = self.map().get(&key).filter(|e| e.is_current()) {
            return Ok(e.value.clone());
        }
        // Loaded outside the lock: two threads may both load a new file, and the first one kept.
        let value = load()?;
        let also = also(&value).iter().map(|p| FileKey::of(p, false)).collect();
        let entry = Entry {
            value: Arc::new(value),
            also,
        };
        let mut map = self.map();
        map.retain(|k, _| !key.supersedes(k));
        match map.get(&key) {
            Some(e) if e.is_current() => Ok(e.value.clone()),
            _ => {
                let value = entry.value.clone();
                map.insert(key, entry);
                Ok(value)
            }
        }
    }

    /// Drops every version of `path`, and every value that was read from it besides its own
    /// file (they stay alive while others hold them).
    pub(crate) fn forget(&self, path: &Path) {
        self.map()
            .retain(|k, e| k.path != path && e.also.iter().all(|a| a.path != path));
    }

    /// How many values are kept for `path` (versions and variants).
    pub(crate) fn count(&self, path: &Path) -> usize {
        self.map().keys().filter(|k| k.path == path).count()
    }

    /// Forgets every value (they stay alive while others hold them).
    pub(crate) fn clear(&self) {
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
        let other = cache.get_or_load(FileKey::of(&b, false), || load(&b), |_| Vec::new());
        assert_eq!(*other.unwrap(), 10);
        for n in 1..=5 {
            // A different size each time: a new version even where the clock is too coarse to
            // tell the writes apart.
            std::fs::write(&a, "x".repeat(n)).unwrap();
            for smooth in [false, true] {
                let got = cache.get_or_load(FileKey::of(&a, smooth), || load(&a), |_| Vec::new());
                assert_eq!(*got.unwrap(), n);
            }
        }
        // `b` once, `a` in its newest version twice (both variants); not 1 + 2 × 5.
        assert_eq!(cache.map().len(), 3);
        assert_eq!((cache.count(&a), cache.count(&b)), (2, 1));
        cache.forget(&a);
        assert_eq!((cache.count(&a), cache.count(&b)), (0, 1));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// A value read from other files too loads again when one of them changes, and is
    /// forgotten with them.
    #[test]
    fn a_change_of_another_file_read_reloads_the_value() {
        let dir = std::env::temp_dir().join(format!("rtc-cache-also-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (main, lib) = (dir.join("m.obj"), dir.join("m.mtl"));
        std::fs::write(&main, "mtllib m.mtl").unwrap();
        let cache: Cache<String> = Cache::new();
        let load = || std::fs::read_to_string(&lib);
        let get = || {
            let got = cache.get_or_load(FileKey::of(&main, false), load, |_| vec![lib.clone()]);
            got.map(|v| v.to_string())
        };
        std::fs::write(&lib, "red").unwrap();
        assert_eq!(get().unwrap(), "red");
        std::fs::write(&lib, "green").unwrap();
        assert_eq!(get().unwrap(), "green");
        assert_eq!(cache.count(&main), 1);
        cache.forget(&lib);
        assert_eq!(cache.count(&main), 0);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
