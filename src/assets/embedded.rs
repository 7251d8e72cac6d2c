//! Images stored inside a mesh file (a glTF buffer view, a GLB's binary chunk, a `data:` URI):
//! kept encoded with the mesh and decoded on first use, once per loaded mesh, under the budgets
//! and checks of an image file (the header's size against the pixel budget before anything is
//! decoded, a JPEG cut short refused).

use std::path::PathBuf;
use std::sync::{Arc, OnceLock};

use super::image::{ImageError, Picture, jpeg_bytes_truncated, truncated_jpeg, within_budget};

/// Where a mesh material's base colour image comes from.
#[derive(Clone, Debug)]
pub enum ImageSource {
    /// An image file beside the mesh file (MTL `map_Kd`, a glTF image's relative URI).
    File(PathBuf),
    /// An image inside the mesh file.
    Embedded(Arc<EmbeddedImage>),
}

/// An encoded image inside a mesh file, decoded once when first asked for.
#[derive(Debug)]
pub struct EmbeddedImage {
    /// What diagnostics call it (`image 0 (a buffer view) of the glTF file`).
    pub(crate) name: String,
    bytes: Vec<u8>,
    format: image::ImageFormat,
    decoded: OnceLock<Result<Arc<Picture>, ImageError>>,
}

impl EmbeddedImage {
    /// The image `bytes` in `format` (PNG or JPEG: what glTF allows), called `name`.
    pub(crate) fn new(name: String, bytes: Vec<u8>, format: image::ImageFormat) -> EmbeddedImage {
        EmbeddedImage {
            name,
            bytes,
            format,
            decoded: OnceLock::new(),
        }
    }

    /// Bytes of the encoded image (what the mesh holds until it is decoded).
    pub(crate) fn encoded_len(&self) -> usize {
        self.bytes.len()
    }

    /// Bytes the image takes decoded: the picture's once decoded, else from its header's size
    /// (0 when the header cannot be read: decoding will say why).
    pub(crate) fn decoded_bytes(&self) -> u64 {
        if let Some(Ok(p)) = self.decoded.get() {
            return p.memory() as u64;
        }
        match self.reader().into_dimensions() {
            Ok((w, h)) => u64::from(w) * u64::from(h) * std::mem::size_of::<glam::DVec3>() as u64,
            Err(_) => 0,
        }
    }

    /// The decoded picture (decoded on the first call; the same result after).
    pub(crate) fn picture(&self) -> Result<Arc<Picture>, ImageError> {
        self.decoded
            .get_or_init(|| self.decode().map(Arc::new))
            .clone()
    }

    fn reader(&self) -> image::ImageReader<std::io::Cursor<&[u8]>> {
        image::ImageReader::with_format(std::io::Cursor::new(&self.bytes[..]), self.format)
    }

    /// Decodes as [`Picture::load`] decodes a file: the header's size within the budget first
    /// (a small file can claim a huge image), a truncated JPEG refused.
    fn decode(&self) -> Result<Picture, ImageError> {
        let malformed = |e: image::ImageError| ImageError::malformed(e.to_string());
        let (w, h) = self.reader().into_dimensions().map_err(malformed)?;
        within_budget(w, h, 0)?;
        if self.format == image::ImageFormat::Jpeg && jpeg_bytes_truncated(&self.bytes) {
            return Err(truncated_jpeg());
        }
        let decoded = self.reader().decode().map_err(malformed)?;
        Picture::of_decoded(&decoded)
    }
}

/// The image format of a glTF image's MIME type (PNG and JPEG: the core specification's two).
pub(crate) fn format_of_mime(mime: &str) -> Option<image::ImageFormat> {
    match mime.trim().to_ascii_lowercase().as_str() {
        "image/png" => Some(image::ImageFormat::Png),
        "image/jpeg" | "image/jpg" => Some(image::ImageFormat::Jpeg),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn png(w: u32, h: u32) -> Vec<u8> {
        let img = image::RgbImage::from_fn(w, h, |x, y| image::Rgb([x as u8, y as u8, 7]));
        let mut out = std::io::Cursor::new(Vec::new());
        img.write_to(&mut out, image::ImageFormat::Png).unwrap();
        out.into_inner()
    }

    #[test]
    fn an_embedded_png_decodes_as_a_file_does() {
        let bytes = png(3, 2);
        let dir = std::env::temp_dir().join(format!("rtc-embedded-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("t.png");
        std::fs::write(&path, &bytes).unwrap();
        let file = Picture::load(&path).unwrap();
        let e = EmbeddedImage::new("t".into(), bytes, image::ImageFormat::Png);
        assert_eq!(e.decoded_bytes(), 6 * 24);
        let p = e.picture().unwrap();
        assert_eq!(p.size(), file.size());
        for (x, y) in [(0, 0), (2, 1), (1, 0)] {
            assert_eq!(p.texel(x, y), file.texel(x, y));
        }
        std::fs::remove_dir_all(&dir).ok();
    }

    #[test]
    fn bad_embedded_images_are_errors_not_panics() {
        let mut good = png(2, 2);
        for bytes in [
            vec![],
            b"not a png".to_vec(),
            good[..good.len() / 2].to_vec(),
        ] {
            let e = EmbeddedImage::new("t".into(), bytes, image::ImageFormat::Png);
            assert!(e.picture().is_err());
            assert!(e.picture().is_err(), "the same answer twice");
        }
        // A header claiming 2^15 × 2^15 pixels (IHDR's width and height at byte 16): refused
        // before its data is decoded.
        good[16..24].copy_from_slice(&[0, 0, 0x80, 0, 0, 0, 0x80, 0]);
        let e = EmbeddedImage::new("t".into(), good, image::ImageFormat::Png);
        assert!(e.picture().is_err());
        // A JPEG without its end-of-image marker.
        let e = EmbeddedImage::new(
            "t".into(),
            vec![0xff, 0xd8, 0xff, 0xda, 1, 2],
            image::ImageFormat::Jpeg,
        );
        assert!(e.picture().is_err());
        assert_eq!(format_of_mime("image/png"), Some(image::ImageFormat::Png));
        assert_eq!(format_of_mime("image/webp"), None);
    }
}
