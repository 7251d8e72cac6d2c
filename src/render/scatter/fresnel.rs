//! The share of light a smooth dielectric interface reflects: the exact Fresnel equations for
//! unpolarised light, and the transmittance of an absorbing medium along a straight path.

use crate::ir::Color;

/// The Fresnel reflectance of unpolarised light arriving at cosine `cos_i` (> 0) to the normal
/// of an interface where the index rises by the ratio `n` (far side over near side): the mean
/// of the s and p reflectances, `½·(r_s² + r_p²)`; 1 under total internal reflection.
///
/// Written the way POV-Ray 3.7 writes it (`Trace::FresnelR`), with `g = √(n² + cos² − 1)`
/// (`n·cos θt`): `R = ½·((g − c)/(g + c))²·(1 + ((c(g + c) − 1)/(c(g − c) + 1))²)`.
pub(crate) fn reflectance(cos_i: f64, n: f64) -> f64 {
    let c = cos_i.clamp(0.0, 1.0);
    let g2 = n * n + c * c - 1.0;
    if g2 <= 0.0 {
        return 1.0;
    }
    let g = g2.sqrt();
    let a = (g - c) / (g + c);
    let b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    (0.5 * a * a * (1.0 + b * b)).clamp(0.0, 1.0)
}

/// What light keeps after travelling `d` through a medium absorbing `sigma` per unit length,
/// per channel (Beer–Lambert): `exp(−σ·d)`.
pub(crate) fn beer_lambert(sigma: Color, d: f64) -> Color {
    Color::new(
        libm::exp(-sigma.x * d),
        libm::exp(-sigma.y * d),
        libm::exp(-sigma.z * d),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Fresnel equations as textbooks write them: Snell's law for θt, then
    /// `r_s = (n1 cos θi − n2 cos θt)/(n1 cos θi + n2 cos θt)`,
    /// `r_p = (n2 cos θi − n1 cos θt)/(n2 cos θi + n1 cos θt)`, `R = (r_s² + r_p²)/2`.
    fn textbook(theta_i: f64, n1: f64, n2: f64) -> f64 {
        let sin_t = n1 / n2 * theta_i.sin();
        if sin_t >= 1.0 {
            return 1.0;
        }
        let (ci, ct) = (theta_i.cos(), (1.0 - sin_t * sin_t).sqrt());
        let rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct);
        let rp = (n2 * ci - n1 * ct) / (n2 * ci + n1 * ct);
        0.5 * (rs * rs + rp * rp)
    }

    #[test]
    fn normal_incidence_is_the_square_of_the_index_contrast() {
        // ((n − 1)/(n + 1))²: 0.04 for glass of index 1.5, 0.02006 for water.
        assert!((reflectance(1.0, 1.5) - 0.04).abs() < 1e-15);
        let w = (0.33f64 / 2.33).powi(2);
        assert!((reflectance(1.0, 1.33) - w).abs() < 1e-15);
        // The same from inside (the formula is symmetric at normal incidence).
        assert!((reflectance(1.0, 1.0 / 1.5) - 0.04).abs() < 1e-15);
    }

    #[test]
    fn grazing_incidence_reflects_everything() {
        assert!((reflectance(0.0, 1.5) - 1.0).abs() < 1e-12);
        // 89.9°: 0.98991 (textbook value), rising towards 1 at 90°.
        let near = reflectance(89.9f64.to_radians().cos(), 1.5);
        assert!((near - 0.989_911_876_9).abs() < 1e-9, "{near}");
        assert!(reflectance(80f64.to_radians().cos(), 1.5) < near);
    }

    #[test]
    fn agrees_with_the_textbook_formula_at_every_angle() {
        for (n1, n2) in [(1.0, 1.5), (1.0, 1.33), (1.5, 1.0), (1.33, 1.5), (1.0, 2.4)] {
            for i in 0..=90 {
                let th = f64::from(i)
                    .to_radians()
                    .min(std::f64::consts::FRAC_PI_2 - 1e-9);
                let r = reflectance(th.cos(), n2 / n1);
                let t = textbook(th, n1, n2);
                assert!((r - t).abs() < 1e-12, "{n1}->{n2} at {i}°: {r} vs {t}");
            }
        }
        // Brewster's angle: p-polarised light is not reflected, so R = r_s²/2 there.
        let brewster = 1.5f64.atan();
        let r = reflectance(brewster.cos(), 1.5);
        assert!((r - textbook(brewster, 1.0, 1.5)).abs() < 1e-14);
    }

    #[test]
    fn total_internal_reflection_past_the_critical_angle() {
        let critical = (1.0f64 / 1.5).asin();
        assert_eq!(reflectance((critical + 0.01).cos(), 1.0 / 1.5), 1.0);
        assert!(reflectance((critical - 0.01).cos(), 1.0 / 1.5) < 1.0);
    }

    #[test]
    fn beer_lambert_over_a_known_thickness() {
        let t = beer_lambert(Color::new(0.0, 0.5, 2.0), 1.5);
        assert_eq!(t.x, 1.0);
        assert!((t.y - (-0.75f64).exp()).abs() < 1e-15);
        assert!((t.z - (-3.0f64).exp()).abs() < 1e-15);
    }
}
