//! Image error metrics: how far a test render is from a reference of the same size.
//!
//! Both images come in as linear-RGB `f32` buffers ([`LinearRgb`], e.g. a film before
//! quantisation, or a PNG decoded with [`srgb::decode_all`]). The rules (issue 9):
//! - **ꟻLIP** ([`flip`]) compares the images as a viewer sees them: both are encoded to 8-bit
//!   sRGB first; the mean of the map is the headline number of rendering research.
//! - **RMSE** ([`rmse`]) and **relMSE** ([`rel_mse`], ε = [`REL_MSE_EPSILON`] = 0.01) are
//!   computed in linear light over every channel.
//! - **The worst 1%** ([`WORST_FRACTION`]): the mean of the `ceil(1% · N)` largest per-pixel
//!   values, once by ꟻLIP and once by squared error (the mean of the pixel's three channels'
//!   `(t − r)²` in linear light, [`squared_error_map`]).
//! - **Noise** ([`noise`]) from two renders that differ only in their seed: the estimator is in
//!   [`noise`]'s module.
//! - The ꟻLIP map is drawn in the magma colour map as a PNG ([`FlipMap::magma_png`]); error
//!   against time is drawn as an SVG plot ([`plot`]).
//!
//! This is a leaf module: it uses nothing of rtc but [`crate::diag`], so the renderer, the CLI
//! and the tests can all measure with it.

mod flip;
mod noise;
pub(crate) mod pareto;
mod pixel_error;
pub mod plot;
pub mod srgb;
mod view;
mod worst;

use crate::diag::Diagnostic;

pub(crate) use flip::FlipMap;
pub use flip::flip;
pub(crate) use noise::NoiseEstimate;
pub use noise::noise;
pub(crate) use pixel_error::squared_error_map;
pub use pixel_error::{REL_MSE_EPSILON, rel_mse, rmse};
pub use view::{BUFFER_SIZE, EMPTY, LinearRgb, NOT_FINITE, SIZE_MISMATCH, TOO_LARGE};
pub(crate) use worst::{WORST_FRACTION, mean_of_worst};

/// Every metric of one test image against its reference.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// Mean ꟻLIP over all pixels, in [0, 1].
    pub flip_mean: f64,
    /// Mean ꟻLIP of the worst 1% of pixels by ꟻLIP.
    pub flip_worst: f64,
    /// Root-mean-square error in linear light.
    pub rmse: f64,
    /// Relative MSE in linear light (ε = [`REL_MSE_EPSILON`]).
    pub rel_mse: f64,
    /// Mean squared error of the worst 1% of pixels by squared error, in linear light.
    pub squared_error_worst: f64,
    /// The ꟻLIP map itself (for the magma picture).
    pub flip_map: FlipMap,
}

/// Measures `test` against `reference` with every metric.
pub fn compare(test: LinearRgb<'_>, reference: LinearRgb<'_>) -> Result<Comparison, Diagnostic> {
    let flip_map = flip(test, reference)?;
    let squared = squared_error_map(test, reference)?;
    Ok(Comparison {
        flip_mean: flip_map.mean(),
        flip_worst: flip_map.mean_of_worst(WORST_FRACTION),
        rmse: rmse(test, reference)?,
        rel_mse: rel_mse(test, reference)?,
        squared_error_worst: mean_of_worst(&squared, WORST_FRACTION),
        flip_map,
    })
}
