//! Fractal sums of noise: octave `i` (counting from 0) is noise at `λⁱ·p` weighted `ωⁱ`, with
//! POV-Ray's names and defaults: `octaves` 6, `omega` (the gain) 0.5, `lambda` (the
//! lacunarity) 2. Each octave reads the noise under a seed of its own (octave 0 under the
//! caller's seed, octave `i` under [`hash::derive`]`(seed, i)`), so the octaves are
//! independent: the variance of a sum of `n` octaves is `σ²·Σ ω²ⁱ` exactly in expectation, and
//! the octaves do not all agree at the origin as POV-Ray's (one noise at scaled points) do.

use glam::DVec3;

use super::{hash, noise};

/// Octave count, gain and lacunarity of a fractal sum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fractal {
    /// How many octaves (at least one is always summed, as in POV-Ray).
    pub octaves: u32,
    /// Each octave's weight relative to the one before (POV-Ray's `omega`; the gain).
    pub omega: f64,
    /// Each octave's frequency relative to the one before (POV-Ray's `lambda`; the lacunarity).
    pub lambda: f64,
}

impl Default for Fractal {
    /// POV-Ray's defaults: 6 octaves, omega 0.5, lambda 2.
    fn default() -> Fractal {
        Fractal {
            octaves: 6,
            omega: 0.5,
            lambda: 2.0,
        }
    }
}

impl Fractal {
    /// `Σ ωⁱ` over the octaves: the most a sum of values in [−1, 1] can reach.
    pub fn amplitude(&self) -> f64 {
        let mut sum = 0.0;
        let mut weight = 1.0;
        for _ in 0..self.octaves.max(1) {
            sum += weight;
            weight *= self.omega;
        }
        sum
    }

    /// Calls `f(octave, seed, weight, point)` for each octave, in order.
    #[inline(always)]
    fn each(&self, p: DVec3, seed: u32, mut f: impl FnMut(u32, u32, f64, DVec3)) {
        let (mut weight, mut scale) = (1.0, 1.0);
        for i in 0..self.octaves.max(1) {
            f(i, octave_seed(seed, i), weight, p * scale);
            weight *= self.omega;
            scale *= self.lambda;
        }
    }
}

/// The seed octave `i` reads its noise under.
#[inline(always)]
pub fn octave_seed(seed: u32, i: u32) -> u32 {
    if i == 0 { seed } else { hash::derive(seed, i) }
}

/// Fractional Brownian motion: `Σ ωⁱ·signed(λⁱp)`. Mean 0; within ±`BOUND`·`amplitude()`.
#[inline]
pub fn fbm(p: DVec3, fractal: &Fractal, seed: u32) -> f64 {
    let mut sum = 0.0;
    fractal.each(p, seed, |_, s, w, q| sum += w * noise::signed(q, s));
    sum
}

/// Perlin's turbulence: `Σ ωⁱ·|signed(λⁱp)|`. At least 0; at most `BOUND`·`amplitude()`; mean
/// 0.22·`amplitude()`.
#[inline]
pub fn turbulence(p: DVec3, fractal: &Fractal, seed: u32) -> f64 {
    let mut sum = 0.0;
    fractal.each(p, seed, |_, s, w, q| sum += w * noise::signed(q, s).abs());
    sum
}

/// Vector fBm: `Σ ωⁱ·vector(λⁱp)` (POV-Ray's `DTurbulence`, the displacement of its
/// turbulence warp). Each component has mean 0.
#[inline]
pub fn vector(p: DVec3, fractal: &Fractal, seed: u32) -> DVec3 {
    let mut sum = DVec3::ZERO;
    fractal.each(p, seed, |_, s, w, q| sum += w * noise::vector(q, s));
    sum
}

/// POV-Ray's scalar turbulence for its default noise generator, the value marble, agate and the
/// spirals add: `clamp(2·unit(p) − 0.5, 0, 1) + Σᵢ≥₁ ωⁱ·(2·unit(λⁱp) − 0.5)`. With
/// `unit = 0.5 + 0.5·signed` each term is `0.5 + signed`: mean `0.5·amplitude()`, the first
/// term in [0, 1], the others within `ωⁱ·(0.5 ± BOUND)`.
#[inline]
pub fn classic(p: DVec3, fractal: &Fractal, seed: u32) -> f64 {
    let mut sum = 0.0;
    fractal.each(p, seed, |i, s, w, q| {
        let term = 2.0 * noise::unit(q, s) - 0.5;
        sum += if i == 0 {
            term.clamp(0.0, 1.0)
        } else {
            w * term
        };
    });
    sum
}
