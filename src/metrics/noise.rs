//! How noisy a render setting is, from two renders that differ only in their seed.
//!
//! Estimator: with `a` and `b` two independent renders of the same settings, each channel value
//! is `μ + noise` with the same variance σ² in both, so `E[(a − b)²] = 2σ²`. The mean per-channel
//! variance of one render is estimated without bias by
//!
//! ```text
//! σ̂² = Σ (a − b)² / (2 · 3N)        (N pixels, 3 channels, linear light)
//! ```
//!
//! and `√σ̂²` is the RMSE one render has against its own expectation. Against a converged
//! reference, `E[MSE] = bias² + σ² (+ the reference's own σ²)`, so `MSE − σ̂²` estimates the
//! error more samples would not remove. Settings without randomness give σ̂² = 0.
//! rtc's renders take independent scrambles of their Sobol' sequences per seed, so two seeds
//! are two independent runs.

use crate::diag::Diagnostic;

use super::flip::flip;
use super::pixel_error::channel_sum;
use super::view::LinearRgb;

/// The noise of one render setting, estimated from two independently seeded renders.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NoiseEstimate {
    /// σ̂²: the mean per-channel variance of one render, `Σ (a − b)² / (2 · 3N)`.
    pub variance: f64,
    /// √σ̂²: the RMSE of one render against its own expectation (the noise share of its error).
    pub rmse: f64,
    /// The mean ꟻLIP between the two renders: how visible the noise is.
    pub flip_between_runs: f64,
}

/// Estimates the noise of a setting from two renders of it with different seeds.
pub fn noise(run_a: LinearRgb<'_>, run_b: LinearRgb<'_>) -> Result<NoiseEstimate, Diagnostic> {
    let sum = channel_sum(run_a, run_b, |a, b| (a - b) * (a - b))?;
    let variance = sum / (2.0 * run_a.data().len() as f64);
    Ok(NoiseEstimate {
        variance,
        rmse: variance.sqrt(),
        flip_between_runs: flip(run_a, run_b)?.mean(),
    })
}
