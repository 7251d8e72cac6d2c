//! Measuring one setting: render it `repeat` times under each seed, time every render, count its
//! rays, and compare each seed's image with the reference.

use std::time::Instant;

use crate::diag::Diagnostic;
use crate::metrics::{self, Comparison, FlipMap, LinearRgb};
use crate::opt::Prepared;
use crate::render::{self, Progress, Region, RenderOptions};

use super::knob::Setting;

/// What one setting measured.
#[derive(Clone, Debug, PartialEq)]
pub struct Measurement {
    /// The setting.
    pub setting: Setting,
    /// The median wall time of one render, in seconds (over every seed and repeat).
    pub seconds: f64,
    /// Every render's wall time, in seconds, in the order they ran.
    pub runs: Vec<f64>,
    /// Rays traced by one render (camera + secondary + shadow; seed 0's; machine-independent).
    pub rays: u64,
    /// The metrics, each the mean over the seeds.
    pub error: Errors,
    /// The sample standard deviation over the seeds of mean ꟻLIP and of RMSE (0 with one seed).
    pub spread: Spread,
    /// The noise RMSE from the first two seeds' images (`metrics::noise`); `None` with one seed.
    pub noise_rmse: Option<f64>,
    /// The ꟻLIP map of the first seed's image.
    pub flip_map: FlipMap,
}

/// The error metrics of one setting against the reference.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Errors {
    /// Mean ꟻLIP.
    pub flip_mean: f64,
    /// Mean ꟻLIP of the worst 1% of pixels.
    pub flip_worst: f64,
    /// RMSE in linear light.
    pub rmse: f64,
    /// Relative MSE in linear light.
    pub(crate) rel_mse: f64,
    /// Mean squared error of the worst 1% of pixels.
    pub(crate) squared_error_worst: f64,
}

/// How much the error varies with the seed.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Spread {
    /// Standard deviation of mean ꟻLIP over the seeds.
    pub flip_mean: f64,
    /// Standard deviation of RMSE over the seeds.
    pub(crate) rmse: f64,
}

/// How to measure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MeasureOptions {
    /// Renders per seed; the time is the median of all.
    pub repeat: u32,
    /// The seeds (the first is the scene's own); a setting without randomness uses only it.
    pub seeds: [u64; 2],
    /// Worker threads (0 = all cores).
    pub threads: usize,
    /// Render only this region of the (swept) image; `None`: all of it. [`super::study`] sets
    /// it from [`super::StudyOptions::region`].
    pub region: Option<Region>,
}

/// A render's linear colour as `f32` RGB triples, rows from the top.
pub fn linear_rgb(film: &render::film::Film) -> Vec<f32> {
    film.color()
        .iter()
        .flat_map(|c| [c.x as f32, c.y as f32, c.z as f32])
        .collect()
}

/// Renders `scene` (or the `options.region` of it) once with its current settings and seed
/// `seed`: the image, its wall time and its rays.
pub(crate) fn render_once(
    scene: &mut Prepared,
    seed: u64,
    options: &MeasureOptions,
    progress: &dyn Progress,
) -> Result<(Vec<f32>, f64, u64), Diagnostic> {
    scene.set_seed(seed);
    let start = Instant::now();
    let film = render::render_region(
        scene,
        &RenderOptions {
            threads: options.threads,
            ..Default::default()
        },
        options.region,
        progress,
    )?;
    let seconds = start.elapsed().as_secs_f64();
    let s = film.stats;
    Ok((
        linear_rgb(&film),
        seconds,
        s.camera_rays + s.secondary_rays + s.shadow_rays,
    ))
}

/// Measures `scene` (already set to `setting`) against `reference` (same size, linear RGB).
/// `after_render` runs after each render (the progress bar's step).
pub(crate) fn measure(
    scene: &mut Prepared,
    setting: Setting,
    reference: LinearRgb<'_>,
    options: &MeasureOptions,
    progress: &dyn Progress,
    after_render: &dyn Fn(),
) -> Result<Measurement, Diagnostic> {
    let seeds: &[u64] = if scene.random() {
        &options.seeds
    } else {
        &options.seeds[..1]
    };
    let (w, h) = (reference.width(), reference.height());
    let mut runs = Vec::new();
    let mut rays = 0;
    let mut images = Vec::new();
    for (i, &seed) in seeds.iter().enumerate() {
        for r in 0..options.repeat.max(1) {
            let (image, seconds, n) = render_once(scene, seed, options, progress)?;
            runs.push(seconds);
            after_render();
            if i == 0 && r == 0 {
                rays = n;
            }
            if r == 0 {
                images.push(image);
            }
        }
    }
    let comparisons = images
        .iter()
        .map(|img| metrics::compare(LinearRgb::new(w, h, img)?, reference))
        .collect::<Result<Vec<Comparison>, Diagnostic>>()?;
    let noise_rmse = match images.as_slice() {
        [a, b, ..] => {
            Some(metrics::noise(LinearRgb::new(w, h, a)?, LinearRgb::new(w, h, b)?)?.rmse)
        }
        _ => None,
    };
    let mean = |f: fn(&Comparison) -> f64| {
        comparisons.iter().map(f).sum::<f64>() / comparisons.len() as f64
    };
    let error = Errors {
        flip_mean: mean(|c| c.flip_mean),
        flip_worst: mean(|c| c.flip_worst),
        rmse: mean(|c| c.rmse),
        rel_mse: mean(|c| c.rel_mse),
        squared_error_worst: mean(|c| c.squared_error_worst),
    };
    let spread = Spread {
        flip_mean: std_dev(comparisons.iter().map(|c| c.flip_mean)),
        rmse: std_dev(comparisons.iter().map(|c| c.rmse)),
    };
    let flip_map = comparisons
        .into_iter()
        .next()
        .map(|c| c.flip_map)
        .expect("at least one seed was rendered");
    Ok(Measurement {
        setting,
        seconds: median(&runs),
        runs,
        rays,
        error,
        spread,
        noise_rmse,
        flip_map,
    })
}

/// The median (the mean of the middle two for an even count); 0 for none.
fn median(values: &[f64]) -> f64 {
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    match v.len() {
        0 => 0.0,
        n if n % 2 == 1 => v[n / 2],
        n => 0.5 * (v[n / 2 - 1] + v[n / 2]),
    }
}

/// The sample standard deviation (n − 1); 0 for fewer than two values.
fn std_dev(values: impl Iterator<Item = f64>) -> f64 {
    let v: Vec<f64> = values.collect();
    if v.len() < 2 {
        return 0.0;
    }
    let m = v.iter().sum::<f64>() / v.len() as f64;
    (v.iter().map(|x| (x - m) * (x - m)).sum::<f64>() / (v.len() - 1) as f64).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_and_spread() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&[4.0, 1.0, 2.0, 3.0]), 2.5);
        assert_eq!(median(&[]), 0.0);
        assert_eq!(std_dev([1.0].into_iter()), 0.0);
        assert!((std_dev([1.0, 3.0].into_iter()) - 2f64.sqrt()).abs() < 1e-12);
    }
}
