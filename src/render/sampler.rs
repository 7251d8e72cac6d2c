//! Sub-pixel sample positions and deterministic randomness.
//!
//! Every random number is a pure function of (pixel, sample, stream, seed), so an image does not
//! depend on the thread count or the order in which tiles run.

use crate::ir::Sampling;

/// The regular f×f grid of sub-pixel offsets ((i+½)/f, (j+½)/f) of COURSE.md §2.5.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Grid {
    factor: u32,
}

impl Grid {
    /// A grid with `factor` samples per axis (at least 1).
    pub(crate) fn new(factor: u32) -> Grid {
        Grid {
            factor: factor.max(1),
        }
    }

    /// Samples per axis.
    pub(crate) fn factor(&self) -> u32 {
        self.factor
    }

    /// Number of samples.
    pub(crate) fn len(&self) -> u32 {
        self.factor * self.factor
    }

    /// Offset of sample `k` (row-major, `k < len`).
    pub(crate) fn offset(&self, k: u32) -> (f64, f64) {
        let f = f64::from(self.factor);
        let (i, j) = (k % self.factor, k / self.factor);
        ((f64::from(i) + 0.5) / f, (f64::from(j) + 0.5) / f)
    }
}

/// The pixel sampling plan: a fixed grid, or a first grid refined to a finer one where needed.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PixelSampler {
    /// The grid every pixel gets.
    pub(crate) first: Grid,
    /// The finer grid and the channel spread that triggers it (adaptive sampling).
    pub(crate) refine: Option<(Grid, f64)>,
}

impl PixelSampler {
    /// The plan for a scene's sampling setting.
    pub(crate) fn new(s: Sampling) -> PixelSampler {
        match s {
            Sampling::Grid { factor } => PixelSampler {
                first: Grid::new(factor),
                refine: None,
            },
            Sampling::Adaptive {
                min,
                max,
                threshold,
            } => {
                let first = Grid::new(min);
                let fine = Grid::new(max);
                PixelSampler {
                    first,
                    refine: (fine.factor() > first.factor()).then_some((fine, threshold.max(0.0))),
                }
            }
        }
    }
}

/// Deterministic random numbers for one camera sample.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Rng {
    seed: u32,
    sample: u32,
}

impl Rng {
    /// The generator for sample `sample` of pixel (x, y) under the scene `seed`.
    pub(crate) fn new(x: u32, y: u32, sample: u32, seed: u64) -> Rng {
        let s = hash(x ^ hash(y ^ hash((seed as u32) ^ hash((seed >> 32) as u32))));
        Rng {
            seed: s,
            // Owen-scrambled Sobol' accepts indices below 2^16.
            sample: sample & 0xffff,
        }
    }

    /// A 2-D point in [0,1)² for the decision `stream` (lens, a light's cell, a bounce...).
    /// Streams are decorrelated by re-seeding; the dimension pair stays (0, 1) so each stream is a
    /// well-stratified 2-D Sobol' sequence over the pixel's samples.
    pub(crate) fn get2(&self, stream: u32) -> (f64, f64) {
        let seed = hash(self.seed ^ hash(stream.wrapping_add(0x9e37_79b9)));
        let a = sobol_burley::sample(self.sample, 0, seed);
        let b = sobol_burley::sample(self.sample, 1, seed);
        (f64::from(a), f64::from(b))
    }
}

/// A 32-bit integer hash (Wellons' lowbias32): good avalanche, cheap.
impl Rng {
    /// Point `k` of a 2-D Sobol' sequence of its own for decision `stream` of this camera
    /// sample (Owen-scrambled per sample and stream): `k = 0..n` are stratified over the unit
    /// square, so the rays of one glossy lobe cover it evenly. `k` < 2^16.
    pub(crate) fn point(&self, stream: u32, k: u32) -> (f64, f64) {
        let seed = hash(self.seed ^ hash(self.sample ^ hash(stream.wrapping_add(0x632b_e5ab))));
        let a = sobol_burley::sample(k & 0xffff, 0, seed);
        let b = sobol_burley::sample(k & 0xffff, 1, seed);
        (f64::from(a), f64::from(b))
    }
}

impl Rng {
    /// The generator of path `j` of the `n` a path tracer traces for this camera sample: its
    /// sample index is `sample·n + j`, so all the paths of a pixel walk one Sobol' sequence
    /// (the render settings keep a pixel's paths within its 2^16 points).
    pub(crate) fn path(&self, j: u32, n: u32) -> Rng {
        Rng {
            seed: self.seed,
            sample: self.sample.wrapping_mul(n).wrapping_add(j) & 0xffff,
        }
    }

    /// A generator of its own for the decisions of group `key` (one bounce of a path):
    /// re-seeded, at the same sample index, so each group's points stay stratified over the
    /// pixel's samples and no two groups share them.
    pub(crate) fn derive(&self, key: u32) -> Rng {
        Rng {
            seed: hash(self.seed ^ hash(key ^ 0x2545_f491)),
            sample: self.sample,
        }
    }
}

fn hash(mut x: u32) -> u32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^= x >> 16;
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_offsets_are_cell_centres() {
        let g = Grid::new(4);
        assert_eq!(g.len(), 16);
        assert_eq!(g.offset(0), (0.125, 0.125));
        assert_eq!(g.offset(5), (0.375, 0.375));
        assert_eq!(g.offset(15), (0.875, 0.875));
        assert_eq!(Grid::new(1).offset(0), (0.5, 0.5));
        assert_eq!(Grid::new(0).len(), 1);
    }

    #[test]
    fn rng_is_a_pure_function_in_unit_square() {
        let a = Rng::new(3, 7, 2, 42);
        assert_eq!(a.get2(5), Rng::new(3, 7, 2, 42).get2(5));
        assert_ne!(a.get2(5), Rng::new(3, 7, 2, 43).get2(5));
        assert_ne!(a.get2(5), a.get2(6));
        for k in 0..64 {
            let (u, v) = Rng::new(1, 2, k, 0).get2(0);
            assert!((0.0..1.0).contains(&u) && (0.0..1.0).contains(&v));
        }
    }
}
