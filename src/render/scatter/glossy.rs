//! Glossy reflection and translucency (Cook's distributed ray tracing): a glossy lobe's rays
//! spread over a cone around its ideal (mirror or refraction) direction.
//!
//! The lobe is uniform in solid angle over the cone of half-angle `gloss·90°`. A ray that the
//! cone tips through the surface is mirrored back about the surface plane, so it stays on its
//! side and keeps its weight: the lobe's rays average to the same total weight as the one ray
//! they replace, and energy never grows. `pdf` (the tests') is the density of that folded cone.

use crate::num::Norm;
use glam::DVec3;

/// The cosine of the cone's half-angle for `gloss` (0: a delta, 1: the hemisphere).
fn cos_max(gloss: f64) -> f64 {
    libm::cos(gloss.clamp(0.0, 1.0) * std::f64::consts::FRAC_PI_2)
}

/// A direction in the cone of half-angle `gloss·90°` around unit `axis`, for the point `(a, b)`
/// of the unit square (uniform in solid angle), on the side of unit `side` (the surface normal
/// the ray leaves through).
pub(crate) fn direction(axis: DVec3, side: DVec3, gloss: f64, (a, b): (f64, f64)) -> DVec3 {
    let cos_max = cos_max(gloss);
    let cos_t = 1.0 - a * (1.0 - cos_max);
    let sin_t = (1.0 - cos_t * cos_t).max(0.0).sqrt();
    let phi = 2.0 * std::f64::consts::PI * b;
    let (t, bt) = axis.any_orthonormal_pair();
    let d = (cos_t * axis + sin_t * (libm::cos(phi) * t + libm::sin(phi) * bt)).unit();
    let below = d.dot(side);
    if below < 0.0 {
        (d - 2.0 * below * side).unit()
    } else {
        d
    }
}

/// The density per unit solid angle of [`direction`]'s rays at unit `wi`: the cone's uniform
/// density where `wi` is in the cone, plus the same again where its mirror image about the
/// surface plane is (the rays folded back). Zero below the surface and for `gloss` 0 (a delta
/// has no density). Whitted weighs a glossy lobe's directions alike; the path tracer needs it.
pub(crate) fn pdf(axis: DVec3, side: DVec3, gloss: f64, wi: DVec3) -> f64 {
    let cos_max = cos_max(gloss);
    let solid_angle = 2.0 * std::f64::consts::PI * (1.0 - cos_max);
    let above = wi.dot(side);
    if solid_angle <= 0.0 || above < 0.0 {
        return 0.0;
    }
    let inside = |d: DVec3| d.dot(axis) >= cos_max;
    let folded = wi - 2.0 * above * side;
    let hits = u32::from(inside(wi)) + u32::from(above > 0.0 && inside(folded));
    f64::from(hits) / solid_angle
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lobe_stays_in_its_cone_and_on_its_side() {
        let axis = DVec3::new(0.3, 0.9, 0.1).unit();
        let n = DVec3::Y;
        for gloss in [0.0, 0.1, 0.5, 1.0] {
            let cos_max = libm::cos(gloss * std::f64::consts::FRAC_PI_2);
            for i in 0..16 {
                for j in 0..16 {
                    let p = ((f64::from(i) + 0.5) / 16.0, (f64::from(j) + 0.5) / 16.0);
                    let d = direction(axis, n, gloss, p);
                    assert!((d.norm() - 1.0).abs() < 1e-12);
                    assert!(d.dot(n) >= 0.0);
                    if d.dot(axis) < cos_max - 1e-9 {
                        // Only a mirrored ray may leave the cone, and only when it was tipped
                        // through the surface.
                        assert!(gloss > 0.0 && axis.dot(n) < 1.0);
                    }
                    if gloss > 0.0 {
                        assert!(pdf(axis, n, gloss, d) > 0.0, "a sampled ray has density");
                    }
                }
            }
        }
    }

    #[test]
    fn zero_gloss_is_the_axis() {
        let axis = DVec3::new(1.0, 2.0, -0.5).unit();
        let d = direction(axis, DVec3::Y, 0.0, (0.7, 0.2));
        assert!((d - axis).norm() < 1e-12);
        assert_eq!(pdf(axis, DVec3::Y, 0.0, axis), 0.0);
    }

    /// The density integrates to one over the sphere, for a lobe well above the surface and for
    /// one the surface cuts (whose folded rays count twice where they land): a midpoint rule
    /// over (cos θ, φ) with 1.6 M cells, tolerance 1%.
    #[test]
    fn the_density_integrates_to_one() {
        let n = DVec3::Z;
        for (axis, gloss) in [
            (DVec3::Z, 0.3),
            (DVec3::new(1.0, 0.0, 0.3).unit(), 0.6),
            (DVec3::new(0.2, -1.0, 0.05).unit(), 1.0),
        ] {
            let cells = 1200;
            let mut sum = 0.0;
            for i in 0..cells {
                let z = -1.0 + 2.0 * (f64::from(i) + 0.5) / f64::from(cells);
                let r = (1.0 - z * z).sqrt();
                for j in 0..cells {
                    let phi = 2.0 * std::f64::consts::PI * (f64::from(j) + 0.5) / f64::from(cells);
                    let wi = DVec3::new(r * libm::cos(phi), r * libm::sin(phi), z);
                    sum += pdf(axis, n, gloss, wi);
                }
            }
            let cell_area = 4.0 * std::f64::consts::PI / f64::from(cells * cells);
            let total = sum * cell_area;
            assert!((total - 1.0).abs() < 0.01, "{axis} {gloss}: {total}");
        }
    }
}
