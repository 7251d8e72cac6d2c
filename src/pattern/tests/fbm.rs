//! Fractal sums: variance as the octaves' independence predicts, the structure function's
//! slope as omega and lambda set it, POV-Ray's scalar turbulence's mean, the bounds.

use glam::DVec3;

use super::{Lcg, moments};
use crate::pattern::fbm::{self, Fractal};
use crate::pattern::noise::{self, BOUND};

/// The raw noise's variance (its standard deviation 0.270, measured on the same points).
fn noise_variance() -> f64 {
    moments(200_000, 500.0, 31, |p| noise::signed(p, 0)).1
}

/// Independent octaves: the variance of the sum is `σ²·Σ ω²ⁱ`, within 3 %, for two sets of
/// parameters.
#[test]
fn variance_follows_omega_squared() {
    let var = noise_variance();
    for f in [
        Fractal::default(),
        Fractal {
            octaves: 8,
            omega: 0.7,
            lambda: 1.9,
        },
    ] {
        let expected: f64 = (0..f.octaves)
            .map(|i| f.omega.powi(2 * i as i32))
            .sum::<f64>()
            * var;
        let (mean, got) = moments(200_000, 500.0, 31, |p| fbm::fbm(p, &f, 0));
        eprintln!("{f:?}: variance {got:.5}, expected {expected:.5}, mean {mean:.5}");
        assert!((got / expected - 1.0).abs() < 0.03, "{got} vs {expected}");
        assert!(mean.abs() < 0.01);
        let (_, vector) = moments(100_000, 500.0, 37, |p| fbm::vector(p, &f, 0).y);
        assert!(
            (vector / expected - 1.0).abs() < 0.04,
            "vector {vector} vs {expected}"
        );
    }
}

/// The spectrum's slope: the structure function `D(d) = E[(f(p + d) − f(p))²]` of fBm scales
/// as `d^2H` with `ω = λ^−H` between its lowest and highest octave, so `D(d/λ)/D(d) = ω²`
/// there (exactly, up to the lowest octave's own `D(d/λ)`, 1 % here). Checked at three lags for
/// omega 0.5 and lambda 3 (2H = 1.26) over 14 octaves, within 10 %.
#[test]
fn structure_function_slope_follows_omega_and_lambda() {
    let f = Fractal {
        octaves: 14,
        omega: 0.5,
        lambda: 3.0,
    };
    let mut rng = Lcg::new(41);
    let points: Vec<DVec3> = (0..100_000).map(|_| rng.point(300.0)).collect();
    let structure = |d: f64| {
        let sum: f64 = points
            .iter()
            .map(|&p| {
                let step = fbm::fbm(p + DVec3::new(d, 0.0, 0.0), &f, 3) - fbm::fbm(p, &f, 3);
                step * step
            })
            .sum();
        sum / points.len() as f64
    };
    let expected_slope = -2.0 * f.omega.ln() / f.lambda.ln();
    for power in [4, 5, 6] {
        let d = f.lambda.powi(-power);
        let ratio = structure(d / f.lambda) / structure(d);
        let slope = -ratio.ln() / f.lambda.ln();
        eprintln!(
            "d = 3^-{power}: D(d/λ)/D(d) = {ratio:.4} (ω² = 0.25), slope {slope:.3} (expected {expected_slope:.3})"
        );
        assert!(
            (ratio / (f.omega * f.omega) - 1.0).abs() < 0.10,
            "ratio {ratio}"
        );
    }
}

/// POV-Ray's scalar turbulence has mean `0.5·Σωⁱ` (each term is `0.5 + signed`); fBm stays
/// within `±BOUND·Σωⁱ` and Perlin's turbulence within `[0, BOUND·Σωⁱ]`.
#[test]
fn sums_have_their_documented_means_and_bounds() {
    let f = Fractal::default();
    let amplitude = f.amplitude();
    assert!((amplitude - 1.96875).abs() < 1e-12);
    let (mean, _) = moments(200_000, 500.0, 43, |p| fbm::classic(p, &f, 0));
    assert!(
        (mean - 0.5 * amplitude).abs() < 0.01 * amplitude,
        "classic mean {mean}"
    );
    let (turbulent, _) = moments(200_000, 500.0, 43, |p| fbm::turbulence(p, &f, 0));
    eprintln!("turbulence mean {:.4} × Σωⁱ", turbulent / amplitude);
    assert!(
        (turbulent / amplitude - 0.22).abs() < 0.01,
        "turbulence mean {turbulent}"
    );
    let mut rng = Lcg::new(47);
    for _ in 0..100_000 {
        let p = rng.point(1000.0);
        let b = fbm::fbm(p, &f, 1);
        let t = fbm::turbulence(p, &f, 1);
        assert!(b.abs() <= BOUND * amplitude);
        assert!((0.0..=BOUND * amplitude).contains(&t));
        let first = (2.0 * noise::unit(p, 1) - 0.5).clamp(0.0, 1.0);
        let single = Fractal { octaves: 1, ..f };
        assert_eq!(fbm::classic(p, &single, 1), first);
    }
    // Zero octaves sum one, as POV-Ray's loop always does.
    let none = Fractal { octaves: 0, ..f };
    let p = DVec3::new(0.3, 0.7, 0.1);
    assert_eq!(fbm::fbm(p, &none, 2), noise::signed(p, 2));
}

/// Each octave is the noise under its own seed at `λⁱ·p`: a one-octave sum is the noise, and
/// the second octave is added at twice the frequency with half the weight.
#[test]
fn octaves_are_scaled_copies_under_their_own_seeds() {
    let one = Fractal {
        octaves: 1,
        omega: 0.5,
        lambda: 2.0,
    };
    let two = Fractal { octaves: 2, ..one };
    let mut rng = Lcg::new(53);
    for _ in 0..1000 {
        let p = rng.point(100.0);
        assert_eq!(fbm::fbm(p, &one, 9), noise::signed(p, 9));
        let second = noise::signed(2.0 * p, fbm::octave_seed(9, 1));
        assert_eq!(fbm::fbm(p, &two, 9), noise::signed(p, 9) + 0.5 * second);
        assert_eq!(
            fbm::vector(p, &two, 9),
            noise::vector(p, 9) + 0.5 * noise::vector(2.0 * p, fbm::octave_seed(9, 1))
        );
    }
    assert_ne!(fbm::octave_seed(9, 1), 9);
}
