//! Dealing an area light's cells out over a pixel's samples (`spread_light_samples`), and the
//! weight each dealt cell carries so that the pixel's estimate stays unbiased.
//!
//! Sample `slot` of `size` takes the ⌈cells/size⌉ consecutive cells from `slot·⌈cells/size⌉`
//! (modulo `cells`): draws `0..size·⌈cells/size⌉` of the cyclic sequence of cells. When `cells`
//! does not divide that number of draws, the first `draws mod cells` cells are drawn once more
//! than the others; weighting every cell's draws alike (`1/⌈cells/size⌉`, as before issue 34)
//! then counts those cells more than the rest, and a penumbra came out consistently too dark or
//! too bright (−0.5 levels at 16 samples under a 5×5 light). Each draw of cell k now weighs
//! `size / (cells · n_k)` with n_k the draws of cell k, so every cell contributes exactly
//! `1/cells` of the light to the pixel's mean: the estimator's expectation is the light's
//! integral whatever `cells` and `size` are. When the draws cover every cell equally (`size`
//! divides `cells`, or `cells` divides `size`), the weight is `1/⌈cells/size⌉` as before, to the
//! bit: those images keep their bytes.

/// Which cells of an area light one camera sample takes: all of them, or (with
/// `ir::LightSampling::Spread`) its share when the cells are dealt out over the `size` samples
/// of its pixel (or of its refinement block), this sample being number `slot` among them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct LightShare {
    /// The sample's position among the samples sharing the cells.
    pub(crate) slot: u32,
    /// How many samples share the cells; 0: every sample takes every cell.
    pub(crate) size: u32,
}

/// The weight of one light cell's sample, `num / den` of the light: a fraction, so that the
/// common `1/count` is computed exactly as `color / count`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Weight {
    /// Numerator.
    pub(crate) num: u32,
    /// Denominator (at least 1).
    pub(crate) den: u32,
}

impl Weight {
    /// `x` times the weight: `x · num / den` (`x / den` to the bit when `num` is 1).
    #[inline]
    pub(crate) fn of(self, x: f64) -> f64 {
        x * f64::from(self.num) / f64::from(self.den)
    }

    /// The weight as a number.
    pub(crate) fn value(self) -> f64 {
        self.of(1.0)
    }
}

impl LightShare {
    /// Every sample takes every cell (the course's rule).
    pub(crate) const ALL: LightShare = LightShare { slot: 0, size: 0 };

    /// The first cell and the number of cells of a light with `cells` cells this sample takes:
    /// cells `(first + j) mod cells` for `j < count`, each weighing [`LightShare::weight`].
    pub(crate) fn cells(self, cells: u32) -> (u32, u32) {
        if self.size == 0 || cells <= 1 {
            return (0, cells);
        }
        let count = cells.div_ceil(self.size);
        ((self.slot % self.size) * count % cells, count)
    }

    /// The weight of cell `k` (of `cells`) in this sample: `size / (cells · n_k)` with n_k the
    /// number of the pixel's samples that take cell k (module doc), reduced; `1/cells` when
    /// every sample takes every cell.
    pub(crate) fn weight(self, cells: u32, k: u32) -> Weight {
        let cells = cells.max(1);
        if self.size == 0 || cells == 1 {
            return Weight { num: 1, den: cells };
        }
        let draws = u64::from(self.size) * u64::from(cells.div_ceil(self.size));
        let c = u64::from(cells);
        let taken = draws / c + u64::from(u64::from(k) < draws % c);
        let (num, den) = (u64::from(self.size), c * taken);
        let g = gcd(num, den);
        Weight {
            num: u32::try_from(num / g).unwrap_or(u32::MAX),
            den: u32::try_from(den / g).unwrap_or(u32::MAX),
        }
    }
}

/// The greatest common divisor (Euclid).
fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a.max(1)
}

#[cfg(test)]
#[path = "deal_tests.rs"]
mod tests;
