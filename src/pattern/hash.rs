//! The integer hash every random choice of the patterns comes from: lattice gradients, feature
//! points of cells, wave sources. Pure 32-bit integer arithmetic (wrapping multiplies, shifts,
//! exclusive or), so every machine and thread count gets the same bits, and no table: any seed
//! works and nothing repeats before the lattice coordinates wrap at 2³².
//!
//! The mixer is Chris Wellons' `lowbias32` (found by his hash-prospector search: two
//! multiply-xorshift rounds, bias ≈ 0.17 on his avalanche measure). It is a bijection of `u32`,
//! so for a fixed seed `x ↦ mix(key(seed) ^ x)` is a permutation of the 2³² integers: a seed
//! selects a permutation, as Ken Perlin's table does for 256 entries, and a lattice point
//! `(x, y, z)` hashes as Perlin's `P[P[P[x] + y] + z]` chains, with `^` for `+`:
//!
//! ```text
//! hash(seed, x, y, z) = mix(mix(mix(key(seed) ^ x) ^ y) ^ z),   key(seed) = mix(seed ^ 0x9e3779b9)
//! ```
//!
//! Coordinates enter as their two's-complement bits (`i64 as u32`: wrapping). The chain shares
//! its prefixes, so the eight corners of a noise cell cost 2 + 4 + 8 mixes.

/// Wellons' `lowbias32`: a bijective 32-bit mixer with good avalanche.
#[inline(always)]
pub fn mix(mut x: u32) -> u32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^= x >> 16;
    x
}

/// The key a seed starts every chain with (the golden-ratio constant keeps seed 0 off the
/// mixer's fixed point at 0).
#[inline(always)]
pub fn key(seed: u32) -> u32 {
    mix(seed ^ 0x9e37_79b9)
}

/// One more coordinate into a chain: `mix(chain ^ coordinate)`.
#[inline(always)]
pub fn chain(h: u32, coordinate: u32) -> u32 {
    mix(h ^ coordinate)
}

/// The hash of lattice point `(x, y, z)` under `seed` (the module's formula).
#[inline(always)]
pub fn lattice(seed: u32, x: i64, y: i64, z: i64) -> u32 {
    chain(chain(chain(key(seed), x as u32), y as u32), z as u32)
}

/// The seed of octave or component `i` derived from `seed` (Weyl steps of the golden ratio, so
/// neighbouring seeds' derived seeds do not collide).
#[inline(always)]
pub fn derive(seed: u32, i: u32) -> u32 {
    seed.wrapping_add(i.wrapping_add(1).wrapping_mul(0x9e37_79b9))
}

/// A hash as a number in [0, 1) (all 32 bits, exactly representable).
#[inline(always)]
pub fn unit(h: u32) -> f64 {
    f64::from(h) * (1.0 / 4_294_967_296.0)
}
