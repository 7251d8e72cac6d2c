//! Distance and angle patterns against their definitions.

use std::f64::consts::{PI, TAU};

use glam::DVec3;

use super::Lcg;
use crate::pattern::geometric::{
    boxed, cylindrical, gradient, onion, planar, radial, spherical, spiral1, spiral2, triangle,
};
use crate::pattern::warps::Turbulence;
use crate::pattern::{Field, Pattern, Wave, WaveShape};

/// Gradient is the coordinate along its direction, whose length does not matter (POV-Ray
/// normalises it), given to the wave as POV-Ray gives it: above 1 its remainder modulo 1
/// (so 1.0 is 1, 2.0 is 0), below 0 as it is. Through the wave (the field) the colour map reads
/// the fractional coordinate; at a fractional frequency the wave wraps `v · frequency`, so
/// negative coordinates read what POV-Ray's do.
#[test]
fn gradient_is_the_fractional_coordinate() {
    let mut rng = Lcg::new(101);
    let along_x = Field::new(Pattern::gradient(DVec3::X));
    let up = Field::new(Pattern::gradient(DVec3::new(0.0, 2.0, 0.0)));
    for _ in 0..10_000 {
        let p = rng.point(100.0);
        let raw = if p.x > 1.0 { p.x % 1.0 } else { p.x };
        assert_eq!(gradient(p, DVec3::X), raw);
        assert!((along_x.eval(p) - (p.x - p.x.floor())).abs() < 1e-12);
        assert!((up.eval(p) - (p.y - p.y.floor())).abs() < 1e-12);
    }
    assert_eq!(gradient(DVec3::new(2.25, 9.0, 9.0), DVec3::X), 0.25);
    assert_eq!(gradient(DVec3::new(-0.25, 0.0, 0.0), DVec3::X), -0.25);
    assert_eq!(along_x.eval(DVec3::new(-0.25, 0.0, 0.0)), 0.75);
    assert_eq!(gradient(DVec3::new(0.0, 1.0, 0.0), DVec3::Y), 1.0);
    assert_eq!(gradient(DVec3::new(0.0, 2.0, 0.0), DVec3::Y), 0.0);
    // Frequency 1.5 at x = −0.25: POV-Ray wraps −0.375 to 0.625 (not 0.75 · 1.5 = 1.125 → 0.125).
    let faster = Field {
        wave: Wave {
            frequency: 1.5,
            ..Wave::new(WaveShape::Ramp)
        },
        ..along_x.clone()
    };
    assert_eq!(faster.eval(DVec3::new(-0.25, 0.0, 0.0)), 0.625);
    let diagonal = Pattern::gradient(DVec3::new(1.0, 1.0, 0.0));
    let along = 0.7 / 2f64.sqrt();
    assert!((diagonal.eval(DVec3::new(0.3, 0.4, 7.0)) - along).abs() < 1e-12);
    assert_eq!(
        Pattern::gradient(DVec3::ZERO),
        Pattern::Gradient { axis: DVec3::X }
    );
}

/// Onion is the fractional distance from the origin.
#[test]
fn onion_is_the_fractional_distance() {
    let mut rng = Lcg::new(103);
    for _ in 0..10_000 {
        let dir = {
            let v = rng.point(1.0);
            v / v.dot(v).sqrt()
        };
        let r = 20.0 * rng.next();
        let v = onion(r * dir);
        assert!((v - (r - r.floor())).abs() < 1e-9, "r {r}: {v}");
        assert!((0.0..1.0).contains(&v));
    }
    assert_eq!(onion(DVec3::new(0.0, 2.5, 0.0)), 0.5);
    assert_eq!(onion(DVec3::new(3.0, 4.0, 0.0)), 0.0);
}

/// Spherical, cylindrical, boxed and planar fall linearly from 1 to 0 over a unit of their
/// distance (Euclidean from the origin, from the y axis, the largest coordinate, |y|).
#[test]
fn falloffs_are_one_minus_their_distance() {
    assert_eq!(spherical(DVec3::ZERO), 1.0);
    assert_eq!(spherical(DVec3::new(0.0, 0.0, 0.25)), 0.75);
    assert_eq!(spherical(DVec3::new(0.6, 0.8, 0.0)), 0.0);
    assert_eq!(spherical(DVec3::new(3.0, 0.0, 0.0)), 0.0);
    assert_eq!(cylindrical(DVec3::new(0.0, 123.0, 0.0)), 1.0);
    assert_eq!(cylindrical(DVec3::new(0.3, -50.0, 0.4)), 0.5);
    assert_eq!(cylindrical(DVec3::new(2.0, 0.0, 0.0)), 0.0);
    assert_eq!(boxed(DVec3::new(0.25, -0.5, 0.125)), 0.5);
    assert_eq!(boxed(DVec3::new(0.1, 0.1, -1.5)), 0.0);
    assert_eq!(planar(DVec3::new(77.0, -0.25, 9.0)), 0.75);
    assert_eq!(planar(DVec3::new(0.0, 1.0, 0.0)), 0.0);
    let mut rng = Lcg::new(107);
    for _ in 0..10_000 {
        let p = rng.point(2.0);
        let r = p.dot(p).sqrt();
        assert!((spherical(p) - (1.0 - r).max(0.0)).abs() < 1e-15);
        let m = p.abs().max_element();
        assert_eq!(boxed(p), (1.0 - m).max(0.0));
    }
}

/// Radial: 0.25 on −z, 0.5 on −x, 0.75 on +z, 1 on +x, rising linearly with the angle turning
/// from +x towards −z, to 1.25 just before −z (POV-Ray's value, which its wave wraps: through
/// the field 1 on +x and 0 just past it); 0.25 within 0.001 of the axis.
#[test]
fn radial_is_the_turn_about_y() {
    let at = |angle: f64| radial(DVec3::new(libm::cos(angle), 3.0, -libm::sin(angle)));
    let wrapped = Field::new(Pattern::Radial);
    let seen = |angle: f64| wrapped.eval(DVec3::new(libm::cos(angle), 3.0, -libm::sin(angle)));
    // −z is where the value jumps from 1.25 down to 0.25: rounding picks the side.
    assert!((seen(PI / 2.0) - 0.25).abs() < 1e-12);
    assert!((at(PI) - 0.5).abs() < 1e-12);
    assert!((at(1.5 * PI) - 0.75).abs() < 1e-12);
    assert_eq!(radial(DVec3::new(1.0, 0.0, 0.0)), 1.0);
    assert_eq!(wrapped.eval(DVec3::new(1.0, 0.0, 0.0)), 1.0);
    for i in 1..100 {
        let angle = TAU * f64::from(i) / 100.0;
        let turn = angle / TAU;
        let raw = if i < 25 { 1.0 + turn } else { turn };
        let off = (at(angle) - raw).abs();
        assert!(
            off < 1e-12 || (i == 25 && (off - 1.0).abs() < 1e-12),
            "angle {angle}: {}",
            at(angle)
        );
        assert!(
            (seen(angle) - turn).abs() < 1e-12,
            "angle {angle}: {}",
            seen(angle)
        );
    }
    assert_eq!(radial(DVec3::new(0.0005, 7.0, -0.0009)), 0.25);
}

/// Spiral1 rises one unit per unit along z and per unit of distance from the axis, and by one
/// per `1/arms` of a turn; spiral2 is the sum of the triangle waves of the radius and of
/// spiral1, in [0, 2].
#[test]
fn spirals_wind_with_their_arms() {
    let none = Turbulence::NONE;
    let arms = 3.0;
    let mut rng = Lcg::new(109);
    for _ in 0..10_000 {
        let (r, z) = (1.0 + 5.0 * rng.next(), 10.0 * rng.next() - 5.0);
        // An angle away from φ = 0 (towards −y), where the value wraps.
        let phi = 0.1 + (TAU - 0.2 - TAU / arms) * rng.next();
        // φ = atan2(y, x) + π/2, so the point at φ is at polar angle φ − π/2.
        let p = |phi: f64, r: f64, z: f64| {
            DVec3::new(
                r * libm::cos(phi - PI / 2.0),
                r * libm::sin(phi - PI / 2.0),
                z,
            )
        };
        let v = spiral1(p(phi, r, z), arms, &none);
        assert!((v - (z + r + arms * phi / TAU)).abs() < 1e-9);
        let turned = spiral1(p(phi + TAU / arms, r, z), arms, &none);
        assert!((turned - v - 1.0).abs() < 1e-9, "{turned} vs {v}");
        assert!((spiral1(p(phi, r, z + 0.5), arms, &none) - v - 0.5).abs() < 1e-9);
        let two = spiral2(p(phi, r, z), arms, &none);
        assert!((two - (triangle(r) + triangle(v))).abs() < 1e-9);
        assert!((0.0..=2.0).contains(&two));
    }
    // On the axis the angle is 0.
    assert_eq!(spiral1(DVec3::new(0.0, 0.0, 2.5), arms, &none), 2.5);
}

/// POV-Ray's triangle wave: 0 at whole numbers, 1 halfway.
#[test]
fn triangle_wave_values() {
    for (v, t) in [
        (0.0, 0.0),
        (0.25, 0.5),
        (0.5, 1.0),
        (0.75, 0.5),
        (1.0, 0.0),
        (-0.25, 0.5),
        (7.5, 1.0),
    ] {
        assert_eq!(triangle(v), t, "triangle({v})");
    }
}
