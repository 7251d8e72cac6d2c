//! Writing images: PNG or binary PPM chosen by the file extension. The image goes to a temporary
//! file in the same directory first and is renamed into place, so a failed or interrupted write
//! never clobbers an existing image.

use std::fs;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use super::Image;
use crate::diag::{Diagnostic, Severity};

/// The output formats `rtc` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// 8-bit RGB PNG.
    Png,
    /// Binary PPM (`P6`, maxval 255).
    Ppm,
}

impl Format {
    /// The format for a path's extension (case-insensitive), or a diagnostic naming the choices.
    pub fn of(path: &Path) -> Result<Format, Diagnostic> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("png") => Ok(Format::Png),
            Some("ppm") => Ok(Format::Ppm),
            other => Err(Diagnostic::new(
                Severity::Error,
                "rtc::output::format",
                None,
                match other {
                    Some(e) => format!("cannot write `.{e}` images: `{}`", path.display()),
                    None => format!("the output `{}` has no extension", path.display()),
                },
            )
            .with_help("name the output `.png` or `.ppm`")),
        }
    }
}

/// Writes `image` to `path` atomically (temporary file + rename).
pub fn write(image: &Image, path: &Path) -> Result<(), Diagnostic> {
    let format = Format::of(path)?;
    let tmp = temp_path(path);
    let result = write_to(image, &tmp, format).and_then(|()| fs::rename(&tmp, path));
    result.map_err(|e| {
        let _ = fs::remove_file(&tmp);
        Diagnostic::new(
            Severity::Error,
            "rtc::output::io",
            None,
            format!("cannot write `{}`: {e}", path.display()),
        )
    })
}

/// `dir/.NAME.PID.tmp`: same directory (so the rename stays on one file system), hidden, unique per process.
fn temp_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    path.with_file_name(format!(".{name}.{}.tmp", std::process::id()))
}

fn write_to(image: &Image, tmp: &Path, format: Format) -> std::io::Result<()> {
    let mut out = BufWriter::new(fs::File::create(tmp)?);
    match format {
        Format::Png => image
            .write_to(&mut out, image::ImageFormat::Png)
            .map_err(std::io::Error::other)?,
        Format::Ppm => {
            write!(out, "P6\n{} {}\n255\n", image.width(), image.height())?;
            out.write_all(image.as_raw())?;
        }
    }
    out.into_inner().map_err(|e| e.into_error())?.sync_all()
}
