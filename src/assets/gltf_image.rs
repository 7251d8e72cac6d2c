//! Where a glTF material's base colour image is: a file beside the glTF file (a relative URI),
//! or inside it (a buffer view, which in a `.glb` is usually the binary chunk, or a base64
//! `data:` URI). An image inside is cut out of its buffer with checked ranges and kept encoded
//! ([`EmbeddedImage`]); it is decoded when the scene is prepared.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::embedded::{EmbeddedImage, ImageSource, format_of_mime};

/// The image `image` of the glTF file `path` whose buffers are `buffers`; `seen` keeps the
/// images inside the file already cut out (materials sharing one image decode it once). The
/// error completes "a base colour texture ..." with why it is not read.
pub(super) fn source(
    path: &Path,
    buffers: &[Vec<u8>],
    image: &gltf::Image<'_>,
    seen: &mut HashMap<usize, Arc<EmbeddedImage>>,
) -> Result<ImageSource, String> {
    if let Some(e) = seen.get(&image.index()) {
        return Ok(ImageSource::Embedded(e.clone()));
    }
    let (bytes, mime, place) = match image.source() {
        gltf::image::Source::Uri { uri, .. } if !uri.starts_with("data:") => {
            return Ok(ImageSource::File(buffer_file(path, uri)));
        }
        gltf::image::Source::Uri { uri, mime_type } => {
            let (mime, bytes) = data_uri(uri)?;
            // The URI's own type, else the one the JSON declares.
            let mime = if mime.is_empty() {
                mime_type.unwrap_or_default().to_owned()
            } else {
                mime
            };
            (bytes, mime, "a `data:` URI")
        }
        gltf::image::Source::View { view, mime_type } => {
            let data = buffers
                .get(view.buffer().index())
                .ok_or("stored inside the file names a buffer the file lacks")?;
            let bytes = view
                .offset()
                .checked_add(view.length())
                .and_then(|end| data.get(view.offset()..end))
                .ok_or_else(|| {
                    format!(
                        "stored inside the file lies outside its buffer (buffer view {}: {} bytes from byte {}, in a buffer of {})",
                        view.index(),
                        view.length(),
                        view.offset(),
                        data.len()
                    )
                })?;
            (bytes.to_vec(), mime_type.to_owned(), "a buffer view")
        }
    };
    let format = format_of_mime(&mime).ok_or_else(|| {
        let shown: String = mime.chars().take(40).collect();
        format!(
            "stored inside the file has the MIME type `{shown}` (rtc reads `image/png` and `image/jpeg`)"
        )
    })?;
    let e = Arc::new(EmbeddedImage::new(
        format!("image {} of the glTF file (in {place})", image.index()),
        bytes,
        format,
    ));
    seen.insert(image.index(), e.clone());
    Ok(ImageSource::Embedded(e))
}

/// The MIME type and the bytes of a base64 `data:` URI (`data:[type][;params];base64,DATA`).
pub(super) fn data_uri(uri: &str) -> Result<(String, Vec<u8>), String> {
    use base64::Engine as _;
    let rest = uri.strip_prefix("data:").unwrap_or(uri);
    let Some((head, data)) = rest.split_once(',') else {
        return Err("is a `data:` URI without a `,` before its data".to_owned());
    };
    let Some(head) = head.strip_suffix(";base64") else {
        return Err("is a `data:` URI that is not base64".to_owned());
    };
    let mime = head.split(';').next().unwrap_or_default().to_owned();
    let bytes = base64::engine::general_purpose::STANDARD
        .decode(data)
        .map_err(|e| format!("is a `data:` URI whose base64 is malformed ({e})"))?;
    Ok((mime, bytes))
}

/// Where a buffer's or an image's relative URI points: beside the glTF file.
pub(super) fn buffer_file(path: &Path, uri: &str) -> PathBuf {
    path.parent()
        .map_or_else(|| PathBuf::from(uri), |d| d.join(uri))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn data_uris_are_read_or_refused_with_a_reason() {
        let (mime, bytes) = data_uri("data:image/png;base64,AAEC").unwrap();
        assert_eq!((mime.as_str(), bytes), ("image/png", vec![0, 1, 2]));
        let (mime, _) = data_uri("data:;base64,").unwrap();
        assert_eq!(mime, "");
        assert!(
            data_uri("data:image/png,plain")
                .unwrap_err()
                .contains("base64")
        );
        assert!(
            data_uri("data:image/png;base64,@@")
                .unwrap_err()
                .contains("malformed")
        );
        assert!(data_uri("data:image/png;base64").unwrap_err().contains(","));
    }
}
