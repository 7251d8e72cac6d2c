//! Glossy reflection and translucency (Cook's distributed ray tracing): a glossy material's
//! reflected and refracted rays spread over a cone around the mirror and refraction directions.
//!
//! The lobe is uniform in solid angle over the cone of half-angle `gloss·90°`; its rays are the
//! points of one scrambled Sobol' sequence per camera sample and decision ([`Rng::point`]), so the
//! bytes are a pure function of (pixel, sample, seed). A ray that the lobe tips through the
//! surface is mirrored back about the surface plane, so it stays on its side and keeps its
//! weight: the lobe's rays average to the same total weight as the one ray they replace, and
//! energy never grows.

use crate::num::Norm;
use glam::DVec3;

use super::whitted::Outgoing;
use crate::render::sampler::Rng;

/// A direction in the cone of half-angle `gloss·90°` around unit `axis`, for the point `(a, b)`
/// of the unit square (uniform in solid angle), on the side of unit `side` (the surface normal
/// the ray leaves through).
pub fn lobe_direction(axis: DVec3, side: DVec3, gloss: f64, (a, b): (f64, f64)) -> DVec3 {
    let cos_max = libm::cos(gloss.clamp(0.0, 1.0) * std::f64::consts::FRAC_PI_2);
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

/// The random-number stream of a lobe at bounce `depth`; `refracted` tells the two lobes of a
/// surface apart. Disjoint from the lens (0) and light streams' high bits.
pub fn stream(depth: u32, refracted: bool) -> u32 {
    0x4000_0000 ^ (depth << 20) ^ u32::from(refracted)
}

/// The `k`-th direction of the lobe of `gloss` around ray `out` at bounce `depth`, for a camera
/// sample's `rng`.
pub fn sample(rng: &Rng, out: &Outgoing, gloss: f64, depth: u32, k: u32) -> DVec3 {
    let p = rng.point(stream(depth, out.refracted), k);
    lobe_direction(out.dir, out.side, gloss, p)
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
                    let d = lobe_direction(axis, n, gloss, p);
                    assert!((d.norm() - 1.0).abs() < 1e-12);
                    assert!(d.dot(n) >= 0.0);
                    if d.dot(axis) < cos_max - 1e-9 {
                        // Only a mirrored ray may leave the cone, and only when it was tipped
                        // through the surface.
                        assert!(gloss > 0.0 && axis.dot(n) < 1.0);
                    }
                }
            }
        }
    }

    #[test]
    fn zero_gloss_is_the_axis() {
        let axis = DVec3::new(1.0, 2.0, -0.5).unit();
        let d = lobe_direction(axis, DVec3::Y, 0.0, (0.7, 0.2));
        assert!((d - axis).norm() < 1e-12);
    }
}
