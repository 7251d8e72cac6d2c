//! `rtc watch SCENE`: a live page on 127.0.0.1 that re-renders the scene whenever it or a file
//! it imports or loads changes (see docs/watch.md).
//!
//! File changes come from the operating system's notifications (the `notify` crate: inotify,
//! FSEvents, ReadDirectoryChangesW) on the folders of the dependencies, not the files: editors
//! save by writing a new file and renaming it over the old one. Events are debounced, then the
//! dependencies' content hashes decide whether anything really changed. Notifications rather
//! than polling because a poll that compares content must re-read every mesh and texture on
//! every tick, and one that compares modification times misses same-second edits.

mod files;
mod html;
mod http;
mod progressive;
mod server;

use std::collections::BTreeSet;
use std::path::PathBuf;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, mpsc};
use std::time::Duration;

use notify::{EventKind, RecursiveMode, Watcher};
use rtc::diag::Diagnostic;
use rtc::source::SourceMap;
use serde_json::json;

use crate::cli::Outcome;
use files::Snapshot;
use progressive::Job;
use server::Hub;

/// Quiet time after the last file event before the scene is re-read: an editor's save is
/// several events (write, rename, attribute change) within a few milliseconds.
const DEBOUNCE: Duration = Duration::from_millis(60);

/// What `rtc watch` was asked to do.
pub(crate) struct Options {
    /// The scene file.
    pub(crate) file: PathBuf,
    /// Port on 127.0.0.1 (0: any free port).
    pub(crate) port: u16,
    /// Open the page in the default browser.
    pub(crate) open: bool,
    /// Worker threads (0 = all cores).
    pub(crate) threads: usize,
}

/// Serves the page and re-renders on every change until the process is stopped.
pub(crate) fn run(options: &Options) -> Outcome {
    let file = &options.file;
    if !file.is_file() {
        eprintln!(
            "error: cannot watch `{}`: no such file\n  help: give the path of a scene file (`.rtc`, `.in` or `.yaml`)",
            file.display()
        );
        return Outcome::IoOrUsage;
    }
    let listener = match server::bind(options.port) {
        Ok(l) => l,
        Err(message) => {
            eprintln!("error: {message}");
            return Outcome::IoOrUsage;
        }
    };
    let url = match listener.local_addr() {
        Ok(addr) => format!("http://{addr}/"),
        Err(e) => {
            eprintln!("error: cannot read the server's address: {e}");
            return Outcome::IoOrUsage;
        }
    };
    let hub = Arc::new(Hub::default());
    if let Err(message) = server::serve(listener, hub.clone(), http::Limits::from_env()) {
        eprintln!("error: {message}");
        return Outcome::IoOrUsage;
    }
    let (tx, rx) = mpsc::channel();
    let mut watcher = match notify::recommended_watcher(move |event| {
        // The loop below ends only with the process; a failed send has nobody to tell.
        let _ = tx.send(event);
    }) {
        Ok(w) => w,
        Err(e) => {
            eprintln!("error: cannot watch files for changes: {e}");
            return Outcome::IoOrUsage;
        }
    };
    eprintln!(
        "rtc watch: serving {url} (watching {}; Ctrl-C stops)",
        file.display()
    );
    if options.open {
        open_browser(&url);
    }
    let mut state = WatchState {
        options,
        hub,
        current: Arc::new(AtomicU64::new(0)),
        frames: Arc::new(AtomicU64::new(0)),
        folders: BTreeSet::new(),
    };
    loop {
        let (snapshot, failed) = state.reload(&mut watcher);
        let Some(changed) = wait_for_change(&rx, &snapshot, failed) else {
            eprintln!("error: the file watcher stopped");
            return Outcome::IoOrUsage;
        };
        // The cached loads of a changed file go, even where its size and modification time
        // look the same; the render in progress keeps its own until it stops.
        for path in &changed {
            rtc::assets::forget(path);
        }
    }
}

/// The watch loop's state between reloads.
struct WatchState<'a> {
    options: &'a Options,
    hub: Arc<Hub>,
    /// The generation of the latest reload; a render whose generation differs stops.
    current: Arc<AtomicU64>,
    frames: Arc<AtomicU64>,
    /// Folders already watched.
    folders: BTreeSet<PathBuf>,
}

impl WatchState<'_> {
    /// Cancels the render in progress, evaluates the scene and starts rendering it; returns the
    /// dependencies' snapshot and whether the scene failed to evaluate.
    fn reload(&mut self, watcher: &mut notify::RecommendedWatcher) -> (Snapshot, bool) {
        let generation = self.current.fetch_add(1, Ordering::SeqCst) + 1;
        let file = &self.options.file;
        let mut sources = SourceMap::new();
        let loaded = crate::cli::load(file, &mut sources, &rtc::eval::EvalOptions::default());
        let deps = files::dependencies(file, &sources, loaded.scene.as_ref());
        for folder in deps.iter().map(|p| files::folder_of(p)) {
            // A folder that cannot be watched (removed meanwhile) is retried on the next reload.
            if !self.folders.contains(&folder)
                && watcher.watch(&folder, RecursiveMode::NonRecursive).is_ok()
            {
                self.folders.insert(folder);
            }
        }
        // Hash after evaluating: an edit made meanwhile is then seen as a change.
        let snapshot = Snapshot::take(&deps);
        let (hub, current, frames) = (self.hub.clone(), self.current.clone(), self.frames.clone());
        let threads = self.options.threads;
        let (diags, scene) = (loaded.diagnostics, loaded.scene);
        let failed = scene.is_none() || diags.has_errors();
        if failed {
            let job = Job {
                hub: &hub,
                current: &current,
                generation,
                frames: &frames,
                threads,
            };
            job.diagnostics(&diags.items, &sources);
            hub.publish(
                "progress",
                &json!({ "stage": "stopped", "fraction": 0.0, "eta_seconds": null, "done": true }),
            );
            return (snapshot, true);
        }
        let Some(scene) = scene else {
            return (snapshot, true);
        };
        hub.publish(
            "scene",
            &json!({ "file": file.display().to_string(), "summary": rtc::check::summary(&scene) }),
        );
        std::thread::spawn(move || {
            let job = Job {
                hub: &hub,
                current: &current,
                generation,
                frames: &frames,
                threads,
            };
            let warnings: Vec<Diagnostic> = diags.items;
            job.run(&scene, &sources, warnings);
        });
        (snapshot, false)
    }
}

/// Blocks until a dependency's content differs from `snapshot` (any file event at all while the
/// scene is broken: the fix may be a file it could not name yet), and returns the dependencies
/// whose content changed. `None` when the watcher ends.
fn wait_for_change(
    rx: &mpsc::Receiver<notify::Result<notify::Event>>,
    snapshot: &Snapshot,
    failed: bool,
) -> Option<Vec<PathBuf>> {
    loop {
        let event = rx.recv().ok()?;
        if !is_change(&event) {
            continue;
        }
        while rx.recv_timeout(DEBOUNCE).is_ok() {}
        let changed = snapshot.changed(&Snapshot::take(&snapshot.files()));
        if failed || !changed.is_empty() {
            return Some(changed);
        }
    }
}

/// Writes, creations, removals and renames; not the reads our own hashing makes.
fn is_change(event: &notify::Result<notify::Event>) -> bool {
    match event {
        Ok(e) => matches!(
            e.kind,
            EventKind::Create(_) | EventKind::Modify(_) | EventKind::Remove(_) | EventKind::Any
        ),
        // An overflowed queue lost events: check the hashes.
        Err(_) => true,
    }
}

/// Opens `url` in the desktop's browser; failing that, says how to open it.
fn open_browser(url: &str) {
    let opener = if cfg!(target_os = "macos") {
        "open"
    } else if cfg!(windows) {
        "explorer"
    } else {
        "xdg-open"
    };
    let started = std::process::Command::new(opener)
        .arg(url)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn();
    if started.is_err() {
        eprintln!("rtc watch: cannot start `{opener}`; open {url} in a browser");
    }
}
