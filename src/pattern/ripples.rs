//! Ripples and waves: concentric sine waves from a few fixed sources, summed (POV-Ray's
//! `ripples` and `waves`, whose sources are its `number_of_waves`, default 10).
//!
//! **Sources.** Source `i` is a point on the unit sphere and a relative frequency in
//! [0.01, 1.01), both from the hash of `i` (uniform on the sphere: `z = 1 − 2u`, angle `2πv`).
//! POV-Ray takes its sources from its own noise, so the centres differ from POV-Ray's but not
//! their kind: ripples rings centred within a unit of the origin, waves of unequal lengths.
//! The table is computed once (the first use), for at most [`MAX_WAVES`] sources.

use std::f64::consts::TAU;
use std::sync::LazyLock;

use glam::DVec3;

use crate::num::Norm;

use super::hash;

/// The most sources a ripples or waves pattern can sum.
pub const MAX_WAVES: usize = 32;

/// POV-Ray's default `number_of_waves`.
pub const DEFAULT_WAVES: u32 = 10;

/// The hash seed the sources are drawn under (fixed: the sources are part of the pattern).
const SOURCE_SEED: u32 = 0x7761_7665;

/// One source: where its rings start and its frequency relative to the pattern's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Source {
    /// A point on the unit sphere.
    pub center: DVec3,
    /// In [0.01, 1.01): a multiplier of the pattern's frequency (waves only).
    pub frequency: f64,
}

/// Source `i`.
fn source(i: usize) -> Source {
    let h = hash::lattice(SOURCE_SEED, i as i64, 0, 0);
    let (a, b) = (hash::mix(h ^ 0x1b87_3593), hash::mix(h ^ 0xcc9e_2d51));
    let z = 1.0 - 2.0 * hash::unit(h);
    let ring = (1.0 - z * z).max(0.0).sqrt();
    let angle = TAU * hash::unit(a);
    Source {
        center: DVec3::new(ring * libm::cos(angle), ring * libm::sin(angle), z),
        frequency: 0.01 + hash::unit(b),
    }
}

static SOURCES: LazyLock<[Source; MAX_WAVES]> = LazyLock::new(|| std::array::from_fn(source));

/// The first `count` sources (1 to [`MAX_WAVES`]).
pub fn sources(count: u32) -> &'static [Source] {
    &SOURCES[..(count as usize).clamp(1, MAX_WAVES)]
}

/// The distance from a source, 1 at the source itself (POV-Ray's guard).
#[inline(always)]
fn distance(p: DVec3, s: &Source) -> f64 {
    let d = p - s.center;
    let r = d.norm();
    if r == 0.0 { 1.0 } else { r }
}

/// `ripples`: `0.5·(1 + mean sin 2π(r·frequency + phase))` over the sources, `r` the distance
/// from each; in [0, 1].
#[inline]
pub fn ripples(p: DVec3, frequency: f64, phase: f64, count: u32) -> f64 {
    let sources = sources(count);
    let mut sum = 0.0;
    for s in sources {
        sum += libm::sin(TAU * (distance(p, s) * frequency + phase));
    }
    0.5 * (1.0 + sum / sources.len() as f64)
}

/// `waves`: `0.5 + 0.2·mean(sin 2π(r·frequency·fᵢ + phase) / fᵢ)`, `fᵢ` each source's relative
/// frequency: longer waves are taller. Within `0.5 ± 0.2·mean(1/fᵢ)` ([`waves_reach`]), not
/// [0, 1]; the wave wraps it, as in POV-Ray.
#[inline]
pub fn waves(p: DVec3, frequency: f64, phase: f64, count: u32) -> f64 {
    let sources = sources(count);
    let mut sum = 0.0;
    for s in sources {
        let index = distance(p, s) * frequency * s.frequency + phase;
        sum += libm::sin(TAU * index) / s.frequency;
    }
    0.5 + 0.2 * sum / sources.len() as f64
}

/// How far `waves` can stray from 0.5 with `count` sources: `0.2·mean(1/fᵢ)`.
pub fn waves_reach(count: u32) -> f64 {
    let sources = sources(count);
    let sum: f64 = sources.iter().map(|s| 1.0 / s.frequency).sum();
    0.2 * sum / sources.len() as f64
}
