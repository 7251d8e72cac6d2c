//! The sRGB transfer curve (IEC 61966-2-1) between linear light and 8-bit display values.
//!
//! ꟻLIP judges what a viewer sees, so images are encoded the way a PNG stores them before it runs;
//! the other metrics stay in linear light.

/// Encodes linear light to an 8-bit sRGB value: clamp to [0, 1], apply the curve, round.
fn encode(linear: f32) -> u8 {
    let c = f64::from(linear).clamp(0.0, 1.0);
    let v = if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * libm::pow(c, 1.0 / 2.4) - 0.055
    };
    (255.0 * v).round() as u8
}

/// Decodes an 8-bit sRGB value to linear light (the exact inverse of [`encode`] on its outputs).
fn decode(value: u8) -> f32 {
    let v = f64::from(value) / 255.0;
    let c = if v <= 0.040_45 {
        v / 12.92
    } else {
        libm::pow((v + 0.055) / 1.055, 2.4)
    };
    c as f32
}

/// Encodes every channel of a linear-RGB buffer.
pub(crate) fn encode_all(linear: &[f32]) -> Vec<u8> {
    linear.iter().map(|&c| encode(c)).collect()
}

/// Decodes every channel of an 8-bit sRGB buffer (a PNG's RGB bytes) to linear light.
pub fn decode_all(bytes: &[u8]) -> Vec<f32> {
    bytes.iter().map(|&b| decode(b)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_byte_survives_a_round_trip() {
        for b in 0..=255u8 {
            assert_eq!(encode(decode(b)), b, "byte {b}");
        }
    }

    #[test]
    fn the_curve_has_its_published_anchors() {
        assert_eq!(encode(0.0), 0);
        assert_eq!(encode(1.0), 255);
        assert_eq!(encode(2.0), 255);
        assert_eq!(encode(-1.0), 0);
        // The sRGB mid grey #808080 (128) is linear 0.2159.
        assert_eq!(encode(0.2159), 128);
        assert!((decode(128) - 0.2159).abs() < 1e-4);
        // Below 0.0031308 the curve is the straight line 12.92·c.
        assert_eq!(encode(0.003), (255.0f64 * 12.92 * 0.003).round() as u8);
    }
}
