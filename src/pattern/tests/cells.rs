//! Worley noise: F1 ≤ F2, zero at feature points, the pruned search equal to a brute-force
//! one, determinism by seed.

use glam::DVec3;

use super::{Lcg, moments};
use crate::pattern::cells::{Nearest, feature, worley};

/// F1 and F2 over the 9×9×9 block of cells around the point: every cell the search could ever
/// need (F2 ≤ 2√3 < 4 from the 3×3×3 block alone).
fn brute_force(p: DVec3, seed: u32) -> Nearest {
    let c = p.floor();
    let mut d = Vec::with_capacity(729);
    for dz in -4..=4 {
        for dy in -4..=4 {
            for dx in -4..=4 {
                let cell = [c.x as i64 + dx, c.y as i64 + dy, c.z as i64 + dz];
                let v = feature(cell, seed) - p;
                d.push(v.dot(v));
            }
        }
    }
    d.sort_by(f64::total_cmp);
    Nearest {
        f1: d[0].sqrt(),
        f2: d[1].sqrt(),
    }
}

/// The search's F1 and F2 are the brute force's, to the bit, on random points and on points
/// near cell corners and edges (where the second nearest is most often two cells away); some
/// of the points need a shell beyond the 3×3×3 block.
#[test]
fn the_search_is_exact() {
    let mut rng = Lcg::new(59);
    let (mut beyond, mut beyond_random) = (0, 0);
    for i in 0..20_000 {
        let mut p = rng.point(1000.0);
        if i % 2 == 0 {
            // Snap two coordinates close to a cell edge.
            p.x = p.x.round() + 1e-3 * (rng.next() - 0.5);
            p.y = p.y.round() + 1e-3 * (rng.next() - 0.5);
        }
        let got = worley(p, 5);
        assert_eq!(got, brute_force(p, 5), "at {p}");
        let f = p - p.floor();
        let margin = f.min(DVec3::ONE - f).min_element();
        if got.f2 > 1.0 + margin {
            beyond += 1;
            beyond_random += i % 2;
        }
    }
    eprintln!(
        "{beyond} of 20 000 points needed a shell beyond the 3×3×3 block \
         ({beyond_random} of the 10 000 uniform ones)"
    );
    assert!(
        beyond > 100,
        "only {beyond} points exercised the outer shells"
    );
}

/// F1 ≤ F2 everywhere, F1 = 0 at each feature point (which lies in its own cell), and the
/// distances' means (F1 ≈ 0.52, F2 − F1 ≈ 0.20 for one point per unit cube).
#[test]
fn f1_is_at_most_f2_and_vanishes_at_feature_points() {
    let mut rng = Lcg::new(61);
    for _ in 0..50_000 {
        let p = rng.point(500.0);
        let d = worley(p, 2);
        assert!(0.0 <= d.f1 && d.f1 <= d.f2, "{d:?} at {p}");
        let cell = [p.x.floor() as i64, p.y.floor() as i64, p.z.floor() as i64];
        let q = feature(cell, 2);
        assert_eq!(q.floor(), p.floor(), "feature point {q} outside its cell");
        let at = worley(q, 2);
        assert_eq!(at.f1, 0.0, "F1 at the feature point {q}");
        assert!(at.f2 > 0.0);
    }
    let (f1, _) = moments(100_000, 500.0, 67, |p| worley(p, 0).f1);
    let (edge, _) = moments(100_000, 500.0, 67, |p| {
        let d = worley(p, 0);
        d.f2 - d.f1
    });
    eprintln!("mean F1 {f1:.4}, mean F2 − F1 {edge:.4}");
    assert!((f1 - 0.52).abs() < 0.01 && (edge - 0.20).abs() < 0.01);
}

/// The same seed gives the same points; another seed moves nearly all of them.
#[test]
fn feature_points_are_determined_by_the_seed() {
    let mut rng = Lcg::new(71);
    let mut moved = 0;
    for _ in 0..10_000 {
        let p = rng.point(1e5);
        let cell = [p.x as i64, p.y as i64, p.z as i64];
        assert_eq!(feature(cell, 8), feature(cell, 8));
        assert_eq!(worley(p, 8), worley(p, 8));
        if feature(cell, 8) != feature(cell, 9) {
            moved += 1;
        }
    }
    assert!(moved > 9_990, "{moved}");
}
