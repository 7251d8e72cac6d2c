//! Isosurfaces (issue 38) over 10 000 random rays each, with and without a mirrored,
//! non-uniformly scaled transform: no NaN, the hit lies on the surface (by formulas written
//! here), the normal is unit and faces out, a ray leaving the hit does not meet the surface
//! again nearby, the bounds hold every hit. A sphere and a torus written as functions meet
//! rays where the analytic `sphere` and `torus` do and draw the same masks, alone and in CSG;
//! a scene of them renders the same scaled from 10⁻⁶ to 10⁸; the render reports a
//! `max_gradient` that is too small (and only then), and a search that runs out of
//! evaluations.

mod geometry_support;
mod numerics_support;

use std::path::Path;

use geometry_support::{
    Probe, Rng, axis_scale, mirrored_transform, object, random_ray_invariants, ray_at_box, world,
};
use glam::{DAffine3, DVec3};
use numerics_support::{assert_same_at_scales, differing_by, render_rtc, share};
use rtc::diag::Diagnostics;
use rtc::eval::{EvalOptions, load_source};
use rtc::ir::{Scene, Shape};
use rtc::num::Norm;
use rtc::source::SourceMap;

const RAYS: usize = 10_000;

/// The scene of `src` (after the header) and what evaluating it said.
fn load(src: &str) -> (Option<Scene>, Diagnostics) {
    let loaded = load_source(
        Path::new("test.rtc"),
        format!("rtc 1.1\n{src}"),
        &mut SourceMap::default(),
        &EvalOptions::default(),
    );
    (loaded.scene, loaded.diagnostics)
}

/// The shape of the one object `src` makes.
fn shape(src: &str) -> Shape {
    let (scene, d) = load(&format!(
        "camera {{ eye: [0, 0, 5], center: [0, 0, 0] }}\n{src}"
    ));
    let scene = scene.unwrap_or_else(|| panic!("{src}: {:?}", d.items));
    scene.objects[0].shape.clone()
}

/// The codes of `d`.
fn codes(d: &[rtc::diag::Diagnostic]) -> Vec<&'static str> {
    d.iter().map(|x| x.code).collect()
}

/// Signed distance to the box [lo, hi] (negative inside).
fn box_side(q: DVec3, lo: DVec3, hi: DVec3) -> f64 {
    let d = (lo - q).max(q - hi);
    d.max(DVec3::ZERO).norm() + d.max_element().min(0.0)
}

/// Signed distance to the torus of radii `big`, `small` about +Y.
fn torus_side(q: DVec3, big: f64, small: f64) -> f64 {
    let r = (q.x * q.x + q.z * q.z).sqrt() - big;
    (r * r + q.y * q.y).sqrt() - small
}

/// An isosurface with an independent signed function (positive outside; zero exactly on the
/// surface, and within a constant of the distance near it).
struct Case {
    name: &'static str,
    src: &'static str,
    side: fn(DVec3) -> f64,
    aim: (DVec3, DVec3),
    size: f64,
    min_hit_share: f64,
}

fn wave(q: DVec3) -> f64 {
    q.y - 0.3 * (3.0 * q.x).sin() * (2.0 * q.z).cos()
}

fn cases() -> Vec<Case> {
    vec![
        Case {
            name: "sphere function",
            src: "isosurface(f: fn(p) { length(p) - 0.8 })",
            side: |q| q.norm() - 0.8,
            aim: (DVec3::splat(-0.8), DVec3::splat(0.8)),
            size: 2.0,
            min_hit_share: 0.4,
        },
        Case {
            name: "torus function",
            src: "isosurface(f: fn(p) { length([length([p.x, 0, p.z]) - 0.6, p.y, 0]) - 0.25 }, min: [-0.9, -0.3, -0.9], max: [0.9, 0.3, 0.9], max_gradient: 1)",
            side: |q| torus_side(q, 0.6, 0.25),
            aim: (
                DVec3::new(-0.85, -0.25, -0.85),
                DVec3::new(0.85, 0.25, 0.85),
            ),
            size: 1.8,
            min_hit_share: 0.3,
        },
        Case {
            name: "ball cut by its box",
            src: "isosurface(f: fn(p) { length(p) - 1 }, min: [-0.7, -0.7, -0.7], max: [0.7, 0.7, 0.7])",
            side: |q| (q.norm() - 1.0).max(box_side(q, DVec3::splat(-0.7), DVec3::splat(0.7))),
            aim: (DVec3::splat(-0.7), DVec3::splat(0.7)),
            size: 1.4,
            min_hit_share: 0.6,
        },
        Case {
            name: "wave closed by walls",
            src: "isosurface(f: fn(p) { p.y - 0.3 * sin(3rad * p.x) * cos(2rad * p.z) })",
            side: |q| {
                // The wave's first-order distance: f / |∇f|.
                let g = DVec3::new(
                    -0.9 * (3.0 * q.x).cos() * (2.0 * q.z).cos(),
                    1.0,
                    0.6 * (3.0 * q.x).sin() * (2.0 * q.z).sin(),
                );
                (wave(q) / g.norm()).max(box_side(q, DVec3::splat(-1.0), DVec3::splat(1.0)))
            },
            aim: (DVec3::splat(-1.0), DVec3::splat(1.0)),
            size: 2.0,
            min_hit_share: 0.5,
        },
    ]
}

fn check(case: &Case, xf: DAffine3, seed: u64) {
    let w = world(vec![object(shape(case.src), xf)]);
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
        side: &case.side,
    };
    random_ray_invariants(&w, &probe, seed);
}

#[test]
fn every_isosurface_keeps_its_invariants() {
    for (k, case) in cases().iter().enumerate() {
        check(case, DAffine3::IDENTITY, 5000 + k as u64);
    }
}

#[test]
fn every_isosurface_keeps_its_invariants_when_mirrored_and_skewed() {
    for (k, case) in cases().iter().enumerate() {
        check(case, mirrored_transform(), 6000 + k as u64);
    }
}

/// Rays at an isosurface and at the analytic shape it writes as a function: the same rays hit
/// (but for grazing ones, within `accuracy` of a tangent), at the same `t` and normal.
fn agrees_with(iso: &str, analytic: Shape, reach: f64, seed: u64) {
    let a = world(vec![object(shape(iso), DAffine3::IDENTITY)]);
    let b = world(vec![object(analytic, DAffine3::IDENTITY)]);
    let mut rng = Rng(seed);
    let (mut both, mut one) = (0, 0);
    for i in 0..RAYS {
        let ray = ray_at_box(&mut rng, DVec3::splat(-reach), DVec3::splat(reach));
        match (
            a.intersect(&ray, 0.0, f64::INFINITY),
            b.intersect(&ray, 0.0, f64::INFINITY),
        ) {
            (Some(x), Some(y)) => {
                both += 1;
                assert!((x.t - y.t).abs() < 1e-9, "ray {i}: t {} vs {}", x.t, y.t);
                assert!(
                    (x.normal - y.normal).norm() < 1e-6,
                    "ray {i}: normal {} vs {}",
                    x.normal,
                    y.normal
                );
            }
            (None, None) => {}
            _ => one += 1,
        }
    }
    assert!(both > RAYS / 4, "only {both} rays hit both");
    assert!(one <= RAYS / 500, "{one} rays hit only one of them");
}

#[test]
fn a_sphere_function_is_the_sphere() {
    agrees_with(
        "isosurface(f: fn(p) { length(p - [0.1, 0, 0]) - 0.8 })",
        Shape::Sphere {
            center: DVec3::new(0.1, 0.0, 0.0),
            radius: 0.8,
        },
        1.0,
        7001,
    );
}

#[test]
fn a_torus_function_is_the_torus() {
    agrees_with(
        "isosurface(f: fn(p) { length([length([p.x, 0, p.z]) - 0.6, p.y, 0]) - 0.25 }, min: [-0.9, -0.3, -0.9], max: [0.9, 0.3, 0.9], max_gradient: 1)",
        Shape::Torus {
            center: DVec3::ZERO,
            major_radius: 0.6,
            minor_radius: 0.25,
            spindle: Default::default(),
        },
        0.9,
        7002,
    );
}

/// A flat-coloured scene of `objects` (rtc source) at scale `s`: the camera and objects
/// scaled together.
fn flat(objects: &str, s: f64) -> String {
    format!(
        "rtc 1.1\n\
         camera {{ eye: [{e1:e}, {e2:e}, {e3:e}], center: [0, 0, 0], fov: 40deg, resolution: [160, 120] }}\n\
         point_light {{ position: [0, 0, {e3:e}] }}\n\
         render {{ shadows: false, max_depth: 0, ambient: once, background: rgb(0.1, 0.1, 0.1) }}\n\
         group(children: [{objects}]).material(material {{ color: rgb(1, 1, 1), ka: 1, kd: 0, ks: 0 }}).scale({s:e})\n",
        e1 = 0.5 * s,
        e2 = 1.5 * s,
        e3 = 6.0 * s,
    )
}

const SPHERE_F: &str = "isosurface(f: fn(p) { length(p) - 1 }, min: [-1.1, -1.1, -1.1], max: [1.1, 1.1, 1.1], max_gradient: 1)";
const TORUS_F: &str = "isosurface(f: fn(p) { length([length([p.x, 0, p.z]) - 1, p.y, 0]) - 0.3 }, min: [-1.4, -0.4, -1.4], max: [1.4, 0.4, 1.4], max_gradient: 1)";

/// Pixels of the masks of two scenes that differ, and their share.
fn masks_differ(a: &str, b: &str) -> (usize, f64) {
    let (x, y) = (render_rtc(&flat(a, 1.0)), render_rtc(&flat(b, 1.0)));
    let n = differing_by(&x, &y, 2);
    (n, share(&x, n))
}

#[test]
fn function_masks_match_the_analytic_shapes_alone_and_in_csg() {
    let pairs = [
        (
            format!("{SPHERE_F}.translate([-1.3, 0, 0]), {TORUS_F}.rotate(x: 50deg).translate([1.3, 0, 0])"),
            "sphere(radius: 1).translate([-1.3, 0, 0]), torus(major_radius: 1, minor_radius: 0.3).rotate(x: 50deg).translate([1.3, 0, 0])".to_string(),
        ),
        (
            format!("box(min: [-1.5, -0.8, -0.8], max: [1.5, 0.8, 0.8]) - {SPHERE_F}.translate([0.8, 0.3, 0.6])"),
            "box(min: [-1.5, -0.8, -0.8], max: [1.5, 0.8, 0.8]) - sphere(radius: 1).translate([0.8, 0.3, 0.6])".to_string(),
        ),
        (
            format!("{TORUS_F}.scale(1.5) & box(min: [-2, -1, -2], max: [0.5, 1, 2])"),
            "torus(major_radius: 1, minor_radius: 0.3).scale(1.5) & box(min: [-2, -1, -2], max: [0.5, 1, 2])".to_string(),
        ),
    ];
    for (iso, analytic) in &pairs {
        let (n, s) = masks_differ(iso, analytic);
        assert!(s <= 0.001, "{n} pixels ({s}) differ:\n{iso}\n{analytic}");
    }
}

#[test]
fn the_isosurface_scene_renders_the_same_at_every_scale() {
    let objects = format!(
        "{SPHERE_F}.translate([-1.3, 0, 0]), {TORUS_F}.rotate(x: 50deg).translate([1.3, 0, 0]), \
         isosurface(f: fn(p) {{ p.y - 0.3 * sin(3rad * p.x) * cos(2rad * p.z) }}).scale(0.6).translate([0, -1.2, 0])"
    );
    assert_same_at_scales(&[1e-6, 1e-3, 3.7, 1e3, 1e6, 1e8], |s| flat(&objects, s));
}

/// The diagnostics of evaluating, preparing and rendering `src`: evaluation's, the
/// preparation's, and the render's report.
fn render_findings(src: &str) -> (Vec<&'static str>, Vec<&'static str>, Vec<&'static str>) {
    let (scene, d) = load(&format!(
        "camera {{ eye: [0, 0, 4], center: [0, 0, 0], fov: 40deg, resolution: [40, 30] }}\n\
         point_light {{ position: [4, 6, 5] }}\n{src}"
    ));
    let scene = scene.unwrap_or_else(|| panic!("{src}: {:?}", d.items));
    let prepared = rtc::opt::prepare(&scene).expect("prepares");
    let options = rtc::render::RenderOptions {
        threads: 2,
        ..Default::default()
    };
    rtc::render::render(&prepared, &options, &rtc::render::Silent).expect("renders");
    (
        codes(&d.items),
        codes(prepared.warnings()),
        codes(&prepared.render_warnings()),
    )
}

#[test]
fn a_max_gradient_too_small_is_reported_and_an_adequate_one_is_not() {
    let wavy = "length(p) - 0.8 + 0.1 * sin(20rad * p.x)";
    // Too small: `rtc check` (evaluation) and the render both say so.
    let (eval, prep, render) = render_findings(&format!(
        "isosurface(f: fn(p) {{ {wavy} }}, max_gradient: 0.5)"
    ));
    assert_eq!(eval, ["rtc::isosurface::max_gradient"]);
    assert!(prep.is_empty(), "{prep:?}");
    assert_eq!(render, ["rtc::isosurface::max_gradient"]);
    // Adequate (the slope is at most 1 + 0.1·20 = 3): nothing.
    let (eval, prep, render) = render_findings(&format!(
        "isosurface(f: fn(p) {{ {wavy} }}, max_gradient: 3)"
    ));
    assert!(eval.is_empty() && prep.is_empty() && render.is_empty());
    // Estimated: a note when prepared, and the estimate holds over the render.
    let (eval, prep, render) = render_findings(&format!("isosurface(f: fn(p) {{ {wavy} }})"));
    assert!(eval.is_empty(), "{eval:?}");
    assert_eq!(prep, ["rtc::isosurface::estimated"]);
    assert!(render.is_empty(), "{render:?}");
}

#[test]
fn a_search_stops_at_its_budget_and_says_so() {
    // 100 000 rad per unit: about 64 000 sign changes across the box, and Lipschitz steps
    // averaging 0.64 / 100 000, so some 300 000 evaluations when CSG asks for every crossing
    // along a ray.
    let (_, _, render) = render_findings(
        "(isosurface(f: fn(p) { sin(100000rad * p.x) }, max_gradient: 100000, accuracy: 0.000001) & box(min: [-2, -2, -2], max: [2, 2, 2])).scale(0.5)",
    );
    assert!(render.contains(&"rtc::isosurface::budget"), "{render:?}");
}

#[test]
fn the_estimate_bounds_a_known_gradient() {
    // |∇(x² + y² + z²)| = 2|p| ≤ 2√3 in the unit box: the estimate (twice the sampled slope,
    // which reaches the corners) is at least that, and a note says what it is.
    let (scene, _) = load(
        "camera { eye: [0, 0, 5], center: [0, 0, 0] }\nisosurface(f: fn(p) { dot(p, p) - 0.5 })",
    );
    let prepared = rtc::opt::prepare(&scene.expect("scene")).expect("prepares");
    let note = &prepared.warnings()[0];
    assert_eq!(note.code, "rtc::isosurface::estimated");
    let bound: f64 = note
        .message
        .split("estimated as ")
        .nth(1)
        .and_then(|s| s.split(' ').next())
        .and_then(|s| s.parse().ok())
        .expect("a number in the note");
    assert!(bound >= 2.0 * 3f64.sqrt() * 1.9, "{bound}");
}
