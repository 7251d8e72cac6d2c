//! Which pixels adaptive supersampling refines, from the first pass's colours.
//!
//! Two tests, either refines:
//!
//! - **Contrast:** the colour differs from a 4-neighbour's by more than the threshold in some
//!   channel (an edge, a shadow boundary, noise).
//! - **Quantisation:** the finer grid's mean would likely be another 8-bit level than the first
//!   pass's. Over a pixel where the colour is smooth, f ≈ c + g·(x, y) + ½(f_xx x² + f_yy y²);
//!   an m×m grid's mean is c + ½(f_xx + f_yy)·(m² − 1)/(12m²), so the fine grid's mean is the
//!   first's plus (L + R + U + D − 4c)·(s(fine) − s(first))/2 with s(m) = (m² − 1)/(12m²) and
//!   the neighbours' second differences for the curvature. When the first pass's colour plus
//!   twice that change (a margin for the rough estimate) encodes, in the film's encoding, to
//!   other bytes than the colour itself, the pixel is refined: a smooth pixel whose one sample
//!   happens to land on the other side of a level boundary. The contrast test alone left such
//!   pixels one level off, which ꟻLIP counts (on scenes/five_spheres.rtc, +20% mean ꟻLIP
//!   against uniform 4×4 for the same RMSE; +0.1% with this test, docs/convergence.md).
//!
//! In a scene that draws random numbers (an area light, a lens, gloss, motion blur) the first
//! pass is noisy, and the quantisation test only sees the noise: its predicted change lies
//! between the pixel and its neighbours' mean, so it crosses a level wherever the noise exceeds
//! one, at every threshold (issue 34: 9457 refined pixels of 19 200 at threshold 0.02, 9165 at
//! 0.5). There the noise estimate — how far the pixel is from its 4-neighbours — is weighed
//! against the threshold alone (the contrast test), so the threshold is the noise a user
//! tolerates: a higher threshold refines a subset of the pixels a lower one refines.

use super::film::encode;
use super::sampler::Grid;
use crate::ir::{Color, Encoding};

/// How far past the predicted change of the mean a level boundary may lie and still refine.
const MARGIN: f64 = 2.0;

/// The refinement test of one render.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Criterion {
    /// The contrast threshold (per channel, linear).
    threshold: f64,
    /// (s(fine) − s(first)) / 2: the curvature's weight in the predicted fine mean.
    curvature: f64,
    /// How film colours become bytes.
    encoding: Encoding,
    /// Whether the quantisation test runs (not in a noisy scene: module doc).
    levels: bool,
}

impl Criterion {
    /// The test for a first pass on `first`, a refinement on `fine`, the contrast `threshold`
    /// and the film's `encoding`.
    pub(crate) fn new(first: Grid, fine: Grid, threshold: f64, encoding: Encoding) -> Criterion {
        let s = |g: Grid| {
            let m = f64::from(g.factor());
            (m * m - 1.0) / (12.0 * m * m)
        };
        Criterion {
            threshold,
            curvature: 0.5 * (s(fine) - s(first)),
            encoding,
            levels: true,
        }
    }

    /// The same test for a scene whose first pass is `noisy` (it draws random numbers): the
    /// threshold alone decides there, against the noise estimate (module doc).
    pub(crate) fn with_noise(self, noisy: bool) -> Criterion {
        Criterion {
            levels: !noisy,
            ..self
        }
    }

    /// Whether pixel (x, y) of a `w`×`h` first pass (`at` reads its colours) is refined.
    pub(crate) fn refines(
        &self,
        at: impl Fn(u32, u32) -> Color,
        x: u32,
        y: u32,
        w: u32,
        h: u32,
    ) -> bool {
        let c = at(x, y);
        // Neighbours outside the image count as the pixel itself (no contrast, no curvature).
        let n = [
            if x > 0 { at(x - 1, y) } else { c },
            if x + 1 < w { at(x + 1, y) } else { c },
            if y > 0 { at(x, y - 1) } else { c },
            if y + 1 < h { at(x, y + 1) } else { c },
        ];
        if n.iter()
            .any(|&v| (v - c).abs().max_element() > self.threshold)
        {
            return true;
        }
        if !self.levels {
            return false;
        }
        // Twice the predicted change: the second differences come from one first-pass value per
        // pixel, so the prediction is rough; encoding is monotone, so this also catches every
        // pixel the change itself would move.
        let laplacian = n[0] + n[1] + n[2] + n[3] - 4.0 * c;
        let predicted = c + MARGIN * self.curvature * laplacian;
        encode(predicted, self.encoding) != encode(c, self.encoding)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn contrast_and_level_crossings_refine() {
        let k = Criterion::new(Grid::new(1), Grid::new(4), 0.02, Encoding::Linear);
        // s(4) = 15/192, s(1) = 0: half of it.
        assert!((k.curvature - 15.0 / 384.0).abs() < 1e-15);
        let flat = |v: f64| move |_: u32, _: u32| DVec3::splat(v);
        assert!(!k.refines(flat(0.5), 1, 1, 3, 3));
        // An edge.
        let edge = |x: u32, _: u32| DVec3::splat(if x == 0 { 0.0 } else { 0.5 });
        assert!(k.refines(edge, 1, 1, 3, 3));
        // A bright ridge (neighbours 0.01 lower, under the threshold) whose centre sits just
        // above a level boundary (102/255): the fine mean, 0.01·4·15/384 ≈ 0.0016 lower
        // (0.0031 with the margin), crosses it; the same ridge 0.9 levels up does not.
        let boundary = 102.0 / 255.0 + 0.0005;
        let ridge = move |centre: f64| {
            move |x: u32, y: u32| {
                DVec3::splat(if (x, y) == (1, 1) {
                    centre
                } else {
                    centre - 0.01
                })
            }
        };
        assert!(k.refines(ridge(boundary), 1, 1, 3, 3));
        assert!(!k.refines(ridge(102.9 / 255.0), 1, 1, 3, 3));
        // A plane (no curvature) never crosses.
        let ramp = |x: u32, _: u32| DVec3::splat(boundary + 0.01 * f64::from(x));
        assert!(!k.refines(ramp, 1, 1, 3, 3));
        // No finer grid, no curvature term.
        let same = Criterion::new(Grid::new(2), Grid::new(2), 0.02, Encoding::Srgb);
        assert_eq!(same.curvature, 0.0);
        // In a noisy scene the level crossing alone does not refine; contrast still does.
        let noisy = k.with_noise(true);
        assert!(!noisy.refines(ridge(boundary), 1, 1, 3, 3));
        assert!(noisy.refines(edge, 1, 1, 3, 3));
        assert!(k.with_noise(false).refines(ridge(boundary), 1, 1, 3, 3));
    }
}
