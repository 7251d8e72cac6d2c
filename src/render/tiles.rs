//! The tile driver: bands of rows rendered in parallel with rayon. Each pixel's value depends
//! only on the pixel (randomness is keyed by pixel and sample), and bands write disjoint slices,
//! so the bytes are identical for any thread count and any cut into bands.

use rayon::prelude::*;

use super::film::Stats;
use std::sync::atomic::{AtomicBool, Ordering};

use super::context::Ctx;
use super::progress::Progress;
use super::shard::Rows;
use crate::diag::{Diagnostic, Severity};

/// Rows per task: small enough to balance load over the cores, large enough to amortise scheduling.
const BAND: usize = 4;

/// Stack per render thread: Whitted recursion up to `ir::limits::MAX_DEPTH` bounces needs more than
/// the default 2 MiB (it is virtual memory; only what is touched is used).
const STACK_BYTES: usize = 64 << 20;

/// A thread pool with `threads` workers (0 = one per core).
pub(crate) fn pool(threads: usize) -> Result<rayon::ThreadPool, Diagnostic> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .stack_size(STACK_BYTES)
        .build()
        .map_err(|e| {
            Diagnostic::new(
                Severity::Error,
                "rtc::render::threads",
                None,
                format!("cannot start the render threads: {e}"),
            )
        })
}

/// Computes `f(x, y, ctx, out)` for every pixel of the `rows` of a `width`×`height` image, row
/// by row from the top; `f` writes the pixel's `channels` values into `out` (colours, or any
/// per-pixel state such as a progressive render's sums). Values come back interleaved per
/// pixel for the whole image (zero in rows not computed). Before each band the callback is asked whether to stop: a cancelled render is the
/// error `rtc::render::cancelled`.
pub(crate) fn run<T, F>(
    pool: &rayon::ThreadPool,
    width: u32,
    height: u32,
    channels: usize,
    rows: Rows,
    progress: &dyn Progress,
    f: F,
) -> Result<(Vec<T>, Stats), Diagnostic>
where
    T: Copy + Default + Send,
    F: Fn(u32, u32, &mut Ctx, &mut [T]) + Sync,
{
    run_spans(pool, (width, height), channels, 1, rows, progress, f)
}

/// [`run`] for runs of up to `span` pixels of a row at once: `f(x0, y, ctx, out)` computes
/// the pixels from column `x0` on, `out.len() / channels` of them (fewer than `span` at the
/// row's end), so neighbouring pixels can be traced as one packet.
pub(crate) fn run_spans<T, F>(
    pool: &rayon::ThreadPool,
    (width, height): (u32, u32),
    channels: usize,
    span: usize,
    rows: Rows,
    progress: &dyn Progress,
    f: F,
) -> Result<(Vec<T>, Stats), Diagnostic>
where
    T: Copy + Default + Send,
    F: Fn(u32, u32, &mut Ctx, &mut [T]) + Sync,
{
    let w = width as usize;
    let row = w * channels;
    let mut values = vec![T::default(); row * height as usize];
    let stop = AtomicBool::new(false);
    let stats = pool.install(|| {
        values
            .par_chunks_mut(row * BAND)
            .enumerate()
            .map(|(band, chunk)| {
                let mut ctx = Ctx::new();
                if stop.load(Ordering::Relaxed) || progress.cancelled() {
                    stop.store(true, Ordering::Relaxed);
                    return ctx.stats;
                }
                let mut done = 0;
                for (r, line) in chunk.chunks_exact_mut(row).enumerate() {
                    let y = (band * BAND + r) as u32;
                    if !rows.contains(y) {
                        continue;
                    }
                    for (k, px) in line.chunks_mut(channels * span).enumerate() {
                        f((k * span) as u32, y, &mut ctx, px);
                    }
                    done += 1;
                }
                progress.advance(done);
                ctx.stats
            })
            .reduce(Stats::default, |mut a, b| {
                a.add(&b);
                a
            })
    });
    if stop.load(Ordering::Relaxed) {
        progress.finish();
        return Err(Diagnostic::new(
            Severity::Error,
            super::progress::CANCELLED,
            None,
            "the render was cancelled",
        ));
    }
    Ok((values, stats))
}
