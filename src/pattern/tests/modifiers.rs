//! Wave shapes, frequency and phase; turbulence, repeat and wrapping warps; a field with both.

use glam::DVec3;

use super::Lcg;
use crate::num::Norm;
use crate::pattern::fbm::{self, Fractal};
use crate::pattern::warps::longitude;
use crate::pattern::waves::wrap;
use crate::pattern::{Field, Pattern, Repeat, Turbulence, Warp, Wave, WaveShape};

/// Each shape at its phase points: 0, a quarter, a half, three quarters, 1.
#[test]
fn wave_shapes_at_their_phase_points() {
    let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
    let table: [(WaveShape, [f64; 5]); 6] = [
        (WaveShape::Ramp, [0.0, 0.25, 0.5, 0.75, 1.0]),
        (WaveShape::Triangle, [0.0, 0.5, 1.0, 0.5, 0.0]),
        (WaveShape::Sine, [0.5, 1.0, 0.5, 0.0, 0.5]),
        (
            WaveShape::Scallop,
            [0.0, 0.5f64.sqrt(), 1.0, 0.5f64.sqrt(), 0.0],
        ),
        (WaveShape::Cubic, [0.0, 0.156_25, 0.5, 0.843_75, 1.0]),
        (WaveShape::Poly(2.0), [0.0, 0.0625, 0.25, 0.5625, 1.0]),
    ];
    for (shape, values) in table {
        for (i, want) in values.into_iter().enumerate() {
            let v = i as f64 / 4.0;
            assert!(
                close(shape.at(v), want),
                "{shape:?} at {v}: {}",
                shape.at(v)
            );
        }
    }
    let mut rng = Lcg::new(401);
    for _ in 0..1000 {
        let v = rng.next();
        assert_eq!(WaveShape::Poly(1.0).at(v), v);
        // Cubic is symmetric about (0.5, 0.5); sine and triangle are periodic shapes.
        assert!(close(
            WaveShape::Cubic.at(v) + WaveShape::Cubic.at(1.0 - v),
            1.0
        ));
        assert!(close(
            WaveShape::Triangle.at(v),
            WaveShape::Triangle.at(1.0 - v)
        ));
        assert!((0.0..=1.0).contains(&WaveShape::Scallop.at(v)));
    }
}

/// Frequency and phase scale and shift the value before it wraps into [0, 1]; a value
/// already in [0, 1] is kept (1 stays 1); frequency 0 leaves the value unscaled and unshifted.
#[test]
fn frequency_and_phase_wrap_the_value() {
    assert_eq!(wrap(1.0), 1.0);
    assert_eq!(wrap(0.0), 0.0);
    assert_eq!(wrap(2.0), 0.0);
    assert_eq!(wrap(-0.25), 0.75);
    assert_eq!(wrap(3.5), 0.5);
    let wave = Wave {
        shape: WaveShape::Ramp,
        frequency: 2.0,
        phase: 0.25,
    };
    assert_eq!(wave.apply(0.3), 0.85);
    assert_eq!(wave.apply(0.5), 0.25);
    assert_eq!(wave.apply(-0.25), 0.75);
    let sine = Wave {
        shape: WaveShape::Sine,
        frequency: 3.0,
        phase: 0.0,
    };
    assert!((sine.apply(1.0 / 12.0) - 1.0).abs() < 1e-12);
    let still = Wave {
        shape: WaveShape::Ramp,
        frequency: 0.0,
        phase: 0.5,
    };
    assert_eq!(still.apply(0.3), 0.3);
    assert_eq!(still.apply(1.3), 1.3 - 1.0);
    assert_eq!(Wave::default().apply(0.4), 0.4);
}

/// The turbulence warp is the identity without turbulence and `p + amount ⊙ vector fBm`
/// with it; its displacement has mean 0 and grows with the amount.
#[test]
fn turbulence_warp_displaces_by_vector_fbm() {
    let p = DVec3::new(0.3, -2.0, 5.5);
    assert_eq!(Turbulence::NONE.warp(p), p);
    assert_eq!(Turbulence::NONE.scalar(p), 0.0);
    let t = Turbulence {
        amount: DVec3::new(0.5, 1.0, 0.0),
        fractal: Fractal {
            octaves: 3,
            omega: 0.6,
            lambda: 2.2,
        },
        seed: 12,
    };
    let mut rng = Lcg::new(403);
    let mut sum = DVec3::ZERO;
    for _ in 0..50_000 {
        let p = rng.point(100.0);
        let moved = t.amount * fbm::vector(p, &t.fractal, 12);
        assert_eq!(t.warp(p), p + moved);
        assert_eq!(moved.z, 0.0);
        sum += moved;
    }
    assert!(
        (sum / 50_000.0).abs().max_element() < 0.01,
        "{}",
        sum / 50_000.0
    );
}

/// The repeat warp shows the first slab everywhere: periodic along its axis, each slab moved
/// by the offset, odd slabs mirrored by the flip.
#[test]
fn repeat_warp_copies_the_first_slab() {
    let plain = Repeat::along(0, 2.0);
    let mut rng = Lcg::new(405);
    for _ in 0..10_000 {
        let p = rng.point(50.0);
        let q = plain.warp(p);
        assert!((0.0..2.0).contains(&q.x), "{q}");
        assert_eq!((q.y, q.z), (p.y, p.z));
        assert!((plain.warp(p + DVec3::new(6.0, 0.0, 0.0)).x - q.x).abs() < 1e-12);
    }
    let shifted = Repeat {
        offset: DVec3::new(0.0, 0.5, 0.0),
        ..Repeat::along(2, 1.0)
    };
    assert_eq!(
        shifted.warp(DVec3::new(0.0, 0.0, 3.25)),
        DVec3::new(0.0, 1.5, 0.25)
    );
    let mirror = Repeat {
        flip: DVec3::new(-1.0, 1.0, 1.0),
        ..Repeat::along(0, 1.0)
    };
    assert_eq!(
        mirror.warp(DVec3::new(1.25, 3.0, 4.0)),
        DVec3::new(0.75, 3.0, 4.0)
    );
    assert_eq!(
        mirror.warp(DVec3::new(2.25, 3.0, 4.0)),
        DVec3::new(0.25, 3.0, 4.0)
    );
    // Mirrored slabs meet their neighbours edge to edge: continuous across x = 1.
    let (a, b) = (
        mirror.warp(DVec3::new(0.999, 0.0, 0.0)),
        mirror.warp(DVec3::new(1.001, 0.0, 0.0)),
    );
    assert!((a.x - b.x).abs() < 0.01);
}

/// The spherical, cylindrical and toroidal warps measure the longitude from +x towards +z, as
/// POV-Ray's do (+x 0, +z ¼, −x ½, −z ¾); the torus's tube angle is 0 on its inner equator, ¼
/// below the core circle, ½ outside and ¾ above; points on the axis stay where they are.
#[test]
fn wrapping_warps_measure_angles_as_povray() {
    let close = |a: DVec3, b: DVec3| (a - b).abs().max_element() < 1e-12;
    for (p, turn) in [
        (DVec3::X, 0.0),
        (DVec3::Z, 0.25),
        (-DVec3::X, 0.5),
        (-DVec3::Z, 0.75),
        (DVec3::new(1.0, 0.0, 1.0), 0.125),
    ] {
        assert!((longitude(p) - turn).abs() < 1e-15, "{p}");
        let r = p.norm();
        let on_sphere = Warp::Spherical.apply(p * 3.0);
        assert!(
            close(on_sphere, DVec3::new(turn, 0.5, 3.0 * r)),
            "{on_sphere}"
        );
        let round_axis = Warp::Cylindrical.apply(p * 2.0 + DVec3::new(0.0, 0.7, 0.0));
        assert!(
            close(round_axis, DVec3::new(turn, 0.7, 2.0 * r)),
            "{round_axis}"
        );
    }
    // Latitude: 0 at the south pole, 1 at the north pole.
    let north = Warp::Spherical.apply(DVec3::new(0.0, 2.0, 0.0));
    assert!(close(north, DVec3::new(0.0, 1.0, 2.0)), "{north}");
    let south = Warp::Spherical.apply(DVec3::new(0.0, -2.0, 0.0));
    assert!(close(south, DVec3::new(0.0, 0.0, 2.0)), "{south}");
    for p in [DVec3::ZERO, DVec3::new(0.0, 0.4, 0.0)] {
        assert_eq!(Warp::Cylindrical.apply(p), p);
        assert_eq!(Warp::Toroidal(1.0).apply(p), p);
    }
    assert_eq!(Warp::Spherical.apply(DVec3::ZERO), DVec3::ZERO);
    // Round a torus of major radius 2 at +z (longitude ¼): the tube's angle and distance.
    let torus = Warp::Toroidal(2.0);
    for (offset, tube) in [
        (DVec3::new(0.0, 0.0, -0.5), 0.0),
        (DVec3::new(0.0, -0.5, 0.0), 0.25),
        (DVec3::new(0.0, 0.0, 0.5), 0.5),
        (DVec3::new(0.0, 0.5, 0.0), 0.75),
    ] {
        let q = torus.apply(DVec3::new(0.0, 0.0, 2.0) + offset);
        assert!(close(q, DVec3::new(0.25, tube, 0.5)), "{offset}: {q}");
    }
}

/// A field warps the point, reads the pattern, then shapes the value (marble: the triangle by
/// default); a discrete pattern's index passes through its wave untouched.
#[test]
fn a_field_is_wave_of_pattern_of_warped_point() {
    let marble = Field::new(Pattern::named("marble").expect("marble"));
    assert_eq!(marble.wave.shape, WaveShape::Triangle);
    assert_eq!(marble.eval(DVec3::new(0.25, 7.0, 7.0)), 0.5);
    assert_eq!(marble.eval(DVec3::new(1.5, 7.0, 7.0)), 1.0);
    let checker = Field {
        wave: Wave {
            shape: WaveShape::Sine,
            frequency: 3.0,
            phase: 0.1,
        },
        ..Field::new(Pattern::Checker)
    };
    assert_eq!(checker.eval(DVec3::new(1.5, 0.5, 0.5)), 1.0);
    let repeated = Field {
        warps: vec![
            Warp::Repeat(Repeat::along(0, 1.0)),
            Warp::Turbulence(Turbulence::NONE),
        ],
        ..Field::new(Pattern::gradient(DVec3::new(0.5, 0.0, 0.0)))
    };
    // Gradient along x (the direction's length does not matter) over the repeated first
    // unit: 0.5 at x = 3.5.
    assert_eq!(repeated.eval(DVec3::new(3.5, 0.0, 0.0)), 0.5);
}
