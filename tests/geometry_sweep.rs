//! Issue 38's swept shapes (`sor`, `sphere_sweep` with its three splines) over 10 000 random
//! rays each, with and without a mirrored, non-uniformly scaled transform: no NaN, the hit lies
//! on the surface (checked against formulas written here, independent of the library), the
//! normal is unit and faces out, a ray leaving the hit does not meet the surface again nearby,
//! and the bounds hold every hit. Then: a sor against the lathe of the same profile where the
//! two coincide (a frustum), a linear sweep of two equal spheres against the capsule made of
//! two spheres and a cylinder, each shape as a CSG operand, and a scene of them rendering the
//! same image scaled by a transform from 10⁻⁶ to 10⁸.

mod geometry_support;
mod numerics_support;

use geometry_support::{
    Probe, Rng, axis_scale, mirrored_transform, object, random_ray_invariants, ray_at_box, world,
};
use glam::{DAffine3, DVec3};
use numerics_support::assert_same_at_scales;
use rtc::ir::{CsgOp, Shape, Spline, SweepSpline};
use rtc::num::Norm;

const RAYS: usize = 10_000;

/// A shape with an independent signed distance-like function in object space (positive
/// outside, its magnitude within a few times the distance to the surface near it).
struct Case {
    name: &'static str,
    shape: Shape,
    side: Box<dyn Fn(DVec3) -> f64>,
    aim: (DVec3, DVec3),
    size: f64,
    min_hit_share: f64,
}

/// Solves the 4×4 system `m·x = b` by Gaussian elimination with partial pivoting.
fn solve4(mut m: [[f64; 4]; 4], mut b: [f64; 4]) -> [f64; 4] {
    for col in 0..4 {
        let piv = (col..4)
            .max_by(|&i, &j| m[i][col].abs().total_cmp(&m[j][col].abs()))
            .unwrap();
        m.swap(col, piv);
        b.swap(col, piv);
        for row in col + 1..4 {
            let k = m[row][col] / m[col][col];
            let pivot = m[col];
            for (v, p) in m[row].iter_mut().zip(pivot).skip(col) {
                *v -= k * p;
            }
            b[row] -= k * b[col];
        }
    }
    let mut x = [0.0; 4];
    for row in (0..4).rev() {
        let s: f64 = (row + 1..4).map(|c| m[row][c] * x[c]).sum();
        x[row] = (b[row] - s) / m[row][row];
    }
    x
}

/// POV-Ray's sor as `Compute_Sor` builds it, in absolute heights: per segment the cubic
/// `A·y³ + B·y² + C·y + D` through the radii² with its slopes, and the segment's heights.
fn pov_sor(p: &[[f64; 2]]) -> Vec<([f64; 4], f64, f64)> {
    (0..p.len() - 3)
        .map(|i| {
            let k = [
                p[i + 1][0] * p[i + 1][0],
                p[i + 2][0] * p[i + 2][0],
                2.0 * p[i + 1][0] * (p[i + 2][0] - p[i][0]) / (p[i + 2][1] - p[i][1]),
                2.0 * p[i + 2][0] * (p[i + 3][0] - p[i + 1][0]) / (p[i + 3][1] - p[i + 1][1]),
            ];
            let (w0, w1) = (p[i + 1][1], p[i + 2][1]);
            let m = [
                [w0 * w0 * w0, w0 * w0, w0, 1.0],
                [w1 * w1 * w1, w1 * w1, w1, 1.0],
                [3.0 * w0 * w0, 2.0 * w0, 1.0, 0.0],
                [3.0 * w1 * w1, 2.0 * w1, 1.0, 0.0],
            ];
            (solve4(m, k), w0, w1)
        })
        .collect()
}

/// The signed distance-like function of a closed sor: the larger of the first-order distance
/// to the curve and the distance to the slab of its heights, negative inside.
fn sor_side(points: &[[f64; 2]]) -> impl Fn(DVec3) -> f64 + 'static {
    let segs = pov_sor(points);
    let (lo, hi) = (points[1][1], points[points.len() - 2][1]);
    move |q: DVec3| {
        let rho2 = q.x * q.x + q.z * q.z;
        let y = q.y.clamp(lo, hi);
        let (c, _, _) = segs.iter().find(|s| y <= s.2).copied().unwrap_or(segs[0]);
        let r2 = ((c[0] * y + c[1]) * y + c[2]) * y + c[3];
        let dr2 = (3.0 * c[0] * y + 2.0 * c[1]) * y + c[2];
        let curve = (rho2 - r2) / (4.0 * rho2 + dr2 * dr2).sqrt().max(1e-300);
        // The solid is the curve's inside cut by the slab between the disks.
        curve.max((lo - q.y).max(q.y - hi))
    }
}

/// `min_s |p − C(s)| − r(s)` over one cubic segment (coefficients lowest first): the signed
/// distance to the union of its spheres, by sampling then golden-section refinement.
fn sweep_segment_side(c: [DVec3; 4], r: [f64; 4], p: DVec3) -> f64 {
    let f = |s: f64| {
        let center = c[0] + s * (c[1] + s * (c[2] + s * c[3]));
        let radius = r[0] + s * (r[1] + s * (r[2] + s * r[3]));
        (p - center).norm() - radius.abs()
    };
    let n = 400;
    let mut best = (f64::INFINITY, 0.0);
    for i in 0..=n {
        let s = f64::from(i) / f64::from(n);
        let v = f(s);
        if v < best.0 {
            best = (v, s);
        }
    }
    let (mut a, mut b) = (
        (best.1 - 1.0 / f64::from(n)).max(0.0),
        (best.1 + 1.0 / f64::from(n)).min(1.0),
    );
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..80 {
        let (x1, x2) = (b - g * (b - a), a + g * (b - a));
        if f(x1) < f(x2) {
            b = x2;
        } else {
            a = x1;
        }
    }
    best.0.min(f(0.5 * (a + b)))
}

/// The segments of a sweep as POV-Ray's basis matrices give them (written out here).
fn sweep_segments(spheres: &[(DVec3, f64)], spline: SweepSpline) -> Vec<([DVec3; 4], [f64; 4])> {
    let m: [[f64; 4]; 4] = match spline {
        SweepSpline::Linear => [
            [1.0, 0.0, 0.0, 0.0],
            [-1.0, 1.0, 0.0, 0.0],
            [0.0; 4],
            [0.0; 4],
        ],
        SweepSpline::CatmullRom => [
            [0.0, 1.0, 0.0, 0.0],
            [-0.5, 0.0, 0.5, 0.0],
            [1.0, -2.5, 2.0, -0.5],
            [-0.5, 1.5, -1.5, 0.5],
        ],
        SweepSpline::BSpline => [
            [1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0, 0.0],
            [-0.5, 0.0, 0.5, 0.0],
            [0.5, -1.0, 0.5, 0.0],
            [-1.0 / 6.0, 0.5, -0.5, 1.0 / 6.0],
        ],
    };
    let width = if spline == SweepSpline::Linear { 2 } else { 4 };
    spheres
        .windows(width)
        .map(|w| {
            let mut c = [DVec3::ZERO; 4];
            let mut r = [0.0; 4];
            for i in 0..4 {
                for (j, s) in w.iter().enumerate() {
                    c[i] += m[i][j] * s.0;
                    r[i] += m[i][j] * s.1;
                }
            }
            (c, r)
        })
        .collect()
}

fn sweep_case(
    name: &'static str,
    spline: SweepSpline,
    spheres: Vec<(DVec3, f64)>,
    aim: f64,
) -> Case {
    let segs = sweep_segments(&spheres, spline);
    Case {
        name,
        shape: Shape::SphereSweep { spline, spheres },
        side: Box::new(move |q| {
            segs.iter()
                .map(|(c, r)| sweep_segment_side(*c, *r, q))
                .fold(f64::INFINITY, f64::min)
        }),
        aim: (DVec3::splat(-aim), DVec3::splat(aim)),
        size: 2.0 * aim,
        min_hit_share: 0.2,
    }
}

fn cases() -> Vec<Case> {
    let vase = vec![
        [0.3, -1.2],
        [0.8, -1.0],
        [0.4, -0.4],
        [0.6, 0.3],
        [0.9, 0.9],
        [0.5, 1.3],
    ];
    let wavy = vec![
        (DVec3::new(-1.5, 0.0, 0.0), 0.2),
        (DVec3::new(-1.0, 0.5, 0.3), 0.3),
        (DVec3::new(-0.2, -0.4, -0.2), 0.25),
        (DVec3::new(0.5, 0.6, 0.1), 0.45),
        (DVec3::new(1.1, -0.3, 0.4), 0.2),
        (DVec3::new(1.6, 0.2, 0.0), 0.3),
    ];
    vec![
        Case {
            name: "sor vase",
            shape: Shape::Sor {
                points: vase.clone(),
                open: false,
            },
            side: Box::new(sor_side(&vase)),
            aim: (DVec3::new(-0.9, -1.0, -0.9), DVec3::new(0.9, 0.9, 0.9)),
            size: 2.0,
            min_hit_share: 0.3,
        },
        sweep_case("linear sweep", SweepSpline::Linear, wavy.clone(), 1.5),
        sweep_case(
            "catmull_rom sweep",
            SweepSpline::CatmullRom,
            wavy.clone(),
            1.2,
        ),
        sweep_case("b_spline sweep", SweepSpline::BSpline, wavy, 1.2),
    ]
}

fn check(case: &Case, xf: DAffine3, seed: u64) {
    let w = world(vec![object(case.shape.clone(), xf)]);
    let dist = |q: DVec3| (case.side)(q).abs();
    let probe = Probe {
        name: case.name,
        xf,
        world_scale: case.size * axis_scale(&xf),
        aim: case.aim,
        rays: RAYS,
        min_hit_share: case.min_hit_share,
        dist: &dist,
        tolerance: 1e-8 * case.size,
        side: &*case.side,
    };
    random_ray_invariants(&w, &probe, seed);
}

#[test]
fn every_sweep_shape_keeps_its_invariants() {
    for (k, case) in cases().iter().enumerate() {
        check(case, DAffine3::IDENTITY, 5000 + k as u64);
    }
}

#[test]
fn every_sweep_shape_keeps_its_invariants_when_mirrored_and_skewed() {
    for (k, case) in cases().iter().enumerate() {
        check(case, mirrored_transform(), 6000 + k as u64);
    }
}

/// Random rays at both worlds give the same first hits (t and normal).
fn same_hits(a: &rtc::geometry::World, b: &rtc::geometry::World, aim: f64, seed: u64, what: &str) {
    let mut rng = Rng(seed);
    let mut hits = 0;
    for i in 0..RAYS {
        let ray = ray_at_box(&mut rng, DVec3::splat(-aim), DVec3::splat(aim));
        let (ha, hb) = (
            a.intersect(&ray, 0.0, f64::INFINITY),
            b.intersect(&ray, 0.0, f64::INFINITY),
        );
        match (ha, hb) {
            (None, None) => {}
            (Some(x), Some(y)) => {
                hits += 1;
                assert!(
                    (x.t - y.t).abs() < 1e-9,
                    "{what} ray {i}: t {} vs {}",
                    x.t,
                    y.t
                );
                // At an edge (a cap's rim) the two may pick either face.
                let rim = (x.normal - y.normal).norm() > 1e-6;
                assert!(
                    !rim || x.normal.dot(y.normal) > -0.5,
                    "{what} ray {i}: normals {} vs {}",
                    x.normal,
                    y.normal
                );
            }
            (x, y) => {
                let t = x.or(y).map(|h| h.point).unwrap();
                panic!(
                    "{what} ray {i}: one hit at {t} ({:?} vs {:?})",
                    x.map(|h| h.t),
                    y.map(|h| h.t)
                );
            }
        }
    }
    assert!(hits > RAYS / 5, "{what}: only {hits} hits");
}

#[test]
fn a_sor_of_a_straight_profile_is_the_lathe_frustum() {
    // Radii on the line r = 1 − 0.4·y: POV-Ray's slopes are then exact, and radius² — a
    // quadratic — is what the cubic reproduces: the sor is the frustum from y = 0 to 1.
    let r = |y: f64| 1.0 - 0.4 * y;
    let points: Vec<[f64; 2]> = [-1.0, 0.0, 0.5, 1.0, 2.0]
        .iter()
        .map(|&y| [r(y), y])
        .collect();
    let sor = world(vec![object(
        Shape::Sor {
            points,
            open: false,
        },
        DAffine3::IDENTITY,
    )]);
    let lathe = world(vec![object(
        Shape::Lathe {
            points: vec![[0.0, 0.0], [1.0, 0.0], [0.6, 1.0], [0.0, 1.0]],
            spline: Spline::Linear,
        },
        DAffine3::IDENTITY,
    )]);
    same_hits(&sor, &lathe, 1.0, 7001, "sor vs lathe");
}

#[test]
fn a_linear_sweep_of_two_equal_spheres_is_a_capsule() {
    let (a, b, r) = (
        DVec3::new(-0.8, -0.3, 0.2),
        DVec3::new(0.7, 0.5, -0.4),
        0.35,
    );
    let sweep = world(vec![object(
        Shape::SphereSweep {
            spline: SweepSpline::Linear,
            spheres: vec![(a, r), (b, r)],
        },
        DAffine3::IDENTITY,
    )]);
    let capsule = world(vec![
        object(
            Shape::Sphere {
                center: a,
                radius: r,
            },
            DAffine3::IDENTITY,
        ),
        object(
            Shape::Sphere {
                center: b,
                radius: r,
            },
            DAffine3::IDENTITY,
        ),
        object(
            Shape::Cylinder {
                base: a,
                top: b,
                radius: r,
                capped: true,
            },
            DAffine3::IDENTITY,
        ),
    ]);
    same_hits(&sweep, &capsule, 1.0, 7002, "sweep vs capsule");
}

#[test]
fn each_shape_is_a_csg_operand() {
    // Intersected with a box that holds it whole, each shape is itself: its crossings pair up.
    for (k, case) in cases().iter().enumerate() {
        let alone = world(vec![object(case.shape.clone(), DAffine3::IDENTITY)]);
        let cut = world(vec![object(
            Shape::Csg {
                op: CsgOp::Intersection,
                children: vec![
                    object(case.shape.clone(), DAffine3::IDENTITY),
                    object(
                        Shape::Box {
                            min: DVec3::splat(-5.0),
                            max: DVec3::splat(5.0),
                        },
                        DAffine3::IDENTITY,
                    ),
                ],
            },
            DAffine3::IDENTITY,
        )]);
        same_hits(&alone, &cut, case.size / 2.0, 7100 + k as u64, case.name);
    }
}

/// The shapes of this file in one scene at scale `s` (objects scaled by a transform, camera
/// and light moved with them).
fn scene(s: f64) -> String {
    let v = |x: f64, y: f64, z: f64| format!("[{:e}, {:e}, {:e}]", x * s, y * s, z * s);
    format!(
        "rtc 1\n\
         camera {{ eye: {}, center: {}, fov: 40deg, resolution: [120, 90] }}\n\
         point_light {{ position: {} }}\n\
         sor(points: [[0.3, -1.2], [0.8, -1.0], [0.4, -0.4], [0.6, 0.3], [0.9, 0.9], [0.5, 1.3]]).rotate(x: 20deg).translate([-1.6, 0, 0]).scale({s:e})\n\
         sphere_sweep(points: [[-1.5, 0, 0], [-0.5, 0.5, 0.3], [0.5, -0.4, 0], [1.5, 0.2, 0]], radii: [0.2, 0.3, 0.25, 0.35]).translate([0, 1.4, 0]).scale({s:e})\n\
         sphere_sweep(points: [[-1.5, 0, 0], [-1, 0.5, 0.3], [-0.2, -0.4, -0.2], [0.5, 0.6, 0.1], [1.1, -0.3, 0.4], [1.6, 0.2, 0]], radii: [0.2, 0.3, 0.25, 0.45, 0.2, 0.3], spline: \"catmull_rom\").translate([0.6, 0, 0]).scale({s:e})\n\
         sphere_sweep(points: [[-1.5, 0, 0], [-1, 0.5, 0.3], [-0.2, -0.4, -0.2], [0.5, 0.6, 0.1], [1.1, -0.3, 0.4], [1.6, 0.2, 0]], radii: [0.2, 0.3, 0.25, 0.45, 0.2, 0.3], spline: \"b_spline\").translate([0, -1.4, 0]).scale({s:e})\n",
        v(0.5, 1.0, 7.0),
        v(0.0, 0.0, 0.0),
        v(4.0, 6.0, 5.0),
    )
}

#[test]
fn the_sweep_scene_renders_the_same_at_every_scale() {
    assert_same_at_scales(&[1e-6, 1e-3, 3.7, 1e3, 1e6, 1e8], scene);
}
