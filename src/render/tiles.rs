//! The tile driver: bands of rows rendered in parallel with rayon. Each pixel's value depends
//! only on the pixel (randomness is keyed by pixel and sample), and bands write disjoint slices,
//! so the bytes are identical for any thread count.

use rayon::prelude::*;

use super::film::Stats;
use super::progress::Progress;
use super::sampler::Rng;
use super::shading::Ctx;
use crate::diag::{Diagnostic, Severity};
use crate::ir::Color;

/// Rows per task: small enough to balance load over the cores, large enough to amortise scheduling.
const BAND: usize = 4;

/// Stack per render thread: Whitted recursion up to `ir::limits::MAX_DEPTH` bounces needs more than
/// the default 2 MiB (it is virtual memory; only what is touched is used).
const STACK_BYTES: usize = 64 << 20;

/// A thread pool with `threads` workers (0 = one per core).
pub fn pool(threads: usize) -> Result<rayon::ThreadPool, Diagnostic> {
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

/// Computes `f(x, y, ctx)` for every pixel of a `width`×`height` image, row by row from the top.
pub fn run<F>(
    pool: &rayon::ThreadPool,
    width: u32,
    height: u32,
    progress: &Progress,
    f: F,
) -> (Vec<Color>, Stats)
where
    F: Fn(u32, u32, &mut Ctx) -> Color + Sync,
{
    let w = width as usize;
    let mut pixels = vec![Color::ZERO; w * height as usize];
    let stats = pool.install(|| {
        pixels
            .par_chunks_mut(w * BAND)
            .enumerate()
            .map(|(band, chunk)| {
                let mut ctx = Ctx {
                    rng: Rng::new(0, 0, 0, 0),
                    stats: Stats::default(),
                };
                for (i, px) in chunk.iter_mut().enumerate() {
                    let (x, y) = ((i % w) as u32, (band * BAND + i / w) as u32);
                    *px = f(x, y, &mut ctx);
                }
                progress.advance((chunk.len() / w) as u64);
                ctx.stats
            })
            .reduce(Stats::default, |mut a, b| {
                a.add(&b);
                a
            })
    });
    (pixels, stats)
}
