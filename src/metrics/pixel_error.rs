//! Errors measured in linear light, channel by channel: RMSE, relMSE and the per-pixel squared
//! error. Sums run in f64 so a 4K image loses no precision.

use crate::diag::Diagnostic;

use super::view::{LinearRgb, same_size};

/// The ε of [`rel_mse`]: `(t − r)² / (r² + ε)`. 0.01 is the value of the denoising literature
/// (Rousselle et al. 2011, used by pbrt-v4's and Mitsuba's tools): it keeps black reference pixels
/// from dominating while a 0.1-bright channel already counts half relative.
pub const REL_MSE_EPSILON: f64 = 0.01;

/// Root-mean-square error over every channel of every pixel, in linear light.
pub fn rmse(test: LinearRgb<'_>, reference: LinearRgb<'_>) -> Result<f64, Diagnostic> {
    let sum = channel_sum(test, reference, |t, r| (t - r) * (t - r))?;
    Ok((sum / test.data().len() as f64).sqrt())
}

/// Relative mean squared error: the mean over every channel of `(t − r)² / (r² + ε)` with
/// ε = [`REL_MSE_EPSILON`], in linear light.
pub fn rel_mse(test: LinearRgb<'_>, reference: LinearRgb<'_>) -> Result<f64, Diagnostic> {
    let sum = channel_sum(test, reference, |t, r| {
        (t - r) * (t - r) / (r * r + REL_MSE_EPSILON)
    })?;
    Ok(sum / test.data().len() as f64)
}

/// The squared error of each pixel: the mean over its three channels of `(t − r)²`, rows from
/// the top.
pub(crate) fn squared_error_map(
    test: LinearRgb<'_>,
    reference: LinearRgb<'_>,
) -> Result<Vec<f64>, Diagnostic> {
    same_size(&test, &reference)?;
    Ok(test
        .pixels()
        .zip(reference.pixels())
        .map(|(t, r)| {
            (0..3)
                .map(|c| {
                    let d = f64::from(t[c]) - f64::from(r[c]);
                    d * d
                })
                .sum::<f64>()
                / 3.0
        })
        .collect())
}

/// The sum over every channel of `term(test, reference)`, after checking the sizes agree.
pub(super) fn channel_sum(
    test: LinearRgb<'_>,
    reference: LinearRgb<'_>,
    term: impl Fn(f64, f64) -> f64,
) -> Result<f64, Diagnostic> {
    same_size(&test, &reference)?;
    Ok(test
        .data()
        .iter()
        .zip(reference.data())
        .map(|(&t, &r)| term(f64::from(t), f64::from(r)))
        .sum())
}
