//! Fog along a ray (`render { fog: fog { .. } }`): POV-Ray 3.7's constant fog (`fog_type 1`) and
//! ground fog (`fog_type 2`), term for term as `Trace::ComputeFog`, `ComputeConstantFogDepth` and
//! `ComputeGroundFogDepth` in `source/core/render/trace.cpp` compute them; POV-Ray's turbulence
//! rule with any rtc pattern in place of its turbulence noise.

use glam::DVec3;

use crate::geometry::Ray;
use crate::ir::{Color, Fog, GroundFog};
use crate::opt::{Prepared, TextureMap};

/// How far a ray that meets nothing travels through the fog: POV-Ray's `BOUND_HUGE`, the depth
/// of an intersection that was not found, so the sky behind fog looks as it does there.
pub(crate) const MISS_DISTANCE: f64 = 2.0e10;

/// POV-Ray's `EPSILON`: ground fog's start and end heights closer than this read the density at
/// the start.
const EPSILON: f64 = 1.0e-10;

/// The colour `seen` at distance `t` along `ray` (unit direction), as it arrives through `fog`
/// (whose pattern, if any, is among `scene`'s textures).
pub(crate) fn apply(scene: &Prepared, fog: &Fog, ray: &Ray, t: f64, seen: Color) -> Color {
    let value = |p: DVec3| match fog
        .pattern
        .map(|fp| &scene.textures()[fp.texture.0 as usize])
    {
        Some(TextureMap::Pattern(pt)) => pt.field.eval(pt.to_pattern.transform_point3(p)),
        _ => 0.0,
    };
    through(fog, ray, t, seen, value)
}

/// [`apply`] with `value` reading the fog's pattern at a point.
fn through(fog: &Fog, ray: &Ray, t: f64, seen: Color, value: impl Fn(DVec3) -> f64) -> Color {
    let mut att = transmittance(fog, ray, t, value);
    // The fog's transmit is the least share that passes, however far.
    if att < fog.transmit {
        att = fog.transmit;
    }
    let kept = att * (DVec3::splat(1.0 - fog.filter) + fog.filter * fog.color);
    (1.0 - att) * fog.color + kept * seen
}

/// The share of light that crosses the first `t` of `ray` through `fog` (before its transmit),
/// `value` reading the fog's pattern at a point.
pub(crate) fn transmittance(fog: &Fog, ray: &Ray, t: f64, value: impl Fn(DVec3) -> f64) -> f64 {
    let density = match fog.ground {
        None => 1.0,
        Some(g) => ground_density(&g, ray.origin.y, ray.origin.y + ray.dir.y * t),
    };
    let mut width = t;
    if let Some(fp) = fog.pattern {
        // The pattern at the segment's midpoint thins it, less so the longer it is.
        let v = value(ray.origin + ray.dir * (0.5 * t));
        let k = libm::exp(-t / fog.distance);
        width *= 1.0 - k * (v * fp.depth).min(1.0);
    }
    libm::exp(-width * density / fog.distance)
}

/// The mean density of ground fog `g` between heights `y1` and `y2` (the density is 1 up to the
/// offset and `1/(1 + h²)` at `h` altitudes above it, whose integral is `atan h`).
fn ground_density(g: &GroundFog, y1: f64, y2: f64) -> f64 {
    let start = (y1 - g.offset) / g.altitude;
    let end = (y2 - g.offset) / g.altitude;
    if start <= 0.0 {
        if end <= 0.0 {
            1.0
        } else {
            (libm::atan(end) - start) / (end - start)
        }
    } else if end <= 0.0 {
        (libm::atan(start) - end) / (start - end)
    } else {
        let delta = start - end;
        if delta.abs() > EPSILON {
            (libm::atan(start) - libm::atan(end)) / delta
        } else {
            1.0 / (start * start + 1.0)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn constant(distance: f64) -> Fog {
        Fog {
            color: DVec3::new(0.5, 0.6, 0.7),
            distance,
            filter: 0.0,
            transmit: 0.0,
            ground: None,
            pattern: None,
        }
    }

    /// No pattern to read.
    fn none(_: DVec3) -> f64 {
        0.0
    }

    /// Along any ray, constant fog keeps exp(−d/D) of the light and adds the rest of its colour.
    #[test]
    fn constant_fog_is_exp_minus_d_over_distance() {
        let ray = Ray::new(DVec3::new(1.0, 2.0, 3.0), DVec3::new(0.6, 0.0, -0.8));
        let fog = constant(7.0);
        for d in [0.0, 0.5, 7.0, 20.0, 123.0] {
            let want = (-d / 7.0f64).exp();
            assert!((transmittance(&fog, &ray, d, none) - want).abs() < 1e-15);
            let seen = DVec3::new(1.0, 0.25, 0.0);
            let got = through(&fog, &ray, d, seen, none);
            let exact = want * seen + (1.0 - want) * fog.color;
            assert!(
                (got - exact).abs().max_element() < 1e-15,
                "{got} vs {exact}"
            );
        }
    }

    /// Transmit bounds what passes from below; filter tints it by the fog's colour.
    #[test]
    fn transmit_and_filter() {
        let ray = Ray::new(DVec3::ZERO, DVec3::X);
        let fog = Fog {
            transmit: 0.3,
            ..constant(1.0)
        };
        let got = through(&fog, &ray, 100.0, DVec3::ONE, none);
        assert!(
            (got - (0.7 * fog.color + DVec3::splat(0.3)))
                .abs()
                .max_element()
                < 1e-12
        );
        let fog = Fog {
            filter: 1.0,
            ..constant(1.0)
        };
        let a = (-1.0f64).exp();
        let got = through(&fog, &ray, 1.0, DVec3::ONE, none);
        let want = (1.0 - a) * fog.color + a * fog.color;
        assert!((got - want).abs().max_element() < 1e-12);
    }

    /// A pattern thins a segment as POV-Ray's turbulence does: `d·(1 − exp(−d/D)·min(1, v·depth))`
    /// with `v` read at the midpoint.
    #[test]
    fn pattern_thins_the_segment() {
        let fog = Fog {
            pattern: Some(crate::ir::FogPattern {
                texture: crate::ir::TextureId(0),
                depth: 0.8,
            }),
            ..constant(2.0)
        };
        let ray = Ray::new(DVec3::new(1.0, 0.0, 0.0), DVec3::Y);
        let mid = std::cell::Cell::new(DVec3::ZERO);
        let value = |p: DVec3| {
            mid.set(p);
            0.5
        };
        let got = transmittance(&fog, &ray, 3.0, value);
        assert_eq!(mid.get(), DVec3::new(1.0, 1.5, 0.0));
        let width = 3.0 * (1.0 - (-1.5f64).exp() * 0.4);
        assert!((got - (-width / 2.0).exp()).abs() < 1e-15);
        let full = transmittance(&fog, &ray, 3.0, |_| 5.0);
        let width = 3.0 * (1.0 - (-1.5f64).exp());
        assert!((full - (-width / 2.0).exp()).abs() < 1e-15);
    }

    /// Ground fog: full density below its offset, and along a level ray above it the density
    /// `1/(1 + h²)` of its height.
    #[test]
    fn ground_fog_density() {
        let g = GroundFog {
            offset: 1.0,
            altitude: 2.0,
        };
        let fog = Fog {
            ground: Some(g),
            ..constant(4.0)
        };
        let low = Ray::new(DVec3::new(0.0, 0.5, 0.0), DVec3::X);
        assert!((transmittance(&fog, &low, 3.0, none) - (-0.75f64).exp()).abs() < 1e-15);
        let level = Ray::new(DVec3::new(0.0, 5.0, 0.0), DVec3::X);
        let h: f64 = (5.0 - 1.0) / 2.0;
        let want = (-3.0 / (1.0 + h * h) / 4.0).exp();
        assert!((transmittance(&fog, &level, 3.0, none) - want).abs() < 1e-15);
        // Climbing from the offset to h = 1: the mean density is atan(1)/1 over the path.
        let up = Ray::new(DVec3::new(0.0, 1.0, 0.0), DVec3::Y);
        let want = (-2.0 * std::f64::consts::FRAC_PI_4 / 4.0).exp();
        assert!((transmittance(&fog, &up, 2.0, none) - want).abs() < 1e-15);
    }
}
