//! ꟻLIP (LDR-FLIP, Andersson et al. 2020): the per-pixel perceived difference between a test
//! image and its reference, in [0, 1], computed by NVIDIA's implementation (the `nv-flip` crate).
//!
//! Both images are encoded to 8-bit sRGB first ([`super::srgb::encode`]), as a PNG of them would
//! store them, so the map judges what a viewer sees; FLIP decodes them back to linear light itself.

use crate::diag::{Diagnostic, Severity};

use super::srgb;
use super::view::{LinearRgb, same_size};
use super::worst::mean_of_worst;

/// Viewing conditions: pixels per degree of visual angle. 67 is ꟻLIP's default (a 0.7 m wide
/// 3840-pixel monitor seen from 0.7 m), which `flip-evaluator` also uses.
const PIXELS_PER_DEGREE: f32 = nv_flip::DEFAULT_PIXELS_PER_DEGREE;

/// The PNG encoder failed.
const PNG_ENCODE: &str = "rtc::metrics::png";

/// A ꟻLIP error map: one value in [0, 1] per pixel, rows from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct FlipMap {
    width: u32,
    height: u32,
    values: Vec<f32>,
}

impl FlipMap {
    /// The per-pixel errors, rows from the top.
    pub fn values(&self) -> &[f32] {
        &self.values
    }

    /// The mean error over all pixels (the number ꟻLIP's authors recommend reporting).
    pub(crate) fn mean(&self) -> f64 {
        let sum: f64 = self.values.iter().map(|&v| f64::from(v)).sum();
        sum / self.values.len() as f64
    }

    /// The mean of the worst `fraction` of pixels ([`super::WORST_FRACTION`] is 1%).
    pub(crate) fn mean_of_worst(&self, fraction: f64) -> f64 {
        let values: Vec<f64> = self.values.iter().map(|&v| f64::from(v)).collect();
        mean_of_worst(&values, fraction)
    }

    /// The map in the magma colour map (black for no error, through purple and orange, to
    /// light yellow for 1), 8-bit RGB rows, as ꟻLIP's own tool shows it.
    fn magma_rgb8(&self) -> Vec<u8> {
        let map = nv_flip::FlipImageFloat::with_data(self.width, self.height, &self.values);
        map.apply_color_lut(&nv_flip::magma_lut()).to_vec()
    }

    /// The magma picture ([`FlipMap::magma_rgb8`]) encoded as a PNG file's bytes.
    pub fn magma_png(&self) -> Result<Vec<u8>, Diagnostic> {
        use image::ImageEncoder;
        let mut bytes = Vec::new();
        image::codecs::png::PngEncoder::new(&mut bytes)
            .write_image(
                &self.magma_rgb8(),
                self.width,
                self.height,
                image::ExtendedColorType::Rgb8,
            )
            .map_err(|e| {
                Diagnostic::new(
                    Severity::Error,
                    PNG_ENCODE,
                    None,
                    format!("cannot encode the ꟻLIP map as PNG: {e}"),
                )
                .with_help("report this as a bug")
            })?;
        Ok(bytes)
    }
}

/// The ꟻLIP map of `test` against `reference` at [`PIXELS_PER_DEGREE`].
pub fn flip(test: LinearRgb<'_>, reference: LinearRgb<'_>) -> Result<FlipMap, Diagnostic> {
    same_size(&test, &reference)?;
    let (w, h) = (test.width(), test.height());
    let encoded =
        |img: LinearRgb<'_>| nv_flip::FlipImageRgb8::with_data(w, h, &srgb::encode_all(img.data()));
    let map = nv_flip::flip(encoded(reference), encoded(test), PIXELS_PER_DEGREE);
    Ok(FlipMap {
        width: w,
        height: h,
        values: map.to_vec(),
    })
}
