//! The analytic gradients of `pattern::slopes` against central differences of the values they
//! differentiate, and the octave envelope's rule.

use glam::{DAffine3, DQuat, DVec3};

use super::Lcg;
use crate::num::Norm;
use crate::pattern::noise::{improved, improved_and_gradient, unit, unit_and_gradient};
use crate::pattern::slopes::octave_weight;
use crate::pattern::{Field, Pattern, Repeat, Warp, WaveShape};

/// Central differences of `f` at `p` with step `h`.
fn numeric(f: impl Fn(DVec3) -> f64, p: DVec3, h: f64) -> DVec3 {
    DVec3::new(
        (f(p + h * DVec3::X) - f(p - h * DVec3::X)) / (2.0 * h),
        (f(p + h * DVec3::Y) - f(p - h * DVec3::Y)) / (2.0 * h),
        (f(p + h * DVec3::Z) - f(p - h * DVec3::Z)) / (2.0 * h),
    )
}

#[test]
fn improved_noise_value_is_bit_identical_and_its_gradient_exact() {
    let mut rnd = Lcg::new(11);
    for _ in 0..20_000 {
        let p = rnd.point(40.0);
        let (v, g) = improved_and_gradient(p, 7);
        assert_eq!(v.to_bits(), improved(p, 7).to_bits(), "at {p}");
        let want = numeric(|q| improved(q, 7), p, 1e-6);
        assert!((g - want).norm() < 1e-6, "at {p}: {g} vs {want}");
    }
}

#[test]
fn unit_noise_gradient_is_half_the_signed_one() {
    let mut rnd = Lcg::new(12);
    for _ in 0..5_000 {
        let p = rnd.point(10.0);
        let (v, g) = unit_and_gradient(p, 3);
        assert_eq!(v.to_bits(), unit(p, 3).to_bits());
        let want = numeric(|q| unit(q, 3), p, 1e-6);
        assert!((g - want).norm() < 1e-6, "at {p}: {g} vs {want}");
    }
}

#[test]
fn the_octave_envelope_is_flat_then_falls_as_one_over_frequency() {
    assert_eq!(octave_weight(1.0, 0.02), 1.0);
    assert_eq!(octave_weight(7.9, 0.02), 1.0);
    let w64 = octave_weight(64.0, 0.02);
    assert!((w64 - 1.0 / (std::f64::consts::TAU * 64.0 * 0.02)).abs() < 1e-15);
    assert!((octave_weight(128.0, 0.02) - w64 / 2.0).abs() < 1e-15);
}

/// Fraction of sample points where the field's analytic gradient (with no octave faded) agrees
/// with central differences of its value to 1e-4 relative.
fn agreement(field: &Field, seed: u64) -> f64 {
    let mut rnd = Lcg::new(seed);
    let mut agree = 0;
    let n = 2_000;
    for _ in 0..n {
        let p = rnd.point(3.0);
        let ours = field.gradient(p, 1e-12).expect("an analytic pattern");
        let want = numeric(|q| field.eval(q), p, 1e-7);
        if (ours - want).norm() <= 1e-4 * want.norm().max(1.0) {
            agree += 1;
        }
    }
    f64::from(agree) / f64::from(n)
}

#[test]
fn smooth_fields_agree_with_differences_everywhere() {
    // bozo through a rotated, stretched transform, a mirroring repeat and a sine wave: smooth
    // but at the repeat's slab walls, which random points do not hit.
    let mut field = Field::new(Pattern::Bozo { seed: 4 });
    field
        .warps
        .push(Warp::Transform(DAffine3::from_scale_rotation_translation(
            DVec3::new(0.7, 1.3, 2.0),
            DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).unit(), 0.8),
            DVec3::new(0.3, -1.0, 2.0),
        )));
    field.warps.push(Warp::Repeat(Repeat {
        axis: 1,
        width: 0.7,
        offset: DVec3::new(0.2, 0.0, 0.1),
        flip: DVec3::new(-1.0, -1.0, 1.0),
    }));
    field.wave.shape = WaveShape::Sine;
    field.wave.frequency = 1.7;
    assert_eq!(agreement(&field, 21), 1.0);
    for pattern in [Pattern::Leopard, Pattern::Dents { seed: 2 }, Pattern::Onion] {
        assert!(
            agreement(&Field::new(pattern.clone()), 22) > 0.999,
            "{pattern:?}"
        );
    }
    assert!(
        agreement(
            &Field::new(Pattern::gradient(DVec3::new(1.0, 2.0, 0.5))),
            23
        ) > 0.999
    );
}

#[test]
fn creased_sums_agree_with_differences_away_from_their_creases() {
    // granite's and wrinkles' octaves have creases and clamps where a difference straddles a
    // kink; away from them (nearly every point) the gradient is the derivative.
    for pattern in [Pattern::Granite { seed: 1 }, Pattern::Wrinkles { seed: 1 }] {
        let share = agreement(&Field::new(pattern.clone()), 24);
        assert!(share > 0.99, "{pattern:?}: {share}");
    }
}

#[test]
fn patterns_without_a_form_here_fall_back() {
    assert!(
        Field::new(Pattern::Checker)
            .gradient(DVec3::ONE, 0.02)
            .is_none()
    );
    assert!(
        Field::new(Pattern::Crackle {
            form: crate::pattern::Crackle::Edges,
            seed: 0
        })
        .gradient(DVec3::ONE, 0.02)
        .is_none()
    );
    let mut warped = Field::new(Pattern::Bozo { seed: 0 });
    warped.warps.push(Warp::Spherical);
    assert!(warped.gradient(DVec3::ONE, 0.02).is_none());
}

#[test]
fn faded_sums_keep_the_relief_of_differences_at_the_step() {
    // The envelope stands in for what central differences of the step do to fine octaves, so
    // the mean slope a bump shows should stay close to the differences' (the look a scene's
    // bump strength was tuned on). Measured: wrinkles 0.97, granite 1.20 (differences
    // straddling granite's many creases flatten them).
    let step = 0.02;
    for pattern in [Pattern::Wrinkles { seed: 5 }, Pattern::Granite { seed: 5 }] {
        let field = Field::new(pattern.clone());
        let mut rnd = Lcg::new(31);
        let (mut ours, mut theirs) = (0.0_f64, 0.0_f64);
        for _ in 0..20_000 {
            let p = rnd.point(20.0);
            ours += field.gradient(p, step).unwrap().length_squared();
            theirs += numeric(|q| field.eval(q), p, step).length_squared();
        }
        let ratio = (ours / theirs).sqrt();
        eprintln!("{pattern:?}: rms slope analytic / differences = {ratio:.3}");
        assert!((ratio - 1.0).abs() < 0.25, "{pattern:?}: {ratio}");
    }
}
