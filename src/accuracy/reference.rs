//! The reference a sweep is measured against: the scene rendered at the reference setting under
//! two seeds (their mean is the reference; their difference estimates its noise), or an image
//! the user gives. Rendered references are cached by the scene's content hash.
//!
//! Cache: `DIR/<hash>-seed<N>.exr`, one linear-RGB EXR per seed (readable by any EXR viewer),
//! where `DIR` is chosen by the caller (the CLI: `$RTC_CACHE_DIR`, else
//! `$XDG_CACHE_HOME/rtc/accuracy`, else `~/.cache/rtc/accuracy`). The hash covers the evaluated
//! scene (its IR with the quality knobs set to the reference's, so changing the scene's own
//! knobs keeps the cache), the swept resolution, the seeds and rtc's version; it does not read
//! mesh or texture files, so after editing one in place pass `--no-cache`.

use std::path::{Path, PathBuf};

use image::{ImageBuffer, Rgb};

use crate::diag::{Diagnostic, IO_ERROR, Severity};
use crate::ir::Scene;
use crate::metrics::{self, LinearRgb, NoiseEstimate};
use crate::opt::Prepared;
use crate::render::{Progress, Region};

use super::knob::Setting;
use super::measure::{MeasureOptions, render_once};

/// Where the reference came from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Source {
    /// Rendered now (and cached when a cache directory was given).
    Rendered,
    /// Read from the cache (these files).
    Cached(Vec<PathBuf>),
    /// The user's `--reference` file.
    File(PathBuf),
}

/// A reference image and what is known of its noise.
#[derive(Clone, Debug, PartialEq)]
pub struct Reference {
    /// Width in pixels.
    width: u32,
    /// Height in pixels.
    height: u32,
    /// Linear RGB, rows from the top.
    pub data: Vec<f32>,
    /// Where it came from.
    pub source: Source,
    /// The noise of one seed's render (`None` for a given file or a scene without randomness;
    /// the mean of two seeds has this RMSE divided by √2).
    pub(crate) noise: Option<NoiseEstimate>,
    /// What went wrong with the cache, which never fails the run: an entry that failed its
    /// checksum or held non-finite values (a miss: rendered again), one that could not be
    /// written.
    pub notes: Vec<String>,
}

impl Reference {
    /// The image as a metrics view.
    pub(crate) fn view(&self) -> Result<LinearRgb<'_>, Diagnostic> {
        LinearRgb::new(self.width, self.height, &self.data)
    }

    /// The RMSE the reference has against its own expectation (its noise), 0 when noiseless
    /// or unknown.
    pub(crate) fn noise_rmse(&self) -> f64 {
        self.noise
            .map_or(0.0, |n| n.rmse / std::f64::consts::SQRT_2)
    }
}

/// The content hash naming a cached reference: FNV-1a (64 bits) over the scene's IR with the
/// reference quality, the resolution, the region, the seeds and rtc's version.
pub(crate) fn content_hash(
    scene: &Scene,
    reference: &Setting,
    seeds: [u64; 2],
    region: Option<Region>,
) -> String {
    let mut s = scene.clone();
    s.settings.sampling = reference.sampling;
    s.settings.max_depth = reference.max_depth;
    s.settings.cutoff = reference.cutoff;
    if let Some(n) = reference.gloss_samples {
        for m in &mut s.materials {
            m.gloss_samples = n;
        }
    }
    s.settings.seed = 0;
    s.settings.output = None;
    s.settings.output_span = None;
    let text = format!(
        "rtc {} reference {:?} seeds {:?} scene {:?}{}",
        env!("CARGO_PKG_VERSION"),
        reference,
        seeds,
        s,
        // No text without a region, so the hashes of whole-image references stay as they were.
        region.map_or(String::new(), |r| format!(" region {}", r.text()))
    );
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in text.bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    format!("{h:016x}")
}

/// Renders the reference (two seeds when the scene draws random numbers; the image or its
/// `options.region`), or reads it from `cache` (a directory and the scene's content hash) and
/// writes it there after rendering. `scene` must already be set to the reference setting.
pub fn rendered(
    scene: &mut Prepared,
    options: &MeasureOptions,
    cache: Option<(&Path, &str)>,
    progress: &dyn Progress,
) -> Result<Reference, Diagnostic> {
    let (width, height) = options
        .region
        .map_or((scene.camera().width, scene.camera().height), |r| {
            (r.width, r.height)
        });
    let seeds = options.seeds;
    let used: &[u64] = if scene.random() { &seeds } else { &seeds[..1] };
    let files: Option<Vec<PathBuf>> = cache.map(|(dir, hash)| {
        used.iter()
            .map(|s| dir.join(format!("{hash}-seed{s}.exr")))
            .collect()
    });
    let mut notes = Vec::new();
    let cached = files.as_ref().and_then(|files| {
        let mut runs = Vec::new();
        for f in files {
            match read_cached(f, width, height) {
                Ok(run) => runs.push(run),
                Err(why) => {
                    notes.extend(why.map(|why| {
                        format!(
                            "the cached reference {} {why}: it is rendered again",
                            f.display()
                        )
                    }));
                    return None;
                }
            }
        }
        Some(runs)
    });
    let (runs, source) = match cached {
        Some(runs) => (runs, Source::Cached(files.clone().unwrap_or_default())),
        None => {
            let mut runs = Vec::new();
            for &seed in used {
                runs.push(render_once(scene, seed, options, progress)?.0);
            }
            if let Some(files) = &files {
                for (f, run) in files.iter().zip(&runs) {
                    if let Err(why) = write_cached(f, width, height, run) {
                        notes.push(format!(
                            "the reference could not be cached as {}: {why}",
                            f.display()
                        ));
                    }
                }
            }
            (runs, Source::Rendered)
        }
    };
    let noise = match runs.as_slice() {
        [a, b] => Some(metrics::noise(
            LinearRgb::new(width, height, a)?,
            LinearRgb::new(width, height, b)?,
        )?),
        _ => None,
    };
    let data = if let [a, b] = runs.as_slice() {
        a.iter().zip(b).map(|(x, y)| 0.5 * (x + y)).collect()
    } else {
        runs.into_iter().next().unwrap_or_default()
    };
    Ok(Reference {
        width,
        height,
        data,
        source,
        noise,
        notes,
    })
}

/// Reads a reference image: an EXR is linear light; any other format (PNG...) holds sRGB
/// bytes, decoded to linear light. It must be `width × height`.
pub(crate) fn from_file(path: &Path, width: u32, height: u32) -> Result<Reference, Diagnostic> {
    let is_exr = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("exr"));
    let data = if is_exr {
        read_exr(path, width, height)?
    } else {
        let img = image::open(path).map_err(|e| io_error(path, &e.to_string()))?;
        let rgb = img.to_rgb8();
        check_size(path, rgb.width(), rgb.height(), width, height)?;
        metrics::srgb::decode_all(rgb.as_raw())
    };
    Ok(Reference {
        width,
        height,
        data,
        source: Source::File(path.to_path_buf()),
        noise: None,
        notes: Vec::new(),
    })
}

fn read_exr(path: &Path, width: u32, height: u32) -> Result<Vec<f32>, Diagnostic> {
    let img = image::open(path).map_err(|e| io_error(path, &e.to_string()))?;
    let rgb = img.to_rgb32f();
    check_size(path, rgb.width(), rgb.height(), width, height)?;
    Ok(rgb.into_raw())
}

/// The checksum file of a cached reference: `X.exr` → `X.exr.sha256`.
fn checksum_path(path: &Path) -> PathBuf {
    path.with_extension("exr.sha256")
}

/// Reads a cached reference: `Err(None)` when there is none (a plain miss), `Err(Some(why))`
/// when there is one that cannot be trusted: its bytes do not match the checksum written with
/// it, it does not decode to the swept size, or it holds a value that is not finite.
fn read_cached(path: &Path, width: u32, height: u32) -> Result<Vec<f32>, Option<String>> {
    if !path.exists() {
        return Err(None);
    }
    let bytes = crate::source::read_regular(path, u64::MAX).map_err(|e| Some(e.to_string()))?;
    let sum = std::fs::read_to_string(checksum_path(path))
        .map_err(|_| Some("has no checksum file".to_string()))?;
    if sum.trim() != crate::opt::fingerprint::bytes(&bytes) {
        return Err(Some("does not match its checksum".into()));
    }
    let img = image::load_from_memory_with_format(&bytes, image::ImageFormat::OpenExr)
        .map_err(|e| Some(format!("cannot be decoded ({e})")))?;
    let rgb = img.to_rgb32f();
    if (rgb.width(), rgb.height()) != (width, height) {
        return Err(Some(format!("is {}×{} pixels", rgb.width(), rgb.height())));
    }
    let data = rgb.into_raw();
    if data.iter().any(|v| !v.is_finite()) {
        return Err(Some("holds a value that is not a finite number".into()));
    }
    Ok(data)
}

/// Writes a reference to the cache: the EXR and its checksum file, each through a temporary
/// file of a random name and a rename (removed on a failure such as a full disk, so no
/// partial file stays). The error says why, for a note.
fn write_cached(path: &Path, width: u32, height: u32, data: &[f32]) -> Result<(), String> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(|e| e.to_string())?;
    }
    let img: ImageBuffer<Rgb<f32>, Vec<f32>> = ImageBuffer::from_raw(width, height, data.to_vec())
        .ok_or("the image buffer has the wrong size")?;
    let mut bytes = std::io::Cursor::new(Vec::new());
    img.write_to(&mut bytes, image::ImageFormat::OpenExr)
        .map_err(|e| e.to_string())?;
    let bytes = bytes.into_inner();
    let write = crate::render::output::write_atomically;
    // The EXR first: a checksum file never describes bytes that are not there yet.
    write(path, &bytes).map_err(|d| d.message)?;
    let sum = crate::opt::fingerprint::bytes(&bytes) + "\n";
    write(&checksum_path(path), sum.as_bytes()).map_err(|d| d.message)
}

fn check_size(path: &Path, w: u32, h: u32, want_w: u32, want_h: u32) -> Result<(), Diagnostic> {
    if (w, h) == (want_w, want_h) {
        return Ok(());
    }
    Err(Diagnostic::new(
        Severity::Error,
        super::REFERENCE_SIZE,
        None,
        format!(
            "the reference {} is {w}×{h} pixels, the sweep renders {want_w}×{want_h}",
            path.display()
        ),
    )
    .with_help(format!(
        "give a {want_w}×{want_h} reference, or choose the sweep's size with --scale (and --region)"
    )))
}

fn io_error(path: &Path, what: &str) -> Diagnostic {
    Diagnostic::new(
        Severity::Error,
        IO_ERROR,
        None,
        format!("cannot use {}: {what}", path.display()),
    )
}
