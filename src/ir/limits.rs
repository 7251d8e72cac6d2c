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
pub(crate) const MAX_PIXEL_SAMPLES_PER_AXIS: u32 = 64;

/// Most samples along one edge of an area light: the Sobol' sampler indexes at most 2^16
/// samples per decision (256×256).
pub(crate) const MAX_LIGHT_SAMPLES_PER_AXIS: u32 = 256;

/// Widest or tallest image, in pixels.
pub(crate) const MAX_IMAGE_SIDE: u32 = 16384;

/// Most memory a render's image may take, in bytes: the film and the 8-bit image, as counted
/// by [`image_bytes`]. A larger image is refused before anything is built (`rtc check` and
/// `rtc render` both say so), not when an allocation fails halfway.
pub const MAX_IMAGE_BYTES: u64 = 4 << 30;

/// Film bytes per pixel per pass: one f64 RGB colour (the film's one channel).
const FILM_BYTES_PER_PIXEL: u64 = 24;

/// Bytes per pixel of the 8-bit RGB image the film is quantised to.
const IMAGE_BYTES_PER_PIXEL: u64 = 3;

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
pub(crate) const MAX_TRIANGLES: usize = 50_000_000;

/// Largest OBJ file rtc reads, in bytes (checked before reading; a file within
/// [`MAX_TRIANGLES`] is about 2 GB of text).
pub const MAX_MESH_FILE_BYTES: u64 = 4 << 30;

/// Most pixels of one texture image (checked from the file's header, before decoding): each
/// decoded texel takes 24 bytes, so 2²⁶ pixels (8192×8192) are 1.5 GiB.
pub const MAX_TEXTURE_PIXELS: u64 = 1 << 26;

/// The most points a height field's grid may have (4096 × 4096: 64 MiB of heights), from an
/// image or a `resolution`.
pub const MAX_HEIGHT_FIELD_POINTS: u64 = 1 << 24;

/// Largest texture image file rtc opens, in bytes (checked before reading): an uncompressed
/// 8192×8192 float EXR of three channels is 805 MB.
pub(crate) const MAX_TEXTURE_FILE_BYTES: u64 = 1 << 30;
/// Most rays per glossy lobe (`gloss_samples`): the lobe's samples are one Sobol' sequence of
/// at most this many points per camera sample.
pub(crate) const MAX_GLOSS_SAMPLES: u32 = 1024;

/// Bytes one scene load may hold unless `--memory-budget` says otherwise: the evaluation's
/// strings, lists and objects, then the textures and meshes the preparation loads. Generous
/// for real scenes (a million spheres charge about 300 MB, the largest test mesh 60 MB) and
/// well inside a 24 GiB machine; four 8192² textures (1.5 GiB each) do not fit.
pub const DEFAULT_MEMORY_BUDGET: u64 = 4 << 30;

/// The diagnostic code of a load past its memory budget.
pub const MEMORY_BUDGET_CODE: &str = "rtc::budget::memory";

/// A scene load's memory budget and the bytes charged to it so far. Charges are counted
/// where the bytes are asked for, before they are allocated, and never given back (a string
/// built and dropped in a loop still counts), so the count bounds the work of building values
/// as well as what they hold; the same scene charges the same bytes in the same order on any
/// machine and thread count.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Memory {
    /// Most bytes the load may charge.
    pub(crate) budget: u64,
    /// Bytes charged so far.
    pub(crate) used: u64,
}

impl Default for Memory {
    fn default() -> Memory {
        Memory::new(DEFAULT_MEMORY_BUDGET)
    }
}

/// A charge that does not fit a [`Memory`] budget.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct MemoryOver {
    /// Bytes asked for.
    asked: u64,
    /// Bytes already charged.
    pub(crate) used: u64,
    /// The budget.
    pub(crate) budget: u64,
}

impl Memory {
    /// Nothing charged yet under `budget`.
    pub(crate) fn new(budget: u64) -> Memory {
        Memory { budget, used: 0 }
    }

    /// Charges `bytes` when they fit; otherwise charges nothing and says by how much not.
    pub(crate) fn charge(&mut self, bytes: u64) -> Result<(), MemoryOver> {
        match self.used.checked_add(bytes) {
            Some(total) if total <= self.budget => {
                self.used = total;
                Ok(())
            }
            _ => Err(MemoryOver {
                asked: bytes,
                used: self.used,
                budget: self.budget,
            }),
        }
    }

    /// Bytes still free (the tests').
    #[cfg(test)]
    fn left(&self) -> u64 {
        self.budget.saturating_sub(self.used)
    }
}

impl MemoryOver {
    /// The error at `span`, where `what` (e.g. "this texture") asked for the bytes.
    pub(crate) fn diagnostic(
        &self,
        span: crate::source::Span,
        what: &str,
    ) -> crate::diag::Diagnostic {
        crate::diag::Diagnostic::error(
            MEMORY_BUDGET_CODE,
            span,
            format!(
                "the scene needs more than its memory budget of {}",
                show_bytes(self.budget)
            ),
        )
        .with_label(format!(
            "{what} would take {} more, with {} already in use",
            show_bytes(self.asked),
            show_bytes(self.used)
        ))
        .with_help(format!(
            "make the scene smaller, or allow more with `--memory-budget {}`",
            show_bytes(self.used.saturating_add(self.asked).next_power_of_two()).replace(' ', "")
        ))
    }
}

/// Bytes for people: `512 B`, `1.5 KiB`, `4 GiB`.
fn show_bytes(bytes: u64) -> String {
    const UNITS: [&str; 5] = ["B", "KiB", "MiB", "GiB", "TiB"];
    let mut value = bytes as f64;
    let mut unit = 0;
    while value >= 1024.0 && unit + 1 < UNITS.len() {
        value /= 1024.0;
        unit += 1;
    }
    if unit == 0 || value.fract() == 0.0 {
        format!("{value} {}", UNITS[unit])
    } else {
        format!("{value:.1} {}", UNITS[unit])
    }
}

/// A size as the command line writes it: a number of bytes, optionally with a unit (`K`,
/// `KiB`, `M`, `MiB`, `G`, `GiB`, `T`, `TiB`, powers of 1024; case ignored): `4GiB`, `512M`,
/// `1.5G`.
pub fn parse_bytes(text: &str) -> Result<u64, String> {
    let t = text.trim();
    let split = t
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(t.len());
    let (number, unit) = (&t[..split], t[split..].trim());
    let value: f64 = number
        .parse()
        .map_err(|_| format!("`{text}` is not a size: write bytes or e.g. `512MiB`, `4GiB`"))?;
    let scale: u64 = match unit.to_ascii_lowercase().as_str() {
        "" | "b" => 1,
        "k" | "kb" | "kib" => 1 << 10,
        "m" | "mb" | "mib" => 1 << 20,
        "g" | "gb" | "gib" => 1 << 30,
        "t" | "tb" | "tib" => 1 << 40,
        _ => {
            return Err(format!(
                "`{unit}` is not a size unit: use KiB, MiB, GiB or TiB"
            ));
        }
    };
    let bytes = value * scale as f64;
    if !bytes.is_finite() || bytes < 1.0 || bytes > u64::MAX as f64 {
        return Err(format!("`{text}` is not a usable size"));
    }
    Ok(bytes as u64)
}

/// The most paths the path tracer traces per camera ray.
pub const MAX_PATH_SAMPLES: u32 = 4096;

/// The most scattering events along one path.
pub const MAX_BOUNCES: u32 = 256;

/// The most paths per pixel (camera samples × paths): each decision's numbers come from one
/// scrambled Sobol' sequence per pixel, which holds 2^16 distinct points.
pub const MAX_PIXEL_PATHS: u32 = 1 << 16;

#[cfg(test)]
mod tests {
    use super::*;

    /// A charge fits up to the budget exactly; one past it is refused and charges nothing.
    #[test]
    fn charges_fit_up_to_the_budget() {
        let mut m = Memory::new(100);
        assert!(m.charge(60).is_ok());
        assert!(m.charge(40).is_ok());
        assert_eq!(m.left(), 0);
        let over = m.charge(1).unwrap_err();
        assert_eq!((over.asked, over.used, over.budget), (1, 100, 100));
        assert_eq!(m.used, 100);
        assert!(m.charge(u64::MAX).is_err(), "no overflow");
    }

    #[test]
    fn sizes_parse_and_show() {
        assert_eq!(parse_bytes("4GiB"), Ok(4 << 30));
        assert_eq!(parse_bytes("512m"), Ok(512 << 20));
        assert_eq!(parse_bytes("1.5 G"), Ok(3 << 29));
        assert_eq!(parse_bytes("1000"), Ok(1000));
        assert!(parse_bytes("lots").is_err());
        assert!(parse_bytes("4 parsecs").is_err());
        assert!(parse_bytes("0").is_err());
        assert_eq!(show_bytes(4 << 30), "4 GiB");
        assert_eq!(show_bytes(1536), "1.5 KiB");
        assert_eq!(show_bytes(12), "12 B");
    }
}
