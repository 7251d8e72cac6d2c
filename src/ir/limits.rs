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

/// Most memory a render's image may take, in bytes: the film and the 8-bit image, as counted
/// by [`image_bytes`]. A larger image is refused before anything is built (`rtc check` and
/// `rtc render` both say so), not when an allocation fails halfway.
pub const MAX_IMAGE_BYTES: u64 = 4 << 30;

/// Film bytes per pixel per pass: one f64 RGB colour (the film's one channel).
pub const FILM_BYTES_PER_PIXEL: u64 = 24;

/// Bytes per pixel of the 8-bit RGB image the film is quantised to.
pub const IMAGE_BYTES_PER_PIXEL: u64 = 3;

/// The memory a `width`×`height` render holds at its peak: 24 bytes of film per pixel, twice
/// under adaptive sampling (the coarse pass is kept while the fine pass runs), plus 3 bytes per
/// pixel of 8-bit image. A 16384×16384 image needs 7 GiB on a grid and is refused; 8192×8192
/// needs 1.7 GiB (3.3 GiB adaptive).
pub fn image_bytes(width: u32, height: u32, adaptive: bool) -> u64 {
    let passes = if adaptive { 2 } else { 1 };
    // Saturating: u32::MAX × u32::MAX pixels are past any budget, not an overflow.
    (u64::from(width) * u64::from(height))
        .saturating_mul(passes * FILM_BYTES_PER_PIXEL + IMAGE_BYTES_PER_PIXEL)
}

/// Most triangles one mesh file may have (about 7 GB of geometry and BVH; the BVH itself indexes
/// up to 2²⁶ primitives).
pub const MAX_TRIANGLES: usize = 50_000_000;

/// Largest OBJ file rtc reads, in bytes (checked before reading; a file within
/// [`MAX_TRIANGLES`] is about 2 GB of text).
pub const MAX_MESH_FILE_BYTES: u64 = 4 << 30;

/// Most pixels of one texture image (checked from the file's header, before decoding): each
/// decoded texel takes 24 bytes, so 2²⁶ pixels (8192×8192) are 1.5 GiB.
pub const MAX_TEXTURE_PIXELS: u64 = 1 << 26;

/// Largest texture image file rtc opens, in bytes (checked before reading): an uncompressed
/// 8192×8192 float EXR of three channels is 805 MB.
pub const MAX_TEXTURE_FILE_BYTES: u64 = 1 << 30;
/// Most rays per glossy lobe (`gloss_samples`): the lobe's samples are one Sobol' sequence of
/// at most this many points per camera sample.
pub const MAX_GLOSS_SAMPLES: u32 = 1024;
