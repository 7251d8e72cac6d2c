//! Limits every stage shares, defined once: the language, both course front ends and the
//! renderer check against these constants. The language and a hand-built IR get an error past a
//! limit; a course file asking for more bounces gets a warning and [`MAX_DEPTH`] (the course
//! files predate rtc, so they are read as far as they can be).

/// Most reflection/refraction bounces. 64 bounces cover any mirror or glass scene (each bounce
/// weighs at most `reflect + refract ≤ 1`, so a 64th bounce rarely moves a byte), and keep the
/// Whitted recursion within the render threads' stacks.
pub const MAX_DEPTH: u32 = 64;

/// Most samples per axis of a pixel grid (supersampling, adaptive `min`/`max`): 64×64 = 4096
/// samples per pixel; beyond this a render never ends anyway.
pub const MAX_PIXEL_SAMPLES_PER_AXIS: u32 = 64;

/// Most samples along one edge of an area light: the Sobol' sampler indexes at most 2^16
/// samples per decision (256×256).
pub const MAX_LIGHT_SAMPLES_PER_AXIS: u32 = 256;

/// Widest or tallest image, in pixels.
pub const MAX_IMAGE_SIDE: u32 = 16384;

/// Largest image, in pixels (the film holds 24 bytes per pixel per channel: 3 GiB).
pub const MAX_PIXELS: u64 = 1 << 27;

/// Most triangles one mesh file may have (about 7 GB of geometry and BVH; the BVH itself indexes
/// up to 2²⁶ primitives).
pub const MAX_TRIANGLES: usize = 50_000_000;

/// Most rays per glossy lobe (`gloss_samples`): the lobe's samples are one Sobol' sequence of
/// at most this many points per camera sample.
pub const MAX_GLOSS_SAMPLES: u32 = 1024;
