//! Writing images: PNG or PPM by extension, through a temporary file and a rename so a failed or
//! interrupted render never clobbers an existing image.

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
}

impl ImageFormat {
    /// The format implied by a path's extension.
    pub fn of(path: &Path) -> Option<ImageFormat> {
        match path.extension()?.to_str()?.to_ascii_lowercase().as_str() {
            "png" => Some(ImageFormat::Png),
            "ppm" => Some(ImageFormat::Ppm),
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
            "name the output `*.png` or `*.ppm`",
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
    }
    Ok(bytes)
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
