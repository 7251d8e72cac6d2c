//! POV-Ray 3.7's finish terms on top of Phong: brilliance (the diffuse falloff), metallic
//! highlights and emission. Each is the identity at its default, and a material at its defaults
//! never reaches these functions' other branches (the packet shader has none of them).

use glam::DVec3;

use crate::ir::{Color, Material};

/// The diffuse falloff `(N·L)^brilliance` for `n_dot_l` > 0 (POV-Ray's
/// `Trace::ComputeDiffuseColour`: `pow(|cos|, brilliance)`, plain `cos` at brilliance 1).
#[inline(always)]
pub(crate) fn falloff(mat: &Material, n_dot_l: f64) -> f64 {
    if mat.brilliance == 1.0 {
        n_dot_l
    } else {
        libm::pow(n_dot_l, mat.brilliance)
    }
}

/// The colour a metallic highlight is multiplied by (POV-Ray's `Trace::ComputeMetallic`,
/// [DB 9/94]): `1 + metallic·(1 − F)·(C − 1)`, where `F` is an empirical Fresnel-like curve of
/// the angle between the normal and the light, `x = acos(N·L)/(π/2)`,
/// `F = clamp(0.014567225/(x − 1.12)² − 0.011612903, 0, 1)`: the highlight takes the surface
/// colour C, less so towards grazing light.
pub(crate) fn metallic_tint(metallic: f64, color: Color, n_dot_l: f64) -> Color {
    let x = libm::acos(n_dot_l.clamp(-1.0, 1.0)).abs() / std::f64::consts::FRAC_PI_2;
    let f = (0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903).clamp(0.0, 1.0);
    DVec3::ONE + (metallic * (1.0 - f)) * (color - DVec3::ONE)
}

/// The light a surface of colour `color` emits by itself: `emission · C` (POV-Ray adds
/// `emission · pigment` before any light, so a white emission glows in the surface's colour).
#[inline(always)]
pub(crate) fn emitted(mat: &Material, color: Color) -> Color {
    mat.emission * color
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn brilliance_one_is_lambert_and_others_a_power() {
        let m = Material::default();
        assert_eq!(falloff(&m, 0.3), 0.3);
        let shiny = Material {
            brilliance: 4.0,
            ..Material::default()
        };
        assert!((falloff(&shiny, 0.5) - 0.0625).abs() < 1e-15);
        assert_eq!(falloff(&shiny, 1.0), 1.0);
    }

    #[test]
    fn metallic_takes_the_colour_head_on_and_less_at_grazing() {
        let gold = Color::new(1.0, 0.8, 0.3);
        // Head on x = 0: F = 0.014567225/1.2544 − 0.011612903 ≈ −4·10⁻¹⁰ (the curve's zero),
        // clamped to 0.
        let f0 = (0.014567225f64 / (1.12f64 * 1.12) - 0.011612903).max(0.0);
        assert!(f0 == 0.0);
        let t = metallic_tint(1.0, gold, 1.0);
        assert!(
            (t - (DVec3::ONE + (1.0 - f0) * (gold - DVec3::ONE)))
                .abs()
                .max_element()
                < 1e-15
        );
        assert!((t - gold).abs().max_element() < 1e-6);
        // At grazing light (x = 1) F = 0.014567225/0.0144 − 0.011612903 = 1 − 5.6·10⁻⁸:
        // the highlight is white again.
        let g = metallic_tint(1.0, gold, 0.0);
        assert!((g - DVec3::ONE).abs().max_element() < 1e-7, "{g}");
        assert!(g != DVec3::ONE);
        // metallic 0 leaves the highlight white.
        assert_eq!(metallic_tint(0.0, gold, 0.7), DVec3::ONE);
        // Half metallic halfway between.
        let h = metallic_tint(0.5, gold, 1.0);
        assert!(
            (h.z - (1.0 + 0.5 * (1.0 - f0) * (0.3 - 1.0))).abs() < 1e-12,
            "{h}"
        );
    }

    #[test]
    fn emission_glows_in_the_surface_colour() {
        let m = Material {
            emission: Color::new(0.5, 0.5, 0.5),
            ..Material::default()
        };
        assert_eq!(
            emitted(&m, Color::new(1.0, 0.2, 0.0)),
            Color::new(0.5, 0.1, 0.0)
        );
    }
}
