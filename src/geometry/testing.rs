//! Helpers of the geometry room's unit tests.

/// Uniform numbers in [0, 1) from a seeded 64-bit LCG (Knuth's MMIX constants, top 53 bits):
/// reproducible random spheres and rays for unit tests.
pub(crate) fn test_uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut seed = seed;
    move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((seed >> 11) as f64) / (1u64 << 53) as f64
    }
}
