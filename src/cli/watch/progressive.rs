//! One progressive render of an evaluated scene for the watch page: a coarse preview (pixels
//! several times larger, one sample each) within a fraction of a second, then full resolution
//! with one sample per pixel, then the scene's own sampling when it asks for more. A newer
//! edit bumps the generation counter, which the renderer polls between bands of rows, so the
//! render in progress stops and its frames are never shown.

use std::sync::Mutex;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

use rtc::diag::Diagnostic;
use rtc::ir::{Camera, Sampling, Scene};
use rtc::opt::{Prepared, Quality};
use rtc::source::SourceMap;
use serde_json::json;

use super::html;
use super::server::Hub;

/// The preview's longer side is at most this many pixels.
const PREVIEW_SIZE: u32 = 128;

/// How often the page hears about progress.
const PROGRESS_EVERY: Duration = Duration::from_millis(100);

/// What a render job shares with the watch loop.
pub(crate) struct Job<'a> {
    /// The page.
    pub(crate) hub: &'a Hub,
    /// The latest generation; the job is stale once it differs from `generation`.
    pub(crate) current: &'a AtomicU64,
    /// This job's generation.
    pub(crate) generation: u64,
    /// Numbers the frames shown on the page.
    pub(crate) frames: &'a AtomicU64,
    /// Worker threads (0 = all cores).
    pub(crate) threads: usize,
}

/// One pass of the progressive render.
struct Stage {
    name: &'static str,
    camera: Camera,
    quality: Quality,
}

impl Job<'_> {
    fn stale(&self) -> bool {
        self.current.load(Ordering::SeqCst) != self.generation
    }

    /// Prepares and renders `scene` in stages, publishing diagnostics, progress and frames.
    /// `warnings` are the evaluation's, shown with the preparation's.
    pub(crate) fn run(&self, scene: &Scene, sources: &SourceMap, warnings: Vec<Diagnostic>) {
        let mut prepared = match rtc::opt::prepare(scene) {
            Ok(p) => p,
            Err(diags) => {
                let mut all = warnings;
                all.extend(diags.items);
                return self.diagnostics(&all, sources);
            }
        };
        let mut all = warnings;
        all.extend(prepared.warnings().iter().cloned());
        self.diagnostics(&all, sources);
        let stages = plan(&prepared);
        let full = (scene.camera.width, scene.camera.height);
        for (i, stage) in stages.iter().enumerate() {
            if self.stale() {
                return;
            }
            let last = i + 1 == stages.len();
            if let Err(d) = self.render_stage(&mut prepared, stage, full, last) {
                if !self.stale() {
                    all.push(d);
                    self.diagnostics(&all, sources);
                }
                return;
            }
        }
    }

    /// Renders one stage and shows it; `full` is the size the page shows every stage at.
    fn render_stage(
        &self,
        prepared: &mut Prepared,
        stage: &Stage,
        full: (u32, u32),
        last: bool,
    ) -> Result<(), Diagnostic> {
        prepared.set_camera(stage.camera.clone())?;
        prepared.set_quality(stage.quality)?;
        let progress = StageProgress {
            job: self,
            stage: stage.name,
            start: Instant::now(),
            total: AtomicU64::new(0),
            done: AtomicU64::new(0),
            last_report: Mutex::new(Instant::now()),
        };
        let options = rtc::render::RenderOptions {
            threads: self.threads,
            ..Default::default()
        };
        let film = rtc::render::render(prepared, &options, &progress)?;
        let seconds = progress.start.elapsed().as_secs_f64();
        let mut png = Vec::new();
        film.to_image()
            .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
            .map_err(|e| {
                Diagnostic::new(
                    rtc::diag::Severity::Error,
                    rtc::diag::IO_ERROR,
                    None,
                    format!("cannot encode the frame: {e}"),
                )
            })?;
        if self.stale() {
            return Ok(());
        }
        let s = &film.stats;
        let rays = s.camera_rays + s.secondary_rays + s.shadow_rays;
        let n = self.frames.fetch_add(1, Ordering::SeqCst) + 1;
        self.hub.set_frame(n, png);
        self.hub.publish(
            "frame",
            &json!({
                "n": n,
                "stage": if last { "final" } else { stage.name },
                "width": stage.camera.width,
                "height": stage.camera.height,
                "full_width": full.0,
                "full_height": full.1,
                "seconds": seconds,
                "rays": rays,
                "rays_per_second": rays as f64 / seconds.max(1e-9),
            }),
        );
        self.hub.publish(
            "progress",
            &json!({ "stage": stage.name, "fraction": 1.0, "eta_seconds": 0.0, "done": last }),
        );
        Ok(())
    }

    /// Publishes the current findings (empty when the scene is clean: the page clears them).
    pub(crate) fn diagnostics(&self, diags: &[Diagnostic], sources: &SourceMap) {
        if self.stale() {
            return;
        }
        let errors = diags.iter().filter(|d| d.is_error()).count();
        self.hub.publish(
            "diagnostics",
            &json!({
                "errors": errors,
                "warnings": diags.len() - errors,
                "html": html::diagnostics(diags, sources),
            }),
        );
    }
}

/// The stages for a prepared scene: a preview when the image is larger than [`PREVIEW_SIZE`],
/// full resolution at one sample per pixel, and the scene's own sampling when it differs.
fn plan(prepared: &Prepared) -> Vec<Stage> {
    let camera = prepared.camera().clone();
    let own = Quality::of(prepared.settings());
    let single = Quality {
        sampling: Sampling::Grid { factor: 1 },
        ..own
    };
    let mut stages = Vec::new();
    let factor = camera.width.max(camera.height).div_ceil(PREVIEW_SIZE);
    if factor > 1 {
        stages.push(Stage {
            name: "preview",
            camera: camera.coarser(factor),
            quality: single,
        });
    }
    stages.push(Stage {
        name: "full",
        camera: camera.clone(),
        quality: single,
    });
    if own != single {
        stages.push(Stage {
            name: "refined",
            camera,
            quality: own,
        });
    }
    stages
}

/// Progress of one stage, reported to the page at most every [`PROGRESS_EVERY`].
struct StageProgress<'a> {
    job: &'a Job<'a>,
    stage: &'static str,
    start: Instant,
    total: AtomicU64,
    done: AtomicU64,
    last_report: Mutex<Instant>,
}

impl rtc::render::Progress for StageProgress<'_> {
    fn start(&self, rows: u64) {
        self.total.store(rows, Ordering::SeqCst);
    }

    fn advance(&self, rows: u64) {
        let done = self.done.fetch_add(rows, Ordering::SeqCst) + rows;
        let Ok(mut last) = self.last_report.try_lock() else {
            return;
        };
        if last.elapsed() < PROGRESS_EVERY || self.job.stale() {
            return;
        }
        *last = Instant::now();
        let total = self.total.load(Ordering::SeqCst).max(1);
        let fraction = done as f64 / total as f64;
        let elapsed = self.start.elapsed().as_secs_f64();
        let eta = (fraction > 0.0).then(|| elapsed * (1.0 - fraction) / fraction);
        self.job.hub.publish(
            "progress",
            &json!({ "stage": self.stage, "fraction": fraction, "eta_seconds": eta, "done": false }),
        );
    }

    fn cancelled(&self) -> bool {
        self.job.stale()
    }
}
