//! `rtc accuracy`: what each quality knob of a scene buys and costs. The scene is rendered at a
//! converged reference setting, then at a ladder of settings per knob the scene uses (the
//! others at the scene's own values) and at a joint product of the knobs; every point gets its
//! median wall time, its rays and its error against the reference ([`crate::metrics`]), and the
//! points no other beats on both time and error form the Pareto front.
//!
//! - [`knob`]: the knobs, their ladders, the reference setting, `render { ... }` text.
//! - [`scale`]: sweeping at a reduced resolution.
//! - [`reference`]: rendering, caching or reading the reference; its noise.
//! - [`measure`]: one setting's time, rays and errors over seeds and repeats.
//! - [`sweep`]: the plan and the loop (cancellable: the points measured so far are kept).
//! - [`report`]: the result, the recommendations and the JSON document.
//!
//! The library prints nothing: the CLI draws the progress bar, the table, the plot and the map.

pub mod knob;
pub mod measure;
pub mod reference;
pub mod report;
pub mod scale;
pub mod sweep;

use std::path::PathBuf;

use crate::diag::{Diagnostic, Diagnostics};
use crate::ir::Scene;
use crate::render::Region;

pub use knob::Knob;
pub(crate) use knob::Setting;
pub use measure::MeasureOptions;
pub use report::{Metric, Report};
pub use sweep::SweepProgress;

/// A `--reference` image is not the size the sweep renders.
const REFERENCE_SIZE: &str = "rtc::accuracy::reference_size";

/// The sweep was cancelled before the reference was done: nothing was measured.
pub const NOTHING_MEASURED: &str = "rtc::accuracy::cancelled";

/// Where the reference comes from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ReferenceChoice {
    /// Rendered at the reference setting, cached in this directory when given.
    Render {
        /// The cache directory (`None`: no cache).
        cache_dir: Option<PathBuf>,
    },
    /// This image (EXR: linear; PNG and others: sRGB bytes) at the swept size.
    File(PathBuf),
}

/// Everything a study needs besides the scene.
#[derive(Clone, Debug, PartialEq)]
pub struct StudyOptions {
    /// The scene's name in the report.
    pub scene_name: String,
    /// The factor per side of the swept resolution; `None` picks one under `max_pixels`.
    pub scale: Option<f64>,
    /// The pixel budget of an automatic scale ([`scale::DEFAULT_MAX_PIXELS`]; with a region,
    /// of the region's pixels).
    pub max_pixels: u64,
    /// Sweep only this sub-rectangle, in the scene's full-resolution pixels (scaled with the
    /// image); `None`: the whole image.
    pub region: Option<Region>,
    /// The reference.
    pub reference: ReferenceChoice,
    /// Seeds, repeats, threads.
    pub measure: MeasureOptions,
    /// Measure the joint product too (the Pareto front over several knobs at once).
    pub joint: bool,
    /// The metric of the front and the recommendations.
    pub metric: Metric,
    /// `--target-error`: recommend the cheapest setting at most this wrong.
    pub target_error: Option<f64>,
    /// `--time`: recommend the most accurate setting whose full render takes at most this.
    pub time: Option<f64>,
}

/// Runs the whole study on an evaluated scene: scale, prepare, reference, sweep, report.
pub fn study(
    scene: &Scene,
    options: &StudyOptions,
    progress: &dyn SweepProgress,
) -> Result<Report, Diagnostics> {
    let one = |d: Diagnostic| Diagnostics {
        items: vec![d],
        ..Diagnostics::default()
    };
    let mut scene = scene.clone();
    if let Some(r) = options.region {
        r.check(scene.camera.width, scene.camera.height)
            .map_err(one)?;
    }
    let (w, h) = options
        .region
        .map_or((scene.camera.width, scene.camera.height), |r| {
            (r.width, r.height)
        });
    let factor = options
        .scale
        .unwrap_or_else(|| scale::auto_scale(w, h, options.max_pixels));
    let mut size = scale::scale_scene(&mut scene, factor);
    size.region = options
        .region
        .map(|r| r.scaled(factor, size.width, size.height));
    let measure = MeasureOptions {
        region: size.region,
        ..options.measure
    };
    let mut prepared = crate::opt::prepare(&scene)?;
    let own = Setting::of(&prepared);
    let own_lights = prepared.light_samples();
    let effects = prepared.effects();
    let knobs = knob::used_knobs(&effects);
    let own_light_max = own_lights.iter().flatten().copied().max().unwrap_or(1);
    let own_gloss_max = prepared
        .materials()
        .iter()
        .filter(|m| m.gloss > 0.0)
        .map(|m| m.gloss_samples)
        .max()
        .unwrap_or(1);
    let ref_setting = knob::reference_setting(&knobs, &own, own_light_max, own_gloss_max);
    let random = prepared.random();
    let planned = sweep::plan(&knobs, &own, options.joint);
    let seeds = options.measure.seeds;

    progress.begin(
        planned.len() as u64 * sweep::renders_per_point(random, &measure)
            + if random { 2 } else { 1 },
    );
    let (reference, hash) = match &options.reference {
        ReferenceChoice::File(path) => {
            let (w, h) = size.rendered();
            (reference::from_file(path, w, h).map_err(one)?, None)
        }
        ReferenceChoice::Render { cache_dir } => {
            progress.point(&format!("reference ({})", ref_setting.label()));
            ref_setting.apply(&mut prepared, &own_lights).map_err(one)?;
            let hash = reference::content_hash(&scene, &ref_setting, seeds, size.region);
            let cancel = sweep::CancelOnly(progress);
            let r = reference::rendered(
                &mut prepared,
                &measure,
                cache_dir.as_deref().map(|d| (d, hash.as_str())),
                &cancel,
            )
            .map_err(|d| {
                if d.code == crate::render::CANCELLED {
                    one(Diagnostic::new(
                        crate::diag::Severity::Error,
                        NOTHING_MEASURED,
                        None,
                        "cancelled while rendering the reference: nothing was measured",
                    ))
                } else {
                    one(d)
                }
            })?;
            for _ in 0..if random { 2 } else { 1 } {
                progress.render_done();
            }
            (r, Some(hash))
        }
    };
    let reference_setting = match reference.source {
        reference::Source::File(_) => None,
        _ => Some(ref_setting),
    };
    let measured = sweep::run(
        &mut prepared,
        &own_lights,
        &planned,
        &reference,
        &measure,
        progress,
    )
    .map_err(one)?;
    let mut report = Report {
        scene: options.scene_name.clone(),
        size,
        threads: options.measure.threads,
        repeat: options.measure.repeat.max(1),
        seeds,
        stochastic: random,
        effects: effects.names(),
        knobs,
        reference: report::ReferenceInfo {
            source: reference.source.clone(),
            setting: reference_setting,
            noise_rmse: reference.noise.map(|_| reference.noise_rmse()),
            noise_flip: reference.noise.map(|n| n.flip_between_runs),
            hash,
            cache_notes: reference.notes.clone(),
        },
        metric: options.metric,
        points: measured
            .points
            .into_iter()
            .map(|(sweeps, measurement)| report::Point {
                sweeps,
                measurement,
                pareto: false,
            })
            .collect(),
        complete: measured.complete,
        recommendations: Vec::new(),
    };
    report.mark_pareto();
    if let Some(e) = options.target_error {
        let r = report.recommend_error(e);
        report.recommendations.push(r);
    }
    if let Some(t) = options.time {
        let r = report.recommend_time(t);
        report.recommendations.push(r);
    }
    // Asked for nothing: the cheapest setting at the scene's own error (issue 34).
    if options.target_error.is_none()
        && options.time.is_none()
        && let Some(own) = report.own()
    {
        let mut r = report.recommend_error(report.metric.of(&own.measurement.error));
        r.goal = "scene_error";
        report.recommendations.push(r);
    }
    Ok(report)
}
