//! Procedural patterns: scalar fields of position for textures, after POV-Ray 3.7's pattern
//! set, on rtc's own noise (docs/textures.md has the definitions, ranges and how they differ
//! from POV-Ray's).
//!
//! A leaf: it imports nothing of the crate but [`crate::num`], and every stage may use it. Every
//! function is pure and deterministic: random choices come from an integer hash ([`hash`]),
//! transcendental functions from the `libm` crate, square roots from `f64::sqrt` (correctly
//! rounded), so a pattern gives the same bits on every CPU and thread. Nothing allocates per
//! evaluation.
//!
//! - [`noise`]: Perlin's improved noise (signed, and POV-Ray-like in [0, 1]), vector noise;
//! - [`fbm`]: fractal sums (fBm, turbulence, POV-Ray's scalar turbulence, vector fBm);
//! - [`cells`]: Worley's F1 and F2;
//! - [`program`]: user functions of position compiled to register operations;
//! - [`Pattern`] ([`field`]): the closed set of patterns, implemented in [`geometric`],
//!   [`tilings`], [`noisy`] and [`ripples`];
//! - modifiers: [`waves`] (frequency, phase, wave shapes), [`warps`] (turbulence, repeat), and
//!   [`Field`], a pattern with its warps and wave.

pub mod cells;
pub mod color_map;
pub mod fbm;
pub mod field;
pub mod geometric;
pub mod hash;
pub mod noise;
pub mod noisy;
pub mod program;
pub mod ripples;
pub mod slopes;
pub mod tilings;
pub mod turbulence;
pub mod warps;
pub mod waves;

pub use color_map::{ColorMap, Rgbft, Stop};
pub use fbm::Fractal;
pub use field::{Field, NAMES, Pattern};
pub use noisy::Crackle;
pub use program::Program;
pub use turbulence::Turbulence;
pub use warps::{Repeat, Warp};
pub use waves::{Wave, WaveShape};

#[cfg(test)]
mod tests;
