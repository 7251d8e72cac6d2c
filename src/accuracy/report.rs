//! The study's result: the measured points with their Pareto front, the reference, what the
//! sweep used, recommendations, and the JSON document (schema `rtc-accuracy/1`, documented in
//! docs/accuracy.md and pinned by tests/accuracy.rs).

use serde_json::{Value, json};

use crate::ir::Sampling;
use crate::metrics::pareto::pareto_front;

use super::knob::{Knob, Setting};
use super::measure::{Errors, Measurement};
use super::reference::Source;
use super::scale::SweepSize;
use super::sweep::Sweep;

/// The JSON document's `schema` value; bumped when a field changes meaning or goes away.
const SCHEMA: &str = "rtc-accuracy/1";

/// The error metric recommendations and the plot use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Metric {
    /// Mean ꟻLIP.
    Flip,
    /// RMSE in linear light.
    Rmse,
    /// Relative MSE.
    RelMse,
}

impl Metric {
    /// The metric's value among `e`.
    pub fn of(self, e: &Errors) -> f64 {
        match self {
            Metric::Flip => e.flip_mean,
            Metric::Rmse => e.rmse,
            Metric::RelMse => e.rel_mse,
        }
    }

    /// The name in JSON.
    fn key(self) -> &'static str {
        match self {
            Metric::Flip => "flip",
            Metric::Rmse => "rmse",
            Metric::RelMse => "rel_mse",
        }
    }

    /// The name on the plot's axis and in messages.
    pub fn label(self) -> &'static str {
        match self {
            Metric::Flip => "mean ꟻLIP",
            Metric::Rmse => "RMSE (linear)",
            Metric::RelMse => "relMSE (linear)",
        }
    }
}

/// What the reference was and how noisy.
#[derive(Clone, Debug, PartialEq)]
pub struct ReferenceInfo {
    /// Rendered, cached or a file.
    pub source: Source,
    /// The reference setting (`None` for a file).
    pub setting: Option<Setting>,
    /// The RMSE of the reference against its own expectation (`None` when unknown).
    pub noise_rmse: Option<f64>,
    /// The mean ꟻLIP between its two seeds' renders (`None` when unknown).
    pub noise_flip: Option<f64>,
    /// The content hash naming the cached files (`None` for a file).
    pub(crate) hash: Option<String>,
    /// Problems with the cache, none fatal ([`super::reference::Reference::notes`]).
    pub cache_notes: Vec<String>,
}

/// One measured setting in the report.
#[derive(Clone, Debug)]
pub struct Point {
    /// The sweeps it belongs to.
    pub sweeps: Vec<Sweep>,
    /// What was measured.
    pub measurement: Measurement,
    /// On the Pareto front of (time, the report's metric).
    pub pareto: bool,
}

/// A recommended setting.
#[derive(Clone, Debug, PartialEq)]
pub struct Recommendation {
    /// `target_error`, `time`, or `scene_error` (asked for neither: the cheapest setting at
    /// the scene's own error).
    pub goal: &'static str,
    /// The asked error or seconds.
    pub value: f64,
    /// The point's index, `None` when no measured setting meets the goal.
    pub point: Option<usize>,
    /// Predicted seconds of a render at the scene's full resolution.
    pub predicted_seconds: Option<f64>,
    /// Predicted error (the report's metric, as measured at the swept size).
    pub predicted_error: Option<f64>,
}

/// A whole study.
#[derive(Clone, Debug)]
pub struct Report {
    /// The scene file as given.
    pub scene: String,
    /// The swept resolution.
    pub size: SweepSize,
    /// Worker threads (0 = all cores).
    pub(crate) threads: usize,
    /// Renders per seed per point.
    pub repeat: u32,
    /// The seeds of stochastic settings (the first alone for the rest).
    pub seeds: [u64; 2],
    /// Whether the scene draws random numbers (lens or area light).
    pub stochastic: bool,
    /// The effects the scene uses (`opt::Effects` names).
    pub effects: Vec<&'static str>,
    /// The knobs swept.
    pub knobs: Vec<Knob>,
    /// The reference.
    pub reference: ReferenceInfo,
    /// The metric of the Pareto front, the plot and the recommendations.
    pub metric: Metric,
    /// The points in measuring order (the scene's own first).
    pub points: Vec<Point>,
    /// False when the sweep was interrupted.
    pub complete: bool,
    /// The recommendations asked for.
    pub recommendations: Vec<Recommendation>,
}

/// The reference is too noisy when its own RMSE is more than this share of the smallest
/// measured RMSE: the best settings' errors are then partly the reference's noise.
pub const NOISY_REFERENCE_SHARE: f64 = 0.5;

impl Report {
    /// Marks the Pareto front (over every point, by time and the report's metric).
    pub(crate) fn mark_pareto(&mut self) {
        let pairs: Vec<(f64, f64)> = self
            .points
            .iter()
            .map(|p| (p.measurement.seconds, self.metric.of(&p.measurement.error)))
            .collect();
        let front = pareto_front(&pairs);
        for (i, p) in self.points.iter_mut().enumerate() {
            p.pareto = front.contains(&i);
        }
    }

    /// The point of the scene's own setting, if it was measured.
    pub fn own(&self) -> Option<&Point> {
        self.points
            .iter()
            .find(|p| p.sweeps.contains(&Sweep::Scene))
    }

    /// The predicted full-resolution time of a point.
    pub fn full_seconds(&self, p: &Point) -> f64 {
        p.measurement.seconds * self.size.pixel_ratio()
    }

    /// Whether the reference's noise is large against the smallest measured RMSE.
    pub fn reference_too_noisy(&self) -> bool {
        let smallest = self
            .points
            .iter()
            .map(|p| p.measurement.error.rmse)
            .fold(f64::INFINITY, f64::min);
        self.reference
            .noise_rmse
            .is_some_and(|n| smallest.is_finite() && n > NOISY_REFERENCE_SHARE * smallest)
    }

    /// The cheapest measured setting whose error (the report's metric) is at most `error`.
    pub(crate) fn recommend_error(&self, error: f64) -> Recommendation {
        let best = self
            .points
            .iter()
            .enumerate()
            .filter(|(_, p)| self.metric.of(&p.measurement.error) <= error)
            .min_by(|a, b| a.1.measurement.seconds.total_cmp(&b.1.measurement.seconds));
        self.recommendation("target_error", error, best.map(|(i, _)| i))
    }

    /// The most accurate measured setting whose predicted full-resolution time is at most
    /// `seconds`.
    pub(crate) fn recommend_time(&self, seconds: f64) -> Recommendation {
        let best = self
            .points
            .iter()
            .enumerate()
            .filter(|(_, p)| self.full_seconds(p) <= seconds)
            .min_by(|a, b| {
                self.metric
                    .of(&a.1.measurement.error)
                    .total_cmp(&self.metric.of(&b.1.measurement.error))
            });
        self.recommendation("time", seconds, best.map(|(i, _)| i))
    }

    fn recommendation(
        &self,
        goal: &'static str,
        value: f64,
        point: Option<usize>,
    ) -> Recommendation {
        let p = point.map(|i| &self.points[i]);
        Recommendation {
            goal,
            value,
            point,
            predicted_seconds: p.map(|p| self.full_seconds(p)),
            predicted_error: p.map(|p| self.metric.of(&p.measurement.error)),
        }
    }

    /// The report as a JSON document (schema [`SCHEMA`]).
    pub fn to_json(&self) -> Value {
        let points: Vec<Value> = self
            .points
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let m = &p.measurement;
                json!({
                    "id": i,
                    "sweeps": p.sweeps.iter().map(|s| s.key()).collect::<Vec<_>>(),
                    "setting": setting_json(&m.setting),
                    "render_block": m.setting.render_block(),
                    "seconds": m.seconds,
                    "seconds_runs": m.runs,
                    "predicted_full_seconds": self.full_seconds(p),
                    "rays": m.rays,
                    "flip_mean": m.error.flip_mean,
                    "flip_worst_1pct": m.error.flip_worst,
                    "rmse": m.error.rmse,
                    "rel_mse": m.error.rel_mse,
                    "squared_error_worst_1pct": m.error.squared_error_worst,
                    "flip_mean_spread": m.spread.flip_mean,
                    "rmse_spread": m.spread.rmse,
                    "noise_rmse": m.noise_rmse,
                    "pareto": p.pareto,
                })
            })
            .collect();
        let (source, files) = match &self.reference.source {
            Source::Rendered => ("rendered", Vec::new()),
            Source::Cached(files) => ("cache", files.clone()),
            Source::File(f) => ("file", vec![f.clone()]),
        };
        json!({
            "schema": SCHEMA,
            "scene": self.scene,
            "complete": self.complete,
            "size": {
                "width": self.size.width,
                "height": self.size.height,
                "full_width": self.size.full_width,
                "full_height": self.size.full_height,
                "scale": self.size.scale,
                "region": self.size.region.map(|r| json!({
                    "x": r.x,
                    "y": r.y,
                    "width": r.width,
                    "height": r.height,
                })),
            },
            "threads": self.threads,
            "repeat": self.repeat,
            "seeds": self.seeds,
            "stochastic": self.stochastic,
            "effects": self.effects,
            "knobs": self.knobs.iter().map(|k| k.key()).collect::<Vec<_>>(),
            "metric": self.metric.key(),
            "reference": {
                "source": source,
                "files": files.iter().map(|f| f.display().to_string()).collect::<Vec<_>>(),
                "hash": self.reference.hash,
                "setting": self.reference.setting.as_ref().map(setting_json),
                "noise_rmse": self.reference.noise_rmse,
                "noise_flip": self.reference.noise_flip,
                "too_noisy": self.reference_too_noisy(),
            },
            "scene_point": self.points.iter().position(|p| p.sweeps.contains(&Sweep::Scene)),
            "points": points,
            "pareto_front": self.points.iter().enumerate().filter(|(_, p)| p.pareto).map(|(i, _)| i).collect::<Vec<_>>(),
            "recommendations": self.recommendations.iter().map(|r| json!({
                "goal": r.goal,
                "value": r.value,
                "point": r.point,
                "render_block": r.point.map(|i| self.points[i].measurement.setting.render_block()),
                "predicted_seconds": r.predicted_seconds,
                "predicted_error": r.predicted_error,
            })).collect::<Vec<_>>(),
        })
    }
}

/// A setting as JSON: `sampling` is `{"grid": f}` or `{"adaptive": {min, max, threshold}}`.
fn setting_json(s: &Setting) -> Value {
    let sampling = match s.sampling {
        Sampling::Grid { factor } => json!({ "grid": factor }),
        Sampling::Adaptive {
            min,
            max,
            threshold,
        } => json!({ "adaptive": { "min": min, "max": max, "threshold": threshold } }),
    };
    json!({
        "sampling": sampling,
        "max_depth": s.max_depth,
        "light_samples": s.light_samples,
        "gloss_samples": s.gloss_samples,
        "cutoff": s.cutoff,
    })
}
