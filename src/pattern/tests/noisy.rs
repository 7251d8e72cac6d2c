//! Noise-based patterns, ripples and waves; and every named pattern within its range.

use std::f64::consts::{FRAC_PI_2, TAU};

use glam::DVec3;

use super::{Lcg, moments};
use crate::pattern::fbm::{self, Fractal};
use crate::pattern::noise;
use crate::pattern::noisy::{self, Crackle};
use crate::pattern::ripples::{self, MAX_WAVES};
use crate::pattern::warps::Turbulence;
use crate::pattern::{NAMES, Pattern, cells};

/// Every name builds, and its pattern's values over 20 000 points lie in its documented range
/// (discrete ones are whole numbers below their count; continuous ones are finite).
#[test]
fn every_named_pattern_stays_in_its_range() {
    let mut rng = Lcg::new(301);
    let points: Vec<DVec3> = (0..20_000).map(|_| rng.point(20.0)).collect();
    for name in NAMES {
        let pattern = Pattern::named(name).unwrap_or_else(|| panic!("{name}"));
        let (lo, hi) = pattern.range();
        let (mut min, mut max) = (f64::INFINITY, f64::NEG_INFINITY);
        for &p in &points {
            let v = pattern.eval(p);
            assert!(v.is_finite() && lo <= v && v <= hi, "{name}: {v} at {p}");
            if let Some(n) = pattern.entries() {
                assert!(v.fract() == 0.0 && v < f64::from(n), "{name}: {v}");
            }
            min = min.min(v);
            max = max.max(v);
        }
        eprintln!("{name:>12}: [{min:.4}, {max:.4}] in [{lo}, {hi}]");
        // Each pattern varies over the sample.
        assert!(max > min, "{name} is constant");
    }
    assert_eq!(Pattern::named("spotted"), Pattern::named("bozo"));
    assert_eq!(Pattern::named("bumps"), Pattern::named("bozo"));
    assert_eq!(Pattern::named("plasma"), None);
}

/// Bozo is the unit noise (mean 0.5), dents its cube (mean E[n³] ≈ 0.152), granite and
/// wrinkles have the means docs/textures.md states.
#[test]
fn noise_patterns_have_their_documented_means() {
    let measure = |f: fn(DVec3, u32) -> f64| moments(200_000, 500.0, 303, |p| f(p, 0)).0;
    let (bozo, dents) = (measure(noisy::bozo), measure(noisy::dents));
    let (granite, wrinkles) = (measure(noisy::granite), measure(noisy::wrinkles));
    eprintln!("means: bozo {bozo:.4} dents {dents:.4} granite {granite:.4} wrinkles {wrinkles:.4}");
    assert!((bozo - 0.5).abs() < 0.01);
    assert!((dents - 0.152).abs() < 0.01);
    assert!((granite - 0.425).abs() < 0.01);
    assert!((wrinkles - 0.50).abs() < 0.01);
    let mut rng = Lcg::new(305);
    for _ in 0..1000 {
        let p = rng.point(100.0);
        assert_eq!(noisy::bozo(p, 4), noise::unit(p, 4));
        assert_eq!(noisy::dents(p, 4), noise::unit(p, 4).powi(3));
    }
}

/// The noise patterns are continuous: no jump over a step of 10⁻⁴ larger than their slope
/// allows (granite's ten-fold frequencies: 4·(1 + 2 + … + 32)/… bounded by 3.75·4·6·h).
#[test]
fn noise_patterns_are_continuous() {
    let h = 1e-4;
    let mut rng = Lcg::new(307);
    let agate = Pattern::named("agate").expect("agate");
    for _ in 0..20_000 {
        let p = rng.point(50.0);
        let q = p + DVec3::new(h, -h, h) / 3f64.sqrt();
        for (name, v, w, bound) in [
            ("bozo", noisy::bozo(p, 1), noisy::bozo(q, 1), 2.0),
            (
                "granite",
                noisy::granite(p, 1),
                noisy::granite(q, 1),
                3.75 * 4.0 * 6.0,
            ),
            (
                "wrinkles",
                noisy::wrinkles(p, 1),
                noisy::wrinkles(q, 1),
                3.75 * 10.0,
            ),
            ("agate", agate.eval(p), agate.eval(q), 200.0),
        ] {
            assert!((v - w).abs() <= bound * h, "{name}: {v} → {w} at {p}");
        }
    }
}

/// Leopard is `((sin x + sin y + sin z)/3)²`: 1 at (π/2, π/2, π/2), 0 at the origin.
#[test]
fn leopard_is_its_formula() {
    assert_eq!(noisy::leopard(DVec3::splat(FRAC_PI_2)), 1.0);
    assert_eq!(noisy::leopard(DVec3::ZERO), 0.0);
    let p = DVec3::new(0.3, 1.1, -2.0);
    let s = (p.x.sin() + p.y.sin() + p.z.sin()) / 3.0;
    assert!((noisy::leopard(p) - s * s).abs() < 1e-15);
}

/// Marble without turbulence is x; with it, x plus `amount · classic`, whose mean is
/// `0.5·Σωⁱ·amount`. Wood without turbulence is the distance from the z axis.
#[test]
fn marble_and_wood_are_their_ramps_plus_turbulence() {
    let none = Turbulence::NONE;
    let p = DVec3::new(1.25, -3.0, 7.0);
    assert_eq!(noisy::marble(p, &none), 1.25);
    assert_eq!(noisy::wood(DVec3::new(3.0, 4.0, 99.0), &none), 5.0);
    let turbulence = Turbulence::uniform(0.8);
    let mut rng = Lcg::new(309);
    let mut sum = 0.0;
    for _ in 0..100_000 {
        let p = rng.point(100.0);
        let push = noisy::marble(p, &turbulence) - p.x;
        assert!((push - 0.8 * fbm::classic(p, &Fractal::default(), 0)).abs() < 1e-12);
        sum += push;
    }
    let expected = 0.8 * 0.5 * Fractal::default().amplitude();
    assert!(
        (sum / 100_000.0 - expected).abs() < 0.01,
        "{} vs {expected}",
        sum / 100_000.0
    );
    // Wood's rings wobble: points at one radius read different values.
    let a = noisy::wood(DVec3::new(2.0, 0.0, 0.0), &turbulence);
    let b = noisy::wood(DVec3::new(0.0, 2.0, 0.0), &turbulence);
    assert_ne!(a, b);
}

/// Crackle's forms are F1, F2 and F2 − F1 of the Worley distances, clamped to [0, 1]: F1 is 0
/// at a feature point; F2 − F1 is 0 halfway between two feature points that are each other's
/// nearest, and largest at the points themselves.
#[test]
fn crackle_forms_are_worley_distances() {
    let mut rng = Lcg::new(311);
    for _ in 0..10_000 {
        let p = rng.point(200.0);
        let d = cells::worley(p, 6);
        assert_eq!(noisy::crackle(p, Crackle::F1, 6), d.f1.min(1.0));
        assert_eq!(noisy::crackle(p, Crackle::F2, 6), d.f2.min(1.0));
        assert_eq!(noisy::crackle(p, Crackle::Edges, 6), (d.f2 - d.f1).min(1.0));
    }
    let q = cells::feature([3, -4, 5], 6);
    assert_eq!(noisy::crackle(q, Crackle::F1, 6), 0.0);
    // The midpoint of q and its nearest other feature point lies on their cell wall.
    let d = cells::worley(q, 6);
    let mut nearest = DVec3::ZERO;
    for dz in -2..=2 {
        for dy in -2..=2 {
            for dx in -2..=2 {
                let r = cells::feature([3 + dx, -4 + dy, 5 + dz], 6);
                if (r - q).dot(r - q) == d.f2 * d.f2 {
                    nearest = r;
                }
            }
        }
    }
    let mid = 0.5 * (q + nearest);
    let at_mid = cells::worley(mid, 6);
    if (at_mid.f1 - 0.5 * d.f2).abs() < 1e-12 {
        assert!(noisy::crackle(mid, Crackle::Edges, 6) < 1e-9);
    }
}

/// Ripples with one source is `0.5·(1 + sin 2π(r·f + φ))` of the distance from it; with any
/// count it stays in [0, 1]. Waves stay within `0.5 ± waves_reach`. The sources lie on the
/// unit sphere with relative frequencies in [0.01, 1.01).
#[test]
fn ripples_and_waves_ring_around_their_sources() {
    let all = ripples::sources(MAX_WAVES as u32);
    assert_eq!(all.len(), MAX_WAVES);
    for s in all {
        assert!((s.center.dot(s.center) - 1.0).abs() < 1e-12);
        assert!((0.01..1.01).contains(&s.frequency));
    }
    assert_eq!(ripples::sources(0).len(), 1);
    let s = all[0];
    let mut rng = Lcg::new(313);
    for _ in 0..10_000 {
        let p = rng.point(10.0);
        let r = (p - s.center).dot(p - s.center).sqrt();
        let want = 0.5 * (1.0 + libm::sin(TAU * (r * 2.0 + 0.25)));
        assert!((ripples::ripples(p, 2.0, 0.25, 1) - want).abs() < 1e-12);
        let v = ripples::ripples(p, 3.0, 0.0, 10);
        assert!((0.0..=1.0).contains(&v));
        let w = ripples::waves(p, 1.0, 0.0, 10);
        assert!((w - 0.5).abs() <= ripples::waves_reach(10));
    }
    eprintln!(
        "waves with 10 sources reach ±{:.3}",
        ripples::waves_reach(10)
    );
}
