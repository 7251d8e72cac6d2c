//! Tests of the pattern module (not timed): analytic properties of every pattern, the noise's
//! statistics, continuity, isotropy and determinism, fBm's scaling, Worley's search. Sampling
//! is by a fixed-seed generator, so every run sees the same points.

use glam::DVec3;

mod cells;
mod color_map;
mod fbm;
mod geometric;
mod modifiers;
mod noise;
mod noisy;
mod slopes;
mod tilings;

/// A 64-bit LCG (Knuth's MMIX constants): reproducible sample points.
pub(super) struct Lcg(u64);

impl Lcg {
    /// A generator from `seed`.
    pub(super) fn new(seed: u64) -> Lcg {
        Lcg(seed)
    }

    /// A number in [0, 1).
    pub(super) fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64) / (1u64 << 53) as f64
    }

    /// A point uniform in the cube [−half, half]³.
    pub(super) fn point(&mut self, half: f64) -> DVec3 {
        DVec3::new(
            (2.0 * self.next() - 1.0) * half,
            (2.0 * self.next() - 1.0) * half,
            (2.0 * self.next() - 1.0) * half,
        )
    }
}

/// Mean and variance of `f` over `n` points uniform in [−half, half]³ (seeded by `seed`).
pub(super) fn moments(n: usize, half: f64, seed: u64, f: impl Fn(DVec3) -> f64) -> (f64, f64) {
    let mut rng = Lcg::new(seed);
    let (mut sum, mut sum2) = (0.0, 0.0);
    for _ in 0..n {
        let v = f(rng.point(half));
        sum += v;
        sum2 += v * v;
    }
    let mean = sum / n as f64;
    (mean, sum2 / n as f64 - mean * mean)
}
