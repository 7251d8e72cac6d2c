//! The pixel driver: a pixel's value as the mean of the integrator's values over its camera
//! samples, one by one or (when the integrator traces packets) side by side, across the pixels
//! of a row when their rays need no per-sample set-up.

use glam::DVec3;

use crate::geometry::Ray;
use crate::ir::Color;

use super::context::{BATCH, Ctx};
use super::film;
use super::integrator::Integrator;
use super::sampler::Grid;
use super::view::View;

/// The per-axis grid offsets [`average_span`] keeps at hand (a 16×16 grid's); finer grids
/// compute theirs sample by sample.
const AXIS_OFFSETS: usize = 16;

/// How many pixels of a row [`average_span`] takes at once for `channels` per pixel:
/// a packet's worth when a scene the Whitted packets trace has plain pinhole camera rays
/// (their samples then fill whole packets across pixels: a 3×3 grid's nine samples alone
/// would leave seven of sixteen lanes idle), else one.
pub(crate) fn span(view: &View, integrator: &Integrator<'_>, channels: usize) -> usize {
    if channels == 1 && integrator.batch().is_some() && view.pinhole() {
        BATCH
    } else {
        1
    }
}

/// [`average`] of the pixels from (x0, y) rightwards, `channels` values each in
/// `out`: when [`span`] is more than one, the samples of all of them, pixel after
/// pixel, traced in packets of [`BATCH`] (each pixel's value bit for bit the one [`average`]
/// gives it: its samples summed in the same order), else pixel by pixel.
pub(crate) fn average_span(
    view: &View,
    integrator: &Integrator<'_>,
    (grid, channels): (Grid, usize),
    x0: u32,
    y: u32,
    ctx: &mut Ctx,
    out: &mut [Color],
) {
    let w = integrator
        .batch()
        .filter(|_| span(view, integrator, channels) > 1 && out.len() <= BATCH);
    let Some(w) = w else {
        for (k, px) in out.chunks_exact_mut(channels).enumerate() {
            average(view, integrator, grid, 0, x0 + k as u32, y, ctx, px);
        }
        return;
    };
    let per_pixel = grid.len();
    let mut sums = [Color::ZERO; BATCH];
    let mut colors = [Color::ZERO; BATCH];
    // The grid's offsets along one axis once per span, `Grid::offset`'s (i + ½)/f, not two
    // divisions of each kind per sample (a table of every sample's pair was a 4 kB
    // `memset` per span, 2% of the duck's render).
    let factor = grid.factor();
    let mut axis = [0.0; AXIS_OFFSETS];
    for (i, a) in axis.iter_mut().enumerate().take(factor as usize) {
        *a = grid.offset(i as u32).0;
    }
    let offset = |(column, row): (u32, u32)| match factor as usize <= AXIS_OFFSETS {
        true => (axis[column as usize], axis[row as usize]),
        false => grid.offset(row * factor + column),
    };
    // Each packet's samples: (pixel of the span, the sample's column and row in the grid),
    // pixel after pixel.
    let mut samples = [(0usize, (0u32, 0u32)); BATCH];
    let (mut pixel, mut cell) = (0, (0, 0));
    while pixel < out.len() {
        let mut m = 0;
        while m < BATCH && pixel < out.len() {
            samples[m] = (pixel, cell);
            m += 1;
            cell.0 += 1;
            if cell.0 == factor {
                cell = (0, cell.1 + 1);
                if cell.1 == factor {
                    (pixel, cell) = (pixel + 1, (0, 0));
                }
            }
        }
        let at = |j: usize| (x0 + samples[j].0 as u32, offset(samples[j].1));
        let rays = view.camera.pinhole_packet(y, at, m);
        ctx.stats.camera_rays += m as u64;
        w.trace_lanes(&rays, m, ctx, &mut colors[..m]);
        for (&(p, _), c) in samples[..m].iter().zip(&colors[..m]) {
            sums[p] += *c;
        }
    }
    for (o, s) in out.iter_mut().zip(&sums) {
        *o = *s / f64::from(per_pixel);
    }
}

/// The mean of the integrator's (unclamped) values over the samples of `grid`, per channel,
/// into `out`; sample numbers start at `first_index`.
#[allow(clippy::too_many_arguments)]
pub(crate) fn average(
    view: &View,
    integrator: &Integrator<'_>,
    grid: Grid,
    first_index: u32,
    x: u32,
    y: u32,
    ctx: &mut Ctx,
    out: &mut [Color],
) {
    out.fill(Color::ZERO);
    // One sample a pixel has no other ray to overlap with: the batch would only add its
    // staging (measured: +15% render time on the 1-sample 100k-sphere scene).
    if let (Some(w), [out], true) = (
        integrator.batch(),
        &mut *out,
        grid.len() > 1 && !view.camera.has_blind_pixels(),
    ) {
        // The samples in batches, summed in the same order as one by one below.
        let mut rays = [Ray::new(DVec3::ZERO, DVec3::ZERO); BATCH];
        let mut colors = [Color::ZERO; BATCH];
        // What `camera_sample` does then is only the ray (and its count).
        let pinhole = view.pinhole();
        let mut k = 0;
        while k < grid.len() {
            let m = (grid.len() - k).min(BATCH as u32);
            if pinhole {
                // Nothing to set up per sample: the rays of the batch at once.
                let mut offsets = [(0.0, 0.0); BATCH];
                for (j, o) in (k..k + m).zip(&mut offsets) {
                    *o = grid.offset(j);
                }
                let m = m as usize;
                view.camera
                    .pinhole_rays(x, y, &offsets[..m], &mut rays[..m]);
                ctx.stats.camera_rays += m as u64;
            } else {
                for (j, ray) in (k..k + m).zip(&mut rays) {
                    *ray = view.camera_sample(
                        x,
                        y,
                        first_index + j,
                        (j, grid.len()),
                        grid.offset(j),
                        ctx,
                    );
                }
            }
            let m = m as usize;
            w.trace_batch(&rays[..m], ctx, &mut colors[..m]);
            for c in &colors[..m] {
                *out += *c;
            }
            k += m as u32;
        }
        *out /= f64::from(grid.len());
        return;
    }
    let mut sample = [Color::ZERO; film::MAX_CHANNELS];
    let sample = &mut sample[..out.len()];
    for k in 0..grid.len() {
        let ray = view.camera_sample(x, y, first_index + k, (k, grid.len()), grid.offset(k), ctx);
        integrator.sample(&ray, ctx, sample);
        for (o, s) in out.iter_mut().zip(sample.iter()) {
            *o += *s;
        }
    }
    let n = f64::from(grid.len());
    for o in out.iter_mut() {
        *o /= n;
    }
}
