//! Texture images: decoded once into linear channels in [0, 1]; lookups are nearest-pixel as
//! the course framework does (COURSE.md §2.5).

use std::path::Path;

use glam::{DVec2, DVec3};

use crate::diag::Diagnostic;
use crate::ir::limits::{MAX_TEXTURE_FILE_BYTES, MAX_TEXTURE_PIXELS};
use crate::source::Span;

/// A decoded image with channels in [0, 1].
#[derive(Clone, Debug)]
pub struct Picture {
    width: u32,
    height: u32,
    texels: Vec<DVec3>,
}

/// Why an image could not be decoded.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ImageError {
    /// What went wrong (the decoder's message).
    pub message: String,
    /// True when the file could not be opened at all.
    missing: bool,
    /// True when the image has more than [`MAX_TEXTURE_PIXELS`] pixels.
    too_large: bool,
}

/// Whether `path` is a JPEG (it starts with the SOI marker FF D8) with no end-of-image marker
/// (FF D9) after its last start-of-scan (FF DA): cut short, which the decoder does not report.
fn jpeg_truncated(path: &Path) -> bool {
    std::fs::read(path).is_ok_and(|bytes| jpeg_bytes_truncated(&bytes))
}

/// [`jpeg_truncated`] of a file's bytes.
pub(super) fn jpeg_bytes_truncated(bytes: &[u8]) -> bool {
    if !bytes.starts_with(&[0xff, 0xd8]) {
        return false;
    }
    let last_scan = bytes.windows(2).rposition(|w| w == [0xff, 0xda]);
    let after = last_scan.map_or(bytes, |p| &bytes[p..]);
    !after.windows(2).any(|w| w == [0xff, 0xd9])
}

/// The largest data window among an EXR file's parts, in pixels (0 for other formats). The
/// decoder reports an EXR's display window as its size but reads, and allocates, by the data
/// windows: a 537-byte file with a 2×2 display window and a 2×10⁹ data window took 1.7 GB
/// (`fuzz/found/texture-3-exr-data-window`).
fn exr_data_window_pixels(path: &Path) -> Result<u64, ImageError> {
    if image::ImageFormat::from_path(path).ok() != Some(image::ImageFormat::OpenExr) {
        return Ok(0);
    }
    let meta = exr::meta::MetaData::read_from_file(path, false).map_err(|e| ImageError {
        message: e.to_string(),
        missing: false,
        too_large: false,
    })?;
    Ok(meta
        .headers
        .iter()
        .map(|h| h.layer_size.width() as u64 * h.layer_size.height() as u64)
        .max()
        .unwrap_or(0))
}

/// Bytes one decoded texel takes (three f64 channels).
const DECODED_BYTES_PER_PIXEL: u64 = std::mem::size_of::<DVec3>() as u64;

/// Bytes the image at `path` takes once decoded, from its header alone; `None` when it is not
/// a regular file within the byte budget or its header cannot be read.
pub(crate) fn header_bytes(path: &Path) -> Option<u64> {
    let (w, h) = header_size(path)?;
    Some(u64::from(w) * u64::from(h) * DECODED_BYTES_PER_PIXEL)
}

/// The width and height of the image at `path` from its header alone; `None` when it is not
/// a regular file within the byte budget or its header cannot be read.
pub(crate) fn header_size(path: &Path) -> Option<(u32, u32)> {
    crate::source::open_regular(path, MAX_TEXTURE_FILE_BYTES).ok()?;
    image::ImageReader::open(path).ok()?.into_dimensions().ok()
}

impl Picture {
    /// Wraps texels stored row by row from the top (`texels.len() == width·height`, both ≥ 1).
    pub(crate) fn new(width: u32, height: u32, texels: Vec<DVec3>) -> Option<Picture> {
        let ok = width > 0 && height > 0 && texels.len() == width as usize * height as usize;
        ok.then_some(Picture {
            width,
            height,
            texels,
        })
    }

    /// Decodes an image file (PNG, JPEG, HDR or EXR, by extension).
    pub fn load(path: &Path) -> Result<Picture, ImageError> {
        // Only a regular file within the byte budget: a device or a FIFO would be read for ever.
        if let Err(e) = crate::source::open_regular(path, MAX_TEXTURE_FILE_BYTES) {
            return Err(ImageError {
                too_large: e.kind() == std::io::ErrorKind::FileTooLarge,
                missing: e.kind() != std::io::ErrorKind::FileTooLarge,
                message: e.to_string(),
            });
        }
        let open = || {
            image::ImageReader::open(path).map_err(|e| ImageError {
                message: e.to_string(),
                missing: true,
                too_large: false,
            })
        };
        let malformed = |e: image::ImageError| ImageError {
            message: e.to_string(),
            missing: false,
            too_large: false,
        };
        // The budget is checked on the header's size before decoding (a small file can claim
        // a huge image); the decoder's own limits (512 MiB) stay as a second guard.
        let (w, h) = open()?.into_dimensions().map_err(malformed)?;
        let data_window = exr_data_window_pixels(path)?;
        within_budget(w, h, data_window)?;
        if jpeg_truncated(path) {
            return Err(truncated_jpeg());
        }
        // The format comes from the extension.
        let decoded = open()?.decode().map_err(malformed)?;
        Picture::of_decoded(&decoded)
    }

    /// The texels of a decoded image: 8-bit images convert exactly as byte/255 in f64, like
    /// the course framework; others through f32.
    pub(super) fn of_decoded(decoded: &image::DynamicImage) -> Result<Picture, ImageError> {
        let (w, h) = (decoded.width(), decoded.height());
        let texels: Vec<DVec3> =
            if decoded.color().bytes_per_pixel() == decoded.color().channel_count() {
                let to = |b: u8| f64::from(b) / 255.0;
                decoded
                    .to_rgb8()
                    .pixels()
                    .map(|p| DVec3::new(to(p[0]), to(p[1]), to(p[2])))
                    .collect()
            } else {
                decoded
                    .to_rgb32f()
                    .pixels()
                    .map(|p| DVec3::new(f64::from(p[0]), f64::from(p[1]), f64::from(p[2])))
                    .collect()
            };
        Picture::new(w, h, texels).ok_or_else(|| ImageError {
            message: "the image has no pixels".into(),
            missing: false,
            too_large: false,
        })
    }

    /// Width and height in texels.
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// The texel in column `x`, row `y` from the top (both in range).
    pub fn texel(&self, x: u32, y: u32) -> DVec3 {
        self.texels[y as usize * self.width as usize + x as usize]
    }

    /// The size of one texel in (u, v).
    pub(crate) fn texel_size(&self) -> (f64, f64) {
        (1.0 / f64::from(self.width), 1.0 / f64::from(self.height))
    }

    /// The texel at `(int(u·(w−1)), int(v·(h−1)))`, v = 0 at the top row; u, v are clamped to [0, 1].
    pub fn nearest(&self, uv: DVec2) -> DVec3 {
        let pick = |t: f64, n: u32| {
            let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
            ((t * f64::from(n - 1)) as u32).min(n - 1) as usize
        };
        let (x, y) = (pick(uv.x, self.width), pick(uv.y, self.height));
        self.texels[y * self.width as usize + x]
    }

    /// The texels around `uv` blended by distance: texel `(i, j)`'s centre is at
    /// `((i + ½)/w, (j + ½)/h)`, and beyond the outer centres the edge texels hold (clamped).
    pub fn bilinear(&self, uv: DVec2) -> DVec3 {
        let axis = |t: f64, n: u32| {
            let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
            let x = (t * f64::from(n) - 0.5).clamp(0.0, f64::from(n - 1));
            let i = (x.floor() as u32).min(n - 1);
            let j = (i + 1).min(n - 1);
            (i as usize, j as usize, x - f64::from(i))
        };
        let (x0, x1, fx) = axis(uv.x, self.width);
        let (y0, y1, fy) = axis(uv.y, self.height);
        let w = self.width as usize;
        let at = |x: usize, y: usize| self.texels[y * w + x];
        let top = at(x0, y0) + (at(x1, y0) - at(x0, y0)) * fx;
        let bottom = at(x0, y1) + (at(x1, y1) - at(x0, y1)) * fx;
        top + (bottom - top) * fy
    }

    /// Approximate heap bytes.
    pub(crate) fn memory(&self) -> usize {
        self.texels.len() * std::mem::size_of::<DVec3>()
    }
}

/// The error of an image over the pixel budget (by its header's size or, for EXR, its
/// largest data window), else `Ok`.
pub(super) fn within_budget(w: u32, h: u32, data_window: u64) -> Result<(), ImageError> {
    let pixels = u64::from(w) * u64::from(h);
    let over = if pixels > MAX_TEXTURE_PIXELS {
        Some(format!("it is {w}×{h} = {pixels} pixels"))
    } else if data_window > MAX_TEXTURE_PIXELS {
        Some(format!("its data window has {data_window} pixels"))
    } else {
        None
    };
    match over {
        Some(what) => Err(ImageError {
            message: format!("{what}; at most {MAX_TEXTURE_PIXELS} are decoded"),
            missing: false,
            too_large: true,
        }),
        None => Ok(()),
    }
}

/// The error of a JPEG cut short: the decoder fills a truncated scan with grey and reports
/// nothing.
pub(super) fn truncated_jpeg() -> ImageError {
    ImageError {
        message: "the JPEG data ends before its end-of-image marker: the file is truncated".into(),
        missing: false,
        too_large: false,
    }
}

impl ImageError {
    /// The error of an image that cannot be decoded (`message` says why).
    pub(super) fn malformed(message: String) -> ImageError {
        ImageError {
            message,
            missing: false,
            too_large: false,
        }
    }

    /// The diagnostic for this error on the image `path` named at `span`:
    /// `rtc::texture::{not_found, too_large, malformed}`.
    pub(crate) fn diagnostic(&self, span: Span, path: &Path) -> Diagnostic {
        if self.too_large {
            return Diagnostic::error(
                "rtc::texture::too_large",
                span,
                format!("the image `{}` is too large", path.display()),
            )
            .with_label(self.message.clone())
            .with_help("scale the image down to at most 8192×8192 pixels");
        }
        let (code, what) = if self.missing {
            ("rtc::texture::not_found", "cannot read the image")
        } else {
            ("rtc::texture::malformed", "cannot decode the image")
        };
        Diagnostic::error(code, span, format!("{what} `{}`", path.display()))
            .with_label(self.message.clone())
            .with_help("check that the file is a complete PNG, JPEG, HDR or EXR image")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_uses_truncated_scaled_coordinates() {
        // 3×2 image: texel value encodes its index.
        let texels = (0..6).map(|i| DVec3::splat(f64::from(i))).collect();
        let p = Picture::new(3, 2, texels).unwrap();
        assert_eq!(p.nearest(DVec2::new(0.0, 0.0)).x, 0.0);
        assert_eq!(p.nearest(DVec2::new(0.49, 0.0)).x, 0.0); // int(0.98) = 0
        assert_eq!(p.nearest(DVec2::new(0.5, 0.0)).x, 1.0);
        assert_eq!(p.nearest(DVec2::new(1.0, 1.0)).x, 5.0);
        assert_eq!(p.nearest(DVec2::new(0.99, 0.99)).x, 1.0); // (int(1.98), int(0.99)) = (1, 0)
        assert_eq!(p.nearest(DVec2::new(f64::NAN, 7.0)).x, 3.0);
        assert!(Picture::new(0, 2, vec![]).is_none());
    }

    #[test]
    fn bilinear_is_exact_at_texel_centres_and_blends_between_them() {
        // 2×2 image: 0 1 / 2 3.
        let texels = (0..4).map(|i| DVec3::splat(f64::from(i))).collect();
        let p = Picture::new(2, 2, texels).unwrap();
        let at = |u: f64, v: f64| p.bilinear(DVec2::new(u, v)).x;
        assert_eq!(at(0.25, 0.25), 0.0);
        assert_eq!(at(0.75, 0.25), 1.0);
        assert_eq!(at(0.25, 0.75), 2.0);
        assert_eq!(at(0.75, 0.75), 3.0);
        assert_eq!(at(0.5, 0.25), 0.5);
        assert_eq!(at(0.5, 0.5), 1.5);
        // Clamped beyond the outer centres and outside [0, 1].
        assert_eq!(at(0.0, 0.0), 0.0);
        assert_eq!(at(1.0, 1.0), 3.0);
        assert_eq!(at(-4.0, 9.0), 2.0);
        assert_eq!(at(f64::NAN, 0.25), 0.0);
        let one = Picture::new(1, 1, vec![DVec3::ONE]).unwrap();
        assert_eq!(one.bilinear(DVec2::new(0.3, 0.9)), DVec3::ONE);
    }

    /// Found by the texture fuzzer: the display window (2×2) passed the budget while the
    /// data window (1,056,964,608×2) made the decoder allocate gigabytes.
    #[test]
    fn an_exr_data_window_counts_against_the_budget() {
        let e = load_found_exr("texture-3-exr-data-window");
        assert!(e.too_large, "{e:?}");
        assert!(
            e.message.contains("data window has 2113929216 pixels"),
            "{e:?}"
        );
    }

    /// Loads the EXR of the texture fuzzer's input `fuzz/found/NAME` (its first byte chose the
    /// extension, 3: exr; the file is the rest), which must fail.
    fn load_found_exr(name: &str) -> ImageError {
        let dir = std::env::temp_dir().join(format!("rtc-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("t.exr");
        let input = std::fs::read(
            Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("fuzz/found")
                .join(name),
        )
        .unwrap();
        std::fs::write(&path, &input[1..]).unwrap();
        let e = Picture::load(&path).unwrap_err();
        std::fs::remove_dir_all(&dir).unwrap();
        e
    }

    /// Found by the texture fuzzer: a B44A block whose values wrap (as OpenEXR's unsigned
    /// arithmetic defines) panicked inside the exr crate in builds with overflow checks; it is
    /// built without them (Cargo.toml), so the file fails as a malformed texture.
    #[test]
    fn a_b44_exr_with_wrapping_blocks_is_an_error_not_a_panic() {
        let e = load_found_exr("texture-4-exr-b44-overflow");
        assert!(!e.missing && !e.too_large, "{e:?}");
        assert!(e.message.contains("B44A"), "{e:?}");
    }

    #[test]
    fn a_truncated_png_is_malformed_not_missing() {
        let dir = std::env::temp_dir().join(format!("rtc-truncated-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("half.png");
        let whole = std::fs::read(
            Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/course/textures/bluegrid.png"),
        )
        .unwrap();
        std::fs::write(&path, &whole[..whole.len() / 2]).unwrap();
        let e = Picture::load(&path).unwrap_err();
        assert!(!e.missing, "{e:?}");
        assert!(Picture::load(&dir.join("none.png")).unwrap_err().missing);
        // A JPEG cut short decodes without complaint (grey fill); it is malformed here.
        let jpeg = std::fs::read(
            Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/course/textures/earthmap1k.jpg"),
        )
        .unwrap();
        let cut = dir.join("cut.jpg");
        std::fs::write(&cut, &jpeg[..jpeg.len() / 2]).unwrap();
        let e = Picture::load(&cut).unwrap_err();
        assert!(!e.missing && e.message.contains("truncated"), "{e:?}");
        std::fs::write(&cut, &jpeg).unwrap();
        assert!(Picture::load(&cut).is_ok());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
