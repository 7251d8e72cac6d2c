//! Height fields (issue 38) over 10 000 random rays, with and without a mirrored, skewed
//! transform: no NaN, the hit lies on the grid's triangles (interpolated here, independently of
//! the library, by POV-Ray's split of a cell), the normal is unit and faces out, a ray leaving
//! the hit does not meet the surface again nearby, the bounds hold every hit; the same for a
//! CSG intersection of a height field and a sphere (the solid's sides, bottom and water level).
//! A height field hits exactly where the same grid built as triangles does; smooth normals
//! follow the terrain's own normals; a scene renders the same scaled from 10⁻⁶ to 10⁸.

mod geometry_support;
mod numerics_support;

use std::sync::Arc;

use geometry_support::{
    Probe, Rng, axis_scale, mirrored_transform, object, random_ray_invariants, ray_at_box, world,
};
use glam::{DAffine3, DVec3};
use numerics_support::assert_same_at_scales;
use rtc::geometry::Ray;
use rtc::ir::{CsgOp, HeightGrid, Object, Shape};
use rtc::num::Norm;

const RAYS: usize = 10_000;

/// A grid of `nx × nz` samples of `f(x, z)`, row by row from z = 0.
fn grid(nx: usize, nz: usize, f: impl Fn(f64, f64) -> f64) -> Arc<HeightGrid> {
    let mut h = Vec::new();
    for j in 0..nz {
        for i in 0..nx {
            h.push(f(i as f64 / (nx - 1) as f64, j as f64 / (nz - 1) as f64) as f32);
        }
    }
    Arc::new(HeightGrid {
        nx,
        nz,
        heights: h.into(),
    })
}

fn field(g: &Arc<HeightGrid>, smooth: bool, water_level: f64) -> Shape {
    Shape::HeightField {
        image: None,
        heights: g.clone(),
        smooth,
        water_level,
    }
}

/// The terrain's height at (x, z) in the square: the triangle under it, split as POV-Ray
/// splits a cell (the diagonal from (i+1, j) to (i, j+1)), heights raised to `floor`.
fn surface(g: &HeightGrid, x: f64, z: f64, floor: f64) -> f64 {
    let (sx, sz) = ((g.nx - 1) as f64, (g.nz - 1) as f64);
    let (gx, gz) = ((x * sx).clamp(0.0, sx), (z * sz).clamp(0.0, sz));
    let (i, j) = (
        (gx.floor() as usize).min(g.nx - 2),
        (gz.floor() as usize).min(g.nz - 2),
    );
    let (fx, fz) = (gx - i as f64, gz - j as f64);
    let h = |a: usize, b: usize| f64::from(g.heights[b * g.nx + a]).max(floor);
    if fx + fz <= 1.0 {
        h(i, j) + (h(i + 1, j) - h(i, j)) * fx + (h(i, j + 1) - h(i, j)) * fz
    } else {
        let h11 = h(i + 1, j + 1);
        h11 + (h(i, j + 1) - h11) * (1.0 - fx) + (h(i + 1, j) - h11) * (1.0 - fz)
    }
}

/// The solid's signed side function (positive outside; a box-like max of its faces).
fn solid_side(g: &HeightGrid, water: f64, q: DVec3) -> f64 {
    let top = q.y - surface(g, q.x, q.z, water);
    top.max(-q.y)
        .max(-q.x)
        .max(q.x - 1.0)
        .max(-q.z)
        .max(q.z - 1.0)
}

struct Case {
    name: &'static str,
    objects: Vec<(Shape, DAffine3)>,
    side: Box<dyn Fn(DVec3) -> f64>,
    /// An upper bound of the distance to the surface, where that is small.
    dist: Box<dyn Fn(DVec3) -> f64>,
    aim: (DVec3, DVec3),
    min_hit_share: f64,
}

fn terrain() -> Arc<HeightGrid> {
    grid(41, 29, |x, z| {
        0.3 + 0.25 * libm::sin(5.0 * x) * libm::cos(4.0 * z) + 0.2 * x * z
    })
}

fn cases() -> Vec<Case> {
    let g = terrain();
    let mut v = Vec::new();
    for (name, smooth) in [("terrain", false), ("smooth terrain", true)] {
        let (g1, g2) = (g.clone(), g.clone());
        v.push(Case {
            name,
            objects: vec![(field(&g, smooth, 0.0), DAffine3::IDENTITY)],
            side: Box::new(move |q| {
                let inside = (0.0..=1.0).contains(&q.x) && (0.0..=1.0).contains(&q.z);
                if inside {
                    q.y - surface(&g1, q.x, q.z, 0.0)
                } else {
                    1.0
                }
            }),
            // The vertical distance bounds the distance to the surface.
            dist: Box::new(move |q| (q.y - surface(&g2, q.x, q.z, 0.0)).abs()),
            aim: (DVec3::ZERO, DVec3::new(1.0, 0.6, 1.0)),
            min_hit_share: 0.3,
        });
    }
    {
        // The solid cut by a sphere: its sides and bottom show, the water level raises it.
        let (g1, g2) = (g.clone(), g.clone());
        let (c, r) = (DVec3::new(0.5, 0.2, 0.5), 0.55);
        let sphere = move |q: DVec3| (q - c).norm() - r;
        let csg = Shape::Csg {
            op: CsgOp::Intersection,
            children: vec![
                object(field(&g, false, 0.25), DAffine3::IDENTITY),
                object(
                    Shape::Sphere {
                        center: c,
                        radius: r,
                    },
                    DAffine3::IDENTITY,
                ),
            ],
        };
        v.push(Case {
            name: "height field ∩ sphere",
            objects: vec![(csg, DAffine3::IDENTITY)],
            side: Box::new(move |q| solid_side(&g1, 0.25, q).max(sphere(q))),
            dist: Box::new(move |q| solid_side(&g2, 0.25, q).abs().min(sphere(q).abs())),
            aim: (DVec3::ZERO, DVec3::new(1.0, 0.6, 1.0)),
            min_hit_share: 0.3,
        });
    }
    v
}

fn check(case: &Case, xf: DAffine3, seed: u64) {
    let objs: Vec<Object> = case
        .objects
        .iter()
        .map(|(s, m)| object(s.clone(), xf * *m))
        .collect();
    let w = world(objs);
    let probe = Probe {
        name: case.name,
        xf,
        world_scale: axis_scale(&xf),
        aim: case.aim,
        rays: RAYS,
        min_hit_share: case.min_hit_share,
        dist: &*case.dist,
        tolerance: 1e-8,
        side: &*case.side,
    };
    random_ray_invariants(&w, &probe, seed);
}

#[test]
fn height_fields_keep_their_invariants() {
    for (k, case) in cases().iter().enumerate() {
        check(case, DAffine3::IDENTITY, 5000 + k as u64);
    }
}

#[test]
fn height_fields_keep_their_invariants_when_mirrored_and_skewed() {
    for (k, case) in cases().iter().enumerate() {
        check(case, mirrored_transform(), 6000 + k as u64);
    }
}

/// The grid's cells as separate triangles, corners computed as the field computes them.
fn as_triangles(g: &HeightGrid) -> Vec<Object> {
    let p = |i: usize, j: usize| {
        DVec3::new(
            i as f64 / (g.nx - 1) as f64,
            f64::from(g.heights[j * g.nx + i]),
            j as f64 / (g.nz - 1) as f64,
        )
    };
    let mut out = Vec::new();
    for j in 0..g.nz - 1 {
        for i in 0..g.nx - 1 {
            for vertices in [
                [p(i, j), p(i, j + 1), p(i + 1, j)],
                [p(i + 1, j + 1), p(i + 1, j), p(i, j + 1)],
            ] {
                out.push(object(Shape::Triangle { vertices }, DAffine3::IDENTITY));
            }
        }
    }
    out
}

#[test]
fn a_height_field_hits_where_its_triangles_do() {
    let g = grid(13, 9, |x, z| {
        (0.5 + 0.45 * libm::sin(7.0 * x + 1.0) * libm::sin(5.0 * z)).clamp(0.0, 1.0)
    });
    let hf = world(vec![object(field(&g, false, 0.0), DAffine3::IDENTITY)]);
    let tris = world(as_triangles(&g));
    let mut rng = Rng(77);
    let (mut both, mut near_edge) = (0, 0);
    for i in 0..RAYS {
        let ray = ray_at_box(&mut rng, DVec3::ZERO, DVec3::ONE);
        let a = hf.intersect(&ray, 0.0, f64::INFINITY);
        let b = tris.intersect(&ray, 0.0, f64::INFINITY);
        match (a, b) {
            (None, None) => {}
            (Some(a), Some(b)) => {
                both += 1;
                assert_eq!(a.t.to_bits(), b.t.to_bits(), "ray {i}: {ray:?}");
                if a.normal != b.normal {
                    // Only where the ray meets an edge two triangles share: either may answer.
                    near_edge += 1;
                    assert!(
                        (a.normal - b.normal).norm() < 1.0 && near_edge < 10,
                        "ray {i}: normals {} and {}",
                        a.normal,
                        b.normal
                    );
                }
            }
            (a, b) => panic!("ray {i}: {ray:?} field {a:?} triangles {b:?}"),
        }
    }
    assert!(both > RAYS / 4, "only {both} hits");
}

#[test]
fn smooth_normals_follow_the_terrain() {
    // A paraboloid: its true normal is (−2a·x', 1, −2a·z') normalised.
    let a = 0.6;
    let h = move |x: f64, z: f64| 0.1 + a * ((x - 0.5).powi(2) + (z - 0.5).powi(2));
    let g = grid(65, 65, h);
    let truth = |p: DVec3| DVec3::new(-2.0 * a * (p.x - 0.5), 1.0, -2.0 * a * (p.z - 0.5)).unit();
    let mut err = [0.0f64; 2];
    let mut worst_smooth: f64 = 0.0;
    let mut n = 0;
    for (k, smooth) in [false, true].into_iter().enumerate() {
        let w = world(vec![object(field(&g, smooth, 0.0), DAffine3::IDENTITY)]);
        let mut rng = Rng(99);
        n = 0;
        for _ in 0..2000 {
            let target = DVec3::new(rng.range(0.05, 0.95), 0.0, rng.range(0.05, 0.95));
            let target = DVec3::new(target.x, h(target.x, target.z), target.z);
            let ray = Ray::new(
                target + DVec3::new(0.1, 2.0, -0.2),
                DVec3::new(-0.1, -2.0, 0.2).unit(),
            );
            let Some(hit) = w.intersect(&ray, 0.0, f64::INFINITY) else {
                continue;
            };
            n += 1;
            let e = hit.normal.angle_between(truth(hit.point));
            err[k] += e;
            if smooth {
                worst_smooth = worst_smooth.max(e);
            }
        }
    }
    let (flat, smooth) = (err[0] / n as f64, err[1] / n as f64);
    assert!(n > 1900);
    assert!(
        smooth < flat / 5.0 && worst_smooth < 2e-3,
        "mean angle flat {flat:e}, smooth {smooth:e}, worst smooth {worst_smooth:e}"
    );
}

/// Height fields (from a function, from numbers, smooth, with a water level, in CSG) in one
/// scene at scale `s`.
fn scene(s: f64) -> String {
    let v = |x: f64, y: f64, z: f64| format!("[{:e}, {:e}, {:e}]", x * s, y * s, z * s);
    format!(
        "rtc 1\n\
         camera {{ eye: {}, center: {}, fov: 40deg, resolution: [120, 90] }}\n\
         point_light {{ position: {} }}\n\
         height_field(f: fn(p) {{ 0.4 + 0.3 * sin(7rad * p.x) * cos(5rad * p.z) }}, resolution: [40, 30], smooth: true).translate([-1.2, -0.5, -0.5]).scale(1.5).scale({s:e})\n\
         height_field(heights: [[0, 0.2, 0.1], [0.5, 1, 0.3], [0.2, 0.6, 0.9]], water_level: 0.15).translate([0.3, -0.4, -0.3]).scale({s:e})\n\
         difference(box(min: [0.1, -1, 0.1], max: [0.9, 0.3, 0.9]), [height_field(f: fn(p) {{ 0.5 + 0.4 * sin(9rad * p.x + 3rad * p.z) }}, resolution: [30, 30])]).rotate(y: 30deg).translate([0, 0.8, -0.5]).scale({s:e})\n",
        v(0.5, 2.5, 5.0),
        v(0.0, 0.0, 0.0),
        v(4.0, 6.0, 5.0),
    )
}

#[test]
fn the_height_field_scene_renders_the_same_at_every_scale() {
    assert_same_at_scales(&[1e-6, 1e-3, 3.7, 1e3, 1e6, 1e8], scene);
}

/// Rays straight down and up (their shadow on the ground is one point): on the terrain from
/// above, on the bottom from below, alone and as a CSG operand (whose crossings span the
/// whole line).
#[test]
fn rays_straight_down_and_up_meet_the_top_and_the_bottom() {
    let g = terrain();
    let plain = world(vec![object(field(&g, false, 0.0), DAffine3::IDENTITY)]);
    let csg = world(vec![object(
        Shape::Csg {
            op: CsgOp::Intersection,
            children: vec![
                object(field(&g, false, 0.0), DAffine3::IDENTITY),
                object(
                    Shape::Box {
                        min: DVec3::splat(-1.0),
                        max: DVec3::splat(2.0),
                    },
                    DAffine3::IDENTITY,
                ),
            ],
        },
        DAffine3::IDENTITY,
    )]);
    let mut rng = Rng(11);
    for _ in 0..500 {
        let (x, z) = (rng.range(0.0, 1.0), rng.range(0.0, 1.0));
        let top = surface(&g, x, z, 0.0);
        let down = Ray::new(DVec3::new(x, 5.0, z), -DVec3::Y);
        for w in [&plain, &csg] {
            let h = w
                .intersect(&down, 0.0, f64::INFINITY)
                .expect("hits from above");
            assert!(
                (h.point.y - top).abs() < 1e-12 && h.normal.y > 0.0,
                "{x}, {z}"
            );
        }
        // From below: the plain field shows no bottom (as POV-Ray's); the solid does.
        let up = Ray::new(DVec3::new(x, -5.0, z), DVec3::Y);
        let h = plain
            .intersect(&up, 0.0, f64::INFINITY)
            .expect("the top from below");
        assert!((h.point.y - top).abs() < 1e-12, "{x}, {z}");
        let h = csg.intersect(&up, 0.0, f64::INFINITY).expect("the bottom");
        assert!(h.point.y.abs() < 1e-12 && h.normal == -DVec3::Y, "{x}, {z}");
    }
}
