//! Progressive rendering to an error or a time budget (`rtc render --target-error E`,
//! `--time T`): every pixel starts with 4 samples and doubles its samples, round by round, where
//! its error estimate is still too large.
//!
//! - **Samples.** Sample `i` of pixel (x, y) is point `i` of the pixel's own Owen-scrambled
//!   Sobol' sequence ([`Rng`]): its sub-pixel position, lens point and light points. A round
//!   adds the aligned block `[n, 2n)` to a pixel holding `n` samples, so every pixel always
//!   holds the first `4·2^level` points, a stratified set for any level.
//! - **Error estimate.** The two halves of a pixel's samples (`[0, n/2)` and `[n/2, n)`, the
//!   block just added) are two independent estimates of the pixel: `e² = mean_c ((a − b)/2)²`
//!   over the three channels, clamped to [0, 1], estimates the variance of their mean. The
//!   image's estimate is `sqrt(mean e²)`, comparable to the linear RMSE of `metrics`.
//! - **Refinement.** A round refines the pixels whose estimate, pooled as the largest over its
//!   3×3 neighbourhood (two halves of 2 samples can agree by chance across an edge), exceeds
//!   `max(E, estimate/2)`: the worst pixels first, then down to the target.
//! - **Reproduction.** A pixel's value depends only on its sample count (the blocks are summed
//!   in the same order whatever decided them), so the final [`SampleMap`] re-renders the same
//!   bytes without a clock or an estimate (`--samples-from`).

use super::context::Ctx;
use super::deal::LightShare;
use super::film::{Channel, Film, Stats};
use super::integrator::Integrator;
use super::progress::Progress;
use super::sampler::{Grid, Rng};
use super::shard::Rows;
use super::tiles;
use super::view::View;
use crate::diag::{Diagnostic, Severity};
use crate::ir::Color;
use crate::ir::limits::MAX_PIXEL_SAMPLES_PER_AXIS;
use crate::opt::Prepared;

/// Samples every pixel starts with.
const FIRST_SAMPLES: u32 = 4;

/// Most doublings of a pixel: 4·2¹⁰ = 4096 samples, the 64×64 of `ir::limits`.
const MAX_LEVEL: u8 =
    (MAX_PIXEL_SAMPLES_PER_AXIS * MAX_PIXEL_SAMPLES_PER_AXIS / FIRST_SAMPLES).ilog2() as u8;

/// The Sobol' stream of sub-pixel positions (distinct from the lens's, 0, and from every
/// area-light stream, whose bits 16..20 are 0).
const POSITION_STREAM: u32 = 0x7fff_fffe;

/// When to stop refining.
#[derive(Clone, Debug, PartialEq)]
pub enum Budget {
    /// Until the image's error estimate is at most this (or the caller stops the rounds).
    TargetError(f64),
    /// Exactly these sample counts (a reproduction).
    Samples(SampleMap),
}

/// Samples per pixel as levels: pixel (x, y) holds `4·2^level` samples.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SampleMap {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Levels row by row from the top.
    pub levels: Vec<u8>,
}

/// What one round reached, for the caller's report and its decision to go on.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Round {
    /// Rounds done (1 after the first 4 samples).
    pub rounds: u32,
    /// The image's error estimate (linear RMSE).
    pub estimate: f64,
    /// Camera samples taken so far.
    pub samples: u64,
    /// Pixels the next round would refine (0 when the render is done).
    pub next: u64,
}

/// A finished progressive render.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// The image.
    pub film: Film,
    /// The samples each pixel took.
    pub map: SampleMap,
    /// The last round's report.
    pub last: Round,
}

/// One pixel's state per film channel: the sum of its samples; the estimate and level are kept
/// in channel 0's entry.
#[derive(Clone, Copy, Debug, Default)]
struct Cell {
    sum: Color,
    error2: f64,
    level: u8,
}

/// Renders `scene` progressively until `budget` is met, no pixel needs more samples, or
/// `round` returns false (its caller's clock). A round cancelled through `progress` is
/// discarded: the image is the last complete round's.
pub fn render(
    scene: &Prepared,
    threads: usize,
    budget: &Budget,
    progress: &dyn Progress,
    round: &mut dyn FnMut(&Round) -> bool,
) -> Result<Outcome, Diagnostic> {
    let pool = tiles::pool(threads)?;
    let view = View::new(scene);
    let ray_of = |x, y, k| view.sample_ray(x, y, k, Grid::new(2));
    let integrator = Integrator::new(scene, &view.first_rays(Grid::new(2), &ray_of), &pool)?;
    let channels = integrator.channels();
    let (w, h) = (view.camera.width(), view.camera.height());
    if let Budget::Samples(m) = budget
        && (m.width, m.height) != (w, h)
    {
        return Err(Diagnostic::new(
            Severity::Error,
            "rtc::render::samples",
            None,
            format!(
                "the sample map is {}×{} but the image is {w}×{h}",
                m.width, m.height
            ),
        )
        .with_help("use the map written by a render of this scene at this resolution"));
    }
    let n = channels.len();
    let block = |x: u32, y: u32, start: u32, len: u32, ctx: &mut Ctx, out: &mut [Color]| {
        sample_block(&view, &integrator, x, y, start, len, ctx, out)
    };
    let (mut cells, mut stats) =
        tiles::run(&pool, w, h, n, Rows::All, progress, |x, y, ctx, out| {
            let mut a = [Color::ZERO; super::film::MAX_CHANNELS];
            let mut b = [Color::ZERO; super::film::MAX_CHANNELS];
            block(x, y, 0, FIRST_SAMPLES / 2, ctx, &mut a[..n]);
            block(x, y, FIRST_SAMPLES / 2, FIRST_SAMPLES / 2, ctx, &mut b[..n]);
            for c in 0..n {
                out[c] = Cell {
                    sum: a[c] + b[c],
                    ..Cell::default()
                };
            }
            out[0].error2 = half_error2(a[0], b[0], FIRST_SAMPLES / 2);
        })?;
    let mut report = summary(&cells, n, 1);
    loop {
        let next = select(&cells, w, h, n, budget, report.estimate);
        report.next = next.iter().filter(|s| **s).count() as u64;
        if !round(&report) || report.next == 0 {
            break;
        }
        let previous = &cells;
        let more = tiles::run(&pool, w, h, n, Rows::All, progress, |x, y, ctx, out| {
            let i = (y as usize * w as usize + x as usize) * n;
            let here = &previous[i..i + n];
            out.copy_from_slice(here);
            if !next[i / n] {
                return;
            }
            ctx.stats.refined_pixels += 1;
            let held = FIRST_SAMPLES << here[0].level;
            let mut b = [Color::ZERO; super::film::MAX_CHANNELS];
            block(x, y, held, held, ctx, &mut b[..n]);
            out[0].error2 = half_error2(here[0].sum, b[0], held);
            for c in 0..n {
                out[c].sum += b[c];
            }
            out[0].level += 1;
        });
        match more {
            Ok((refined, s)) => {
                cells = refined;
                stats.add(&s);
                report = summary(&cells, n, report.rounds + 1);
            }
            Err(d) if d.code == "rtc::render::cancelled" => break,
            Err(d) => return Err(d),
        }
    }
    report.next = 0;
    Ok(finish(cells, w, h, channels, stats, scene, report))
}

/// The film and sample map of the final cells.
fn finish(
    cells: Vec<Cell>,
    w: u32,
    h: u32,
    channels: &[Channel],
    stats: Stats,
    scene: &Prepared,
    last: Round,
) -> Outcome {
    let n = channels.len();
    let levels: Vec<u8> = cells.iter().step_by(n).map(|c| c.level).collect();
    let values = cells
        .chunks_exact(n)
        .flat_map(|px| {
            let count = f64::from(FIRST_SAMPLES << px[0].level);
            px.iter().map(move |c| c.sum / count)
        })
        .collect();
    Outcome {
        film: Film::new(w, h, channels, values, stats, scene.settings().encoding),
        map: SampleMap {
            width: w,
            height: h,
            levels,
        },
        last,
    }
}

/// The round's report: the image's estimate and the samples taken.
fn summary(cells: &[Cell], n: usize, rounds: u32) -> Round {
    let pixels = cells.iter().step_by(n);
    let count = (cells.len() / n).max(1) as f64;
    let (mut sum2, mut samples) = (0.0, 0u64);
    for c in pixels {
        sum2 += c.error2;
        samples += u64::from(FIRST_SAMPLES << c.level);
    }
    Round {
        rounds,
        estimate: (sum2 / count).sqrt(),
        samples,
        next: 0,
    }
}

/// Which pixels the next round refines.
fn select(cells: &[Cell], w: u32, h: u32, n: usize, budget: &Budget, estimate: f64) -> Vec<bool> {
    let (w, h) = (w as usize, h as usize);
    let level = |i: usize| cells[i * n].level;
    match budget {
        Budget::Samples(m) => (0..w * h).map(|i| level(i) < m.levels[i]).collect(),
        Budget::TargetError(target) => {
            if estimate <= *target {
                return vec![false; w * h];
            }
            let threshold2 = target.max(estimate / 2.0).powi(2);
            (0..w * h)
                .map(|i| {
                    let (x, y) = (i % w, i / w);
                    let pooled = (y.saturating_sub(1)..(y + 2).min(h))
                        .flat_map(|ny| {
                            (x.saturating_sub(1)..(x + 2).min(w)).map(move |nx| (nx, ny))
                        })
                        .map(|(nx, ny)| cells[(ny * w + nx) * n].error2)
                        .fold(0.0, f64::max);
                    pooled > threshold2 && level(i) < MAX_LEVEL
                })
                .collect()
        }
    }
}

/// The estimated squared error of the mean of two halves of `count` samples each with sums
/// `a` and `b`: the mean over the channels of `((a − b)/2)²`, each half's mean clamped to the
/// displayable [0, 1].
fn half_error2(a: Color, b: Color, count: u32) -> f64 {
    let k = f64::from(count);
    let d = ((a / k).clamp(Color::ZERO, Color::ONE) - (b / k).clamp(Color::ZERO, Color::ONE)) / 2.0;
    d.length_squared() / 3.0
}

/// The sums over samples `start..start + len` of pixel (x, y) into `out`, per channel.
#[allow(clippy::too_many_arguments)]
fn sample_block(
    view: &View,
    integrator: &Integrator<'_>,
    x: u32,
    y: u32,
    start: u32,
    len: u32,
    ctx: &mut Ctx,
    out: &mut [Color],
) {
    out.fill(Color::ZERO);
    let mut sample = [Color::ZERO; super::film::MAX_CHANNELS];
    let sample = &mut sample[..out.len()];
    for k in 0..len {
        let index = start + k;
        ctx.rng = Rng::new(x, y, index, view.seed);
        if view.spread_lights {
            ctx.lights = LightShare { slot: k, size: len };
        }
        let (sx, sy) = ctx.rng.get2(POSITION_STREAM);
        let lens = if view.camera.has_lens() {
            ctx.rng.get2(0)
        } else {
            (0.5, 0.5)
        };
        let ray = view.camera.ray(x, y, sx, sy, lens);
        ctx.stats.camera_rays += 1;
        integrator.sample(&ray, ctx, sample);
        for (o, s) in out.iter_mut().zip(sample.iter()) {
            *o += *s;
        }
    }
}

impl SampleMap {
    /// The map as text: a header line, the size, then one line per row with one character per
    /// pixel, its level in base 36 (`0` = 4 samples, `a` = 4096).
    pub fn to_text(&self) -> String {
        let mut s = format!("rtc-samples 1\n{} {}\n", self.width, self.height);
        for row in self.levels.chunks(self.width.max(1) as usize) {
            s.extend(
                row.iter()
                    .map(|l| char::from_digit(u32::from(*l), 36).unwrap_or('?')),
            );
            s.push('\n');
        }
        s
    }

    /// Reads [`SampleMap::to_text`]'s format; an error names the line and column (1-based) and
    /// what is wrong there.
    pub fn parse(text: &str) -> Result<SampleMap, (usize, usize, String)> {
        let mut lines = text.lines();
        if lines.next().map(str::trim) != Some("rtc-samples 1") {
            return Err((1, 1, "expected the header `rtc-samples 1`".into()));
        }
        let size = lines.next().unwrap_or("");
        let dims: Vec<u32> = size
            .split_whitespace()
            .map(str::parse)
            .collect::<Result<_, _>>()
            .map_err(|_| (2, 1, format!("expected `WIDTH HEIGHT`, found `{size}`")))?;
        let [width, height] = dims[..] else {
            return Err((2, 1, format!("expected `WIDTH HEIGHT`, found `{size}`")));
        };
        let limit = crate::ir::limits::MAX_IMAGE_SIDE;
        if width == 0 || height == 0 || width > limit || height > limit {
            return Err((2, 1, format!("each side must be in 1..={limit}")));
        }
        let mut levels = Vec::with_capacity(width as usize * height as usize);
        for y in 0..height as usize {
            let line_no = y + 3;
            let row =
                lines
                    .next()
                    .ok_or((line_no, 1, format!("missing row {} of {height}", y + 1)))?;
            let before = levels.len();
            for (col, ch) in row.chars().enumerate() {
                match ch.to_digit(36) {
                    Some(l) if l <= u32::from(MAX_LEVEL) => levels.push(l as u8),
                    _ => {
                        return Err((
                            line_no,
                            col + 1,
                            format!("`{ch}` is not a level in 0..={MAX_LEVEL}"),
                        ));
                    }
                }
            }
            if levels.len() - before != width as usize {
                return Err((
                    line_no,
                    1,
                    format!(
                        "row {} has {} pixels, not {width}",
                        y + 1,
                        levels.len() - before
                    ),
                ));
            }
        }
        Ok(SampleMap {
            width,
            height,
            levels,
        })
    }

    /// Mean samples per pixel.
    pub fn mean_samples(&self) -> f64 {
        let total: u64 = self
            .levels
            .iter()
            .map(|l| u64::from(FIRST_SAMPLES << l))
            .sum();
        total as f64 / self.levels.len().max(1) as f64
    }

    /// The fewest and most samples of a pixel.
    pub fn sample_range(&self) -> (u32, u32) {
        let lo = self.levels.iter().min().copied().unwrap_or(0);
        let hi = self.levels.iter().max().copied().unwrap_or(0);
        (FIRST_SAMPLES << lo, FIRST_SAMPLES << hi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sample_maps_round_trip_and_bad_text_is_located() {
        let m = SampleMap {
            width: 3,
            height: 2,
            levels: vec![0, 1, 10, 2, 0, 9],
        };
        assert_eq!(m.to_text(), "rtc-samples 1\n3 2\n01a\n209\n");
        assert_eq!(SampleMap::parse(&m.to_text()), Ok(m.clone()));
        assert_eq!(m.sample_range(), (4, 4096));
        let err = |t: &str| SampleMap::parse(t).unwrap_err();
        assert_eq!(err("nope").0, 1);
        assert_eq!(err("rtc-samples 1\n3\n").0, 2);
        assert_eq!(err("rtc-samples 1\n0 2\n").0, 2);
        let bad = err("rtc-samples 1\n3 2\n01b\n209\n");
        assert_eq!((bad.0, bad.1), (3, 3));
        assert_eq!(err("rtc-samples 1\n3 2\n01\n").0, 3);
        assert_eq!(err("rtc-samples 1\n3 2\n012\n").0, 4);
        assert_eq!(MAX_LEVEL, 10);
    }

    #[test]
    fn halves_that_agree_have_no_error() {
        let c = Color::new(0.2, 0.4, 0.6);
        assert_eq!(half_error2(c * 2.0, c * 2.0, 2), 0.0);
        // Means 0 and 1 in every channel: each half is 0.5 off the mean.
        assert_eq!(half_error2(Color::ZERO, Color::ONE * 8.0, 8), 0.25);
    }
}
