//! Patterns built on noise: bozo (spotted, bumps), dents, granite, wrinkles, agate, marble,
//! wood, leopard and crackle, after POV-Ray 3.7's definitions for its default noise generator,
//! with rtc's noise ([`super::noise::unit`] where POV-Ray reads its `Noise`). Where POV-Ray sums
//! noise at scaled points, each scale here reads its own seed ([`super::fbm::octave_seed`]).

use std::f64::consts::TAU;

use glam::DVec3;

use super::cells::{self, Nearest};
use super::fbm::{self, Fractal, octave_seed};
use super::noise;
use super::turbulence::Turbulence;

/// `bozo` (also `spotted`, and `bumps` as a normal): the noise itself, in [0, 1], mean 0.5.
#[inline]
pub fn bozo(p: DVec3, seed: u32) -> f64 {
    noise::unit(p, seed)
}

/// `dents`: the noise cubed, in [0, 1], mean 0.15: mostly low, with sharp rises.
#[inline]
pub fn dents(p: DVec3, seed: u32) -> f64 {
    let n = noise::unit(p, seed);
    n * n * n
}

/// `granite`: six octaves of `min(|1 − 2·noise|, 0.5)` (a crease where the noise crosses its
/// mean), starting at frequency 4, each twice the frequency and half the weight of the one
/// before; in [0, 0.984375], mean 0.42.
#[inline]
pub fn granite(p: DVec3, seed: u32) -> f64 {
    let mut sum = 0.0;
    let mut scale = 1.0;
    for i in 0..6 {
        let n = noise::unit(p * (4.0 * scale), octave_seed(seed, i));
        sum += (1.0 - 2.0 * n).abs().min(0.5) / scale;
        scale *= 2.0;
    }
    sum
}

/// `wrinkles`: half the sum of ten octaves of `clamp(2·noise − 0.5, 0, 1)` (a contrast-raised
/// noise), lambda 2 and omega 0.5; in [0, 0.999], mean 0.50.
#[inline]
pub fn wrinkles(p: DVec3, seed: u32) -> f64 {
    let mut sum = 0.0;
    let mut scale = 1.0;
    for i in 0..10 {
        let n = noise::unit(p * scale, octave_seed(seed, i));
        sum += (2.0 * n - 0.5).clamp(0.0, 1.0) / scale;
        scale *= 2.0;
    }
    0.5 * sum
}

/// `leopard`: `((sin x + sin y + sin z) / 3)²`, regular spots on a 2π lattice; in [0, 1].
#[inline]
pub fn leopard(p: DVec3) -> f64 {
    let s = (libm::sin(p.x) + libm::sin(p.y) + libm::sin(p.z)) / 3.0;
    s * s
}

/// `agate`: bands along z bent by turbulence, `(0.5·(sin 2π(1.3·t + 1.1·z) + 1))^0.77` with
/// `t = turb · classic(p)` (POV-Ray's `agate_turb`, default 1, and the pattern's octaves,
/// omega and lambda); in [0, 1].
#[inline]
pub fn agate(p: DVec3, turb: f64, fractal: &Fractal, seed: u32) -> f64 {
    let t = turb * fbm::classic(p, fractal, seed);
    let v = 0.5 * (libm::sin(TAU * (1.3 * t + 1.1 * p.z)) + 1.0);
    libm::pow(v.clamp(0.0, 1.0), 0.77)
}

/// `marble`: `x + turbulence.x · classic(p)`: a ramp along x pushed back and forth by the
/// scalar turbulence. Unbounded; its default wave is the triangle, so bands rise and fall
/// every unit.
#[inline]
pub fn marble(p: DVec3, turbulence: &Turbulence) -> f64 {
    p.x + turbulence.scalar(p)
}

/// `wood`: the distance from the z axis with x and y each pushed by `sin 2π((x + Tₓ)·amountₓ)`
/// (and likewise y), `T` the vector turbulence: rings about z, wobbling. At least 0,
/// unbounded; its default wave is the triangle, so rings rise and fall every unit.
#[inline]
pub fn wood(p: DVec3, turbulence: &Turbulence) -> f64 {
    let (mut x, mut y) = (p.x, p.y);
    if !turbulence.is_none() {
        let t = fbm::vector(p, &turbulence.fractal, turbulence.seed);
        x += libm::sin(TAU * (p.x + t.x) * turbulence.amount.x);
        y += libm::sin(TAU * (p.y + t.y) * turbulence.amount.y);
    }
    (x * x + y * y).sqrt()
}

/// Which Worley distance crackle shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Crackle {
    /// F1: 0 at each feature point, rising towards the cell walls (POV-Ray's `form <1, 0, 0>`).
    F1,
    /// F2: the distance to the second nearest point (`form <0, 1, 0>`).
    F2,
    /// F2 − F1: 0 on the cell walls, rising inside (POV-Ray's default crackle, `form <-1, 1, 0>`).
    Edges,
}

impl Crackle {
    /// This form's value of the two distances, clamped into [0, 1] as POV-Ray clamps.
    #[inline]
    pub fn of(self, d: Nearest) -> f64 {
        let v = match self {
            Crackle::F1 => d.f1,
            Crackle::F2 => d.f2,
            Crackle::Edges => d.f2 - d.f1,
        };
        v.clamp(0.0, 1.0)
    }
}

/// `crackle`: a Worley distance ([`cells::worley`], one feature point per unit cube) in [0, 1].
#[inline]
pub fn crackle(p: DVec3, form: Crackle, seed: u32) -> f64 {
    form.of(cells::worley(p, seed))
}
