//! Writing images: PNG or PPM (8-bit, encoded) or OpenEXR (linear, unclamped `f32` colour) by
//! extension, through a temporary file and a rename so a failed or interrupted render never
//! clobbers an existing image.

use std::io::Write;

use image::ImageEncoder;
use std::path::{Path, PathBuf};

use crate::diag::{Diagnostic, IO_ERROR, Severity};

use super::Image;

/// Image file formats rtc writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageFormat {
    /// 8-bit RGB PNG.
    Png,
    /// Binary PPM (P6, maxval 255), as the legacy course framework wrote.
    Ppm,
    /// OpenEXR, linear RGB `f32`, unclamped (for compositing).
    Exr,
}

impl ImageFormat {
    /// The format implied by a path's extension.
    pub fn of(path: &Path) -> Option<ImageFormat> {
        match path.extension()?.to_str()?.to_ascii_lowercase().as_str() {
            "png" => Some(ImageFormat::Png),
            "ppm" => Some(ImageFormat::Ppm),
            "exr" => Some(ImageFormat::Exr),
            _ => None,
        }
    }
}

fn io_error(message: String, help: &str) -> Diagnostic {
    Diagnostic::new(Severity::Error, IO_ERROR, None, message).with_help(help)
}

/// Encodes `image` in memory in the format of `path`'s extension.
pub fn encode(image: &Image, path: &Path) -> Result<Vec<u8>, Diagnostic> {
    let format = ImageFormat::of(path).ok_or_else(|| {
        io_error(
            format!("cannot write `{}`: unknown image format", path.display()),
            "name the output `*.png`, `*.ppm` or `*.exr`",
        )
    })?;
    let mut bytes = Vec::new();
    match format {
        ImageFormat::Png => {
            image::codecs::png::PngEncoder::new(&mut bytes)
                .write_image(
                    image.as_raw(),
                    image.width(),
                    image.height(),
                    image::ExtendedColorType::Rgb8,
                )
                .map_err(|e| io_error(format!("cannot encode PNG: {e}"), "report this as a bug"))?;
        }
        ImageFormat::Ppm => {
            let _ = write!(bytes, "P6\n{} {}\n255\n", image.width(), image.height());
            bytes.extend_from_slice(image.as_raw());
        }
        ImageFormat::Exr => {
            // An 8-bit image has no linear values left: its levels are stored as f32 in
            // [0, 1]. Films go through `save_film`, which writes their linear colour.
            let linear = image::Rgb32FImage::from_fn(image.width(), image.height(), |x, y| {
                let p = image.get_pixel(x, y).0;
                image::Rgb(p.map(|b| f32::from(b) / 255.0))
            });
            return encode_exr(&linear);
        }
    }
    Ok(bytes)
}

/// A linear `f32` RGB image as OpenEXR bytes.
fn encode_exr(linear: &image::Rgb32FImage) -> Result<Vec<u8>, Diagnostic> {
    let mut cursor = std::io::Cursor::new(Vec::new());
    linear
        .write_to(&mut cursor, image::ImageFormat::OpenExr)
        .map_err(|e| io_error(format!("cannot encode EXR: {e}"), "report this as a bug"))?;
    Ok(cursor.into_inner())
}

/// Writes a film to `path`: every channel linear and unclamped for `*.exr` (`render::exr`),
/// else the 8-bit image of its colour in the film's encoding (PNG or PPM).
pub fn save_film(film: &super::film::Film, path: &Path) -> Result<(), Diagnostic> {
    if ImageFormat::of(path) != Some(ImageFormat::Exr) {
        return save(&film.to_image(), path);
    }
    write_atomically(path, &super::exr::encode(film)?)
}

/// Writes `image` to `path` atomically (temporary sibling file, then rename).
pub fn save(image: &Image, path: &Path) -> Result<(), Diagnostic> {
    write_atomically(path, &encode(image, path)?)
}

/// Writes `bytes` to `path` through a temporary sibling file and a rename, so readers see the
/// old file or the whole new one, never a part.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), Diagnostic> {
    let tmp = temp_sibling(path);
    let write = std::fs::write(&tmp, bytes).and_then(|()| std::fs::rename(&tmp, path));
    write.map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        io_error(
            format!("cannot write `{}`: {e}", path.display()),
            "check that the directory exists and is writable, or choose another path with `-o`",
        )
    })
}

fn temp_sibling(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map_or_else(|| "image".into(), |n| n.to_string_lossy().into_owned());
    path.with_file_name(format!(".{name}.{}.tmp", std::process::id()))
}
