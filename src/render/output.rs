//! Writing images: PNG or PPM (8-bit, encoded) or OpenEXR (linear, unclamped `f32` colour) by
//! extension, through a temporary file and a rename so a failed or interrupted render never
//! clobbers an existing image. The temporary files of writes in progress are known
//! ([`abandon_writes`]), so a command ended by a signal, which runs no destructors, can remove
//! them first.

use std::io::Write;
use std::sync::{Mutex, MutexGuard};

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
/// else the 8-bit image of its colour in the film's encoding (PNG or PPM); a PNG of a film
/// with an alpha channel is RGBA (straight alpha, as PNG defines it).
pub fn save_film(film: &super::film::Film, path: &Path) -> Result<(), Diagnostic> {
    match (ImageFormat::of(path), film.to_rgba()) {
        (Some(ImageFormat::Png), Some(rgba)) => {
            let mut bytes = Vec::new();
            image::codecs::png::PngEncoder::new(&mut bytes)
                .write_image(
                    rgba.as_raw(),
                    rgba.width(),
                    rgba.height(),
                    image::ExtendedColorType::Rgba8,
                )
                .map_err(|e| io_error(format!("cannot encode PNG: {e}"), "report this as a bug"))?;
            return write_atomically(path, &bytes);
        }
        (Some(ImageFormat::Exr), _) => {}
        _ => return save(&film.to_image(), path),
    }
    write_atomically(path, &super::exr::encode(film)?)
}

/// Writes `image` to `path` atomically (temporary sibling file, then rename).
fn save(image: &Image, path: &Path) -> Result<(), Diagnostic> {
    write_atomically(path, &encode(image, path)?)
}

/// Checks, before a render, that its image can be written to `path`: a format rtc writes
/// (by extension), and [`check_folder`].
pub fn check_destination(path: &Path) -> Result<(), Diagnostic> {
    if ImageFormat::of(path).is_none() {
        return Err(io_error(
            format!("cannot write `{}`: unknown image format", path.display()),
            "name the output `*.png`, `*.ppm` or `*.exr`",
        ));
    }
    check_folder(path)
}

/// Checks that a file can be created at `path`: its folder exists and a file can be created
/// in it (one is, with a random name, and removed), and `path` is not a folder.
pub fn check_folder(path: &Path) -> Result<(), Diagnostic> {
    let dir = folder_of(path);
    let fail = |why: String, help: &str| {
        Err(io_error(
            format!("cannot write `{}`: {why}", path.display()),
            help,
        ))
    };
    if path.is_dir() {
        return fail(
            "it is a folder".into(),
            "give a file name, e.g. `-o out/image.png`",
        );
    }
    if !dir.is_dir() {
        return fail(
            format!("the folder `{}` does not exist", dir.display()),
            "create the folder first, or choose another path with `-o`",
        );
    }
    match Tracked::create(tempfile::Builder::new().prefix(".rtc-probe."), dir) {
        Ok(probe) => {
            drop(probe);
            Ok(())
        }
        Err(e) => fail(
            format!("the folder `{}` is not writable ({e})", dir.display()),
            "choose a writable folder with `-o`, or change the folder's permissions",
        ),
    }
}

/// The folder a file at `path` goes into (`.` for a bare name).
fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    }
}

/// Writes `bytes` to `path` through a temporary sibling file and a rename, so readers see the
/// old file or the whole new one, never a part. The new file's mode is what `std::fs::write`
/// would give it (0666 less the umask).
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), Diagnostic> {
    write_atomically_with(path, bytes, None)
}

/// [`write_atomically`], the new file getting `permissions` (those of the file it replaces,
/// for `rtc fmt`) when given. The temporary file has a random name and is created exclusively
/// (`O_EXCL`: a symlink planted at the name is never followed) and removed on any failure.
pub fn write_atomically_with(
    path: &Path,
    bytes: &[u8],
    permissions: Option<std::fs::Permissions>,
) -> Result<(), Diagnostic> {
    let fail = |e: std::io::Error| {
        io_error(
            format!("cannot write `{}`: {e}", path.display()),
            "check that the directory exists and is writable, or choose another path with `-o`",
        )
    };
    let dir = folder_of(path);
    let name = path
        .file_name()
        .map_or_else(|| "image".into(), |n| n.to_string_lossy().into_owned());
    let prefix = format!(".{name}.");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(std::fs::Permissions::from_mode(0o666));
    }
    let mut tmp = Tracked::create(&builder, dir).map_err(fail)?;
    tmp.write(bytes, permissions).map_err(fail)?;
    test_pause();
    // Dropped on an error, the temporary file is removed.
    tmp.persist(path).map_err(fail)
}

/// Environment variable, for tests only: milliseconds an atomic write waits between writing its
/// temporary file and renaming it, so that a test can signal the process inside that window.
pub const WRITE_PAUSE_VAR: &str = "RTC_TEST_WRITE_PAUSE_MS";

/// Waits as long as [`WRITE_PAUSE_VAR`] says (read once per process; unset: not at all).
fn test_pause() {
    static PAUSE: std::sync::OnceLock<Option<std::time::Duration>> = std::sync::OnceLock::new();
    let pause = PAUSE.get_or_init(|| {
        let ms = std::env::var(WRITE_PAUSE_VAR).ok()?.trim().parse().ok()?;
        Some(std::time::Duration::from_millis(ms))
    });
    if let Some(d) = pause {
        std::thread::sleep(*d);
    }
}

/// The temporary files of the writes in progress.
static LIVE: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn live() -> MutexGuard<'static, Vec<PathBuf>> {
    // A poisoned lock only means a thread panicked while holding it; the list is still whole.
    LIVE.lock().unwrap_or_else(|e| e.into_inner())
}

/// Removes the temporary files of every write in progress, then runs `then` while no write can
/// create, rename or forget one: for a signal handler that ends the process in `then` (an
/// ended process runs no destructors, so `tempfile`'s own clean-up never happens). A write
/// that had renamed its file into place keeps it: the image is whole.
pub fn abandon_writes<R>(then: impl FnOnce() -> R) -> R {
    let mut live = live();
    for path in live.drain(..) {
        // Already gone (its write failed and removed it) is as good as removed.
        let _ = std::fs::remove_file(&path);
    }
    then()
}

/// A temporary file listed in [`LIVE`] from its creation until it is renamed into place or
/// removed: both happen under the list's lock, so [`abandon_writes`] sees every file that
/// exists.
struct Tracked {
    file: Option<tempfile::NamedTempFile>,
    path: PathBuf,
}

impl Tracked {
    /// Creates a temporary file in `dir` with `builder` and lists it.
    fn create(builder: &tempfile::Builder, dir: &Path) -> std::io::Result<Tracked> {
        let mut live = live();
        let file = builder.tempfile_in(dir)?;
        let path = file.path().to_path_buf();
        live.push(path.clone());
        Ok(Tracked {
            file: Some(file),
            path,
        })
    }

    /// Writes `bytes` to the file and gives it `permissions`, if any.
    fn write(
        &mut self,
        bytes: &[u8],
        permissions: Option<std::fs::Permissions>,
    ) -> std::io::Result<()> {
        // The file is taken only by `persist` and `drop`, which consume the value.
        let Some(file) = self.file.as_mut() else {
            return Err(std::io::Error::other("the temporary file is gone"));
        };
        file.write_all(bytes)?;
        if let Some(p) = permissions {
            file.as_file().set_permissions(p)?;
        }
        Ok(())
    }

    /// Renames the file to `to` (on failure it is removed) and forgets it.
    fn persist(mut self, to: &Path) -> std::io::Result<()> {
        let mut live = live();
        let result = match self.file.take() {
            // The error holds the file; dropping it removes the file, under the lock.
            Some(file) => file.persist(to).map(drop).map_err(|e| e.error),
            None => Ok(()),
        };
        live.retain(|p| *p != self.path);
        result
    }
}

impl Drop for Tracked {
    fn drop(&mut self) {
        if let Some(file) = self.file.take() {
            let mut live = live();
            drop(file);
            live.retain(|p| *p != self.path);
        }
    }
}
