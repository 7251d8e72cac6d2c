//! Grazing rays on the quartic surfaces: rays ever closer to tangent must still hit, at the
//! analytic distance, and rays just outside must miss (no holes, no speckle).

mod geometry_support;

use geometry_support::{object, world};
use glam::{DAffine3, DVec3};
use rtc::geometry::{Ray, World};
use rtc::ir::{BlobComponent, Shape};
use rtc::num::Norm;

/// √(a² − b²) without cancellation.
fn leg(a: f64, b: f64) -> f64 {
    ((a - b) * (a + b)).max(0.0).sqrt()
}

/// For a family of offsets approaching tangency: hits at the expected distance, and misses
/// just past it.
fn sweep(
    w: &World,
    what: &str,
    ray_at: impl Fn(f64) -> Ray,
    tangent: f64,
    expected_t: impl Fn(f64) -> f64,
) {
    for k in 1..=13 {
        let off = tangent * (1.0 - 10f64.powi(-k));
        let ray = ray_at(off);
        let h = w
            .intersect(&ray, 0.0, f64::INFINITY)
            .unwrap_or_else(|| panic!("{what}: offset 1−1e-{k} of tangency missed"));
        let want = expected_t(off);
        // Near-double roots are ill-conditioned: the error grows like √ε; 1e-6 still
        // separates a polished root from a wrong or speckled one.
        assert!(
            (h.t - want).abs() < 1e-6,
            "{what}: 1−1e-{k}: t = {} want {want}",
            h.t
        );
        assert!((h.normal.norm() - 1.0).abs() < 1e-12);
        let outside = ray_at(tangent * (1.0 + 10f64.powi(-k)));
        assert!(
            w.intersect(&outside, 0.0, f64::INFINITY).is_none(),
            "{what}: offset 1+1e-{k} (outside) hit"
        );
    }
    // A dense sweep across tangency: hit exactly when inside, away from a 1e-12 band.
    let n = 4001;
    for i in 0..n {
        let rel = -1e-6 + 2e-6 * i as f64 / (n - 1) as f64;
        if rel.abs() < 1e-12 {
            continue;
        }
        let hit = w
            .intersect(&ray_at(tangent * (1.0 + rel)), 0.0, f64::INFINITY)
            .is_some();
        assert_eq!(hit, rel < 0.0, "{what}: dense sweep at 1{rel:+e}");
    }
}

#[test]
fn torus_grazing_rays_hit_at_the_analytic_distance() {
    let (big, small) = (2.0, 0.5);
    let w = world(vec![object(
        Shape::Torus {
            center: DVec3::ZERO,
            major_radius: big,
            minor_radius: small,
            spindle: Default::default(),
        },
        DAffine3::IDENTITY,
    )]);
    // Along +X at height y: tangent to the top of the tube at y = r.
    sweep(
        &w,
        "torus top",
        |y| Ray::new(DVec3::new(-10.0, y, 0.0), DVec3::X),
        small,
        |y| 10.0 - (big + leg(small, y)),
    );
    // Along +Z at x: tangent to the outer equator at x = R + r.
    sweep(
        &w,
        "torus outer silhouette",
        |x| Ray::new(DVec3::new(x, 0.0, -10.0), DVec3::Z),
        big + small,
        |x| 10.0 - leg(big + small, x),
    );
    // Along +Z at x just inside the hole (x < R − r): through the tube, out into the hole
    // and back in (the grazing pair ∓√((R − r)² − x²)), out again.
    let inner = big - small;
    for k in 1..=12 {
        let x = inner * (1.0 - 10f64.powi(-k));
        let ray = Ray::new(DVec3::new(x, 0.0, -10.0), DVec3::Z);
        let mut ts = Vec::new();
        let mut from = 0.0;
        while let Some(h) = w.intersect(&ray, from, f64::INFINITY) {
            ts.push(h.t);
            from = h.t;
            assert!(ts.len() <= 4);
        }
        let (o, i) = (leg(big + small, x), leg(inner, x));
        let want = [10.0 - o, 10.0 - i, 10.0 + i, 10.0 + o];
        assert_eq!(ts.len(), 4, "inner graze 1−1e-{k}: {ts:?}");
        for (got, want) in ts.iter().zip(want) {
            assert!(
                (got - want).abs() < 1e-6,
                "inner graze 1−1e-{k}: {ts:?} vs {want}"
            );
        }
    }
}

#[test]
fn torus_rotated_and_far_away_stays_accurate() {
    // A torus a million units away: the solver works from the bounding-box entry, so the
    // hit still lies on the surface to ~1e-9 of its size.
    let c = DVec3::new(1e6, -2e6, 3e5);
    let w = world(vec![object(
        Shape::Torus {
            center: DVec3::ZERO,
            major_radius: 2.0,
            minor_radius: 0.5,
            spindle: Default::default(),
        },
        DAffine3::from_rotation_translation(glam::DQuat::from_rotation_x(0.4), c),
    )]);
    let inv = DAffine3::from_rotation_translation(glam::DQuat::from_rotation_x(0.4), c).inverse();
    let origin = DVec3::ZERO;
    let mut hits = 0;
    for i in 0..200 {
        let target = c + DVec3::new(
            (i % 20) as f64 * 0.25 - 2.5,
            (i / 20) as f64 * 0.5 - 2.5,
            0.1,
        );
        let ray = Ray::new(origin, (target - origin).unit());
        if let Some(h) = w.intersect(&ray, 0.0, f64::INFINITY) {
            hits += 1;
            let q = inv.transform_point3(h.point);
            let d =
                (glam::DVec2::new(glam::DVec2::new(q.x, q.z).norm() - 2.0, q.y).norm() - 0.5).abs();
            // Coordinates near 2e6 carry ~4e-10 of rounding each.
            assert!(d < 1e-8, "ray {i}: {d:e} off the surface");
        }
    }
    assert!(hits > 50, "{hits}");
}

#[test]
fn blob_grazing_rays_hit_at_the_analytic_distance() {
    // One component: the surface is a sphere of radius ρ = R·√(1 − √(T/s)).
    let (r, s, t): (f64, f64, f64) = (1.5, 1.0, 0.25);
    let rho = r * (1.0 - (t / s).sqrt()).sqrt();
    let w = world(vec![object(
        Shape::Blob {
            components: vec![BlobComponent {
                center: DVec3::ZERO,
                radius: r,
                strength: s,
                end: None,
            }],
            threshold: t,
        },
        DAffine3::IDENTITY,
    )]);
    sweep(
        &w,
        "single blob",
        |y| Ray::new(DVec3::new(-10.0, y, 0.0), DVec3::X),
        rho,
        |y| 10.0 - leg(rho, y),
    );
    // Two components at ±d: in the plane x = 0 the surface is the circle y² + z² = y_n²,
    // y_n² = R²(1 − √(T/2s)) − d²; a ray along z at height y grazes the neck (a saddle).
    let d = 0.6;
    let neck = (r * r * (1.0 - (t / (2.0 * s)).sqrt()) - d * d).sqrt();
    let w2 = world(vec![object(
        Shape::Blob {
            components: vec![
                BlobComponent {
                    center: DVec3::new(-d, 0.0, 0.0),
                    radius: r,
                    strength: s,
                    end: None,
                },
                BlobComponent {
                    center: DVec3::new(d, 0.0, 0.0),
                    radius: r,
                    strength: s,
                    end: None,
                },
            ],
            threshold: t,
        },
        DAffine3::IDENTITY,
    )]);
    for k in 1..=12 {
        let y = neck * (1.0 - 10f64.powi(-k));
        let h = w2
            .intersect(
                &Ray::new(DVec3::new(0.0, y, -10.0), DVec3::Z),
                0.0,
                f64::INFINITY,
            )
            .unwrap_or_else(|| panic!("neck graze 1−1e-{k} missed"));
        let want = 10.0 - leg(neck, y);
        assert!(
            (h.t - want).abs() < 1e-6,
            "neck 1−1e-{k}: {} vs {want}",
            h.t
        );
    }
}
