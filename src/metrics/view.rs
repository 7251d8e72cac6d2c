//! The input of every metric: a linear-RGB image borrowed as `f32`s, checked once on creation.

use crate::diag::{Diagnostic, Severity};

/// The buffer's length is not `width × height × 3`.
pub const BUFFER_SIZE: &str = "rtc::metrics::buffer_size";
/// The test and reference images differ in size.
pub const SIZE_MISMATCH: &str = "rtc::metrics::size_mismatch";
/// An image with no pixels.
pub const EMPTY: &str = "rtc::metrics::empty";
/// A channel is NaN or infinite.
pub const NOT_FINITE: &str = "rtc::metrics::not_finite";
/// More pixels than the ꟻLIP library can index.
pub const TOO_LARGE: &str = "rtc::metrics::too_large";

/// The largest image measured: ꟻLIP's C++ counts `width × height × 3` channels in 32 bits.
const MAX_PIXELS: u64 = u32::MAX as u64 / 3;

/// A linear-RGB image: `width × height` pixels of three `f32` channels, rows from the top.
///
/// Channels are light, not display values: 0 is black, 1 the display's white, and values above 1
/// (a light brighter than white) are kept. Every channel is finite.
#[derive(Clone, Copy, Debug)]
pub struct LinearRgb<'a> {
    width: u32,
    height: u32,
    data: &'a [f32],
}

impl<'a> LinearRgb<'a> {
    /// Checks that `data` holds `width × height` finite RGB triples.
    pub fn new(width: u32, height: u32, data: &'a [f32]) -> Result<LinearRgb<'a>, Diagnostic> {
        if width == 0 || height == 0 {
            return Err(
                error(EMPTY, format!("a {width}×{height} image has no pixels"))
                    .with_help("compare images of at least 1×1 pixels"),
            );
        }
        let pixels = u64::from(width) * u64::from(height);
        if pixels > MAX_PIXELS {
            return Err(error(
                TOO_LARGE,
                format!("a {width}×{height} image has more than {MAX_PIXELS} pixels"),
            )
            .with_help("measure a crop or a reduced-resolution render"));
        }
        let expected = pixels * 3;
        if data.len() as u64 != expected {
            return Err(error(
                BUFFER_SIZE,
                format!(
                    "a {width}×{height} RGB image needs {expected} channel values, the buffer has {}",
                    data.len()
                ),
            )
            .with_help("pass three f32 channels per pixel, rows from the top, no padding"));
        }
        if let Some(i) = data.iter().position(|c| !c.is_finite()) {
            let pixel = i / 3;
            let (x, y) = (pixel % width as usize, pixel / width as usize);
            return Err(error(
                NOT_FINITE,
                format!("pixel ({x}, {y}) has a channel that is {}", data[i]),
            )
            .with_help(
                "replace NaN and infinite values before comparing (a render never makes them)",
            ));
        }
        Ok(LinearRgb {
            width,
            height,
            data,
        })
    }

    /// Width in pixels.
    pub(crate) fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub(crate) fn height(&self) -> u32 {
        self.height
    }

    /// The channels, three per pixel, rows from the top.
    pub(crate) fn data(&self) -> &'a [f32] {
        self.data
    }

    /// The pixels as RGB triples.
    pub(crate) fn pixels(&self) -> impl Iterator<Item = [f32; 3]> + 'a {
        self.data.chunks_exact(3).map(|c| [c[0], c[1], c[2]])
    }
}

/// Checks that a test image and its reference have the same size.
pub(crate) fn same_size(test: &LinearRgb<'_>, reference: &LinearRgb<'_>) -> Result<(), Diagnostic> {
    if (test.width, test.height) == (reference.width, reference.height) {
        return Ok(());
    }
    Err(error(
        SIZE_MISMATCH,
        format!(
            "the test image is {}×{} pixels, the reference {}×{}",
            test.width, test.height, reference.width, reference.height
        ),
    )
    .with_help("render the test and the reference at the same resolution"))
}

fn error(code: &'static str, message: String) -> Diagnostic {
    Diagnostic::new(Severity::Error, code, None, message)
}
