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
//! - [`noise`]: Perlin's improved noise (signed, and POV-Ray-like in [0, 1]), vector noise.

pub mod hash;
pub mod noise;

#[cfg(test)]
mod tests;
