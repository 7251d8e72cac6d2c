//! Where secondary and shadow rays start (issue 10, defects 3, 4 and 5): the offset is the hit
//! point's own error bound, so nothing far away or out of view changes a small object's
//! shadows, a scene far from the origin keeps its shadow edges, a light lying on a surface lights
//! what is above it, and rays survive long chains of refractions.
//!
//! Each expectation is a rule, not captured output: two scenes that must look the same (with and
//! without an invisible object, a ground plane and the Earth-sized sphere it approximates to
//! 10⁻⁸, a shell 10⁻⁶ thick and no shell), or an analytic ray path.

mod geometry_support;
mod numerics_support;

use glam::{DAffine3, DVec3};
use numerics_support::{at, differing, differing_by, render_rtc, share};
use rtc::geometry::{Ray, World};
use rtc::ir::{Object, Shape};
use rtc::num::Norm;
use rtc::render::offset::SpawnPoint;
use rtc::render::scatter::refract;

const NO_SHADING: &str = "ka: 0, kd: 0, ks: 0";

#[test]
fn a_light_lying_on_a_plane_does_not_shadow_a_ball_above_it() {
    // Defect 5: every point above the plane sees the light; the plane itself gets no diffuse
    // light from a light in its own plane. So shadows change nothing.
    let scene = |shadows: bool| {
        format!(
            "rtc 1\n\
             camera {{ eye: [0, 2, 6], center: [0, 0.5, 0], fov: 40deg, resolution: [96, 72] }}\n\
             render {{ shadows: {shadows} }}\n\
             point_light {{ position: [2, 0, 1] }}\n\
             plane()\n\
             sphere(center: [0, 1, 0], radius: 0.5)\n"
        )
    };
    let with = render_rtc(&scene(true));
    let without = render_rtc(&scene(false));
    assert_eq!(differing(&with, &without), 0);
}

/// A small still life (balls 0.05 across on a floor, one of glass, one box) and `extra` objects.
fn still_life(ground: &str, extra: &str) -> String {
    format!(
        "rtc 1\n\
         camera {{ eye: [0, 0.12, 0.35], center: [0, 0.03, 0], fov: 40deg, resolution: [96, 72] }}\n\
         render {{ max_depth: 4 }}\n\
         point_light {{ position: [0.3, 0.5, 0.4] }}\n\
         {ground}\n\
         sphere(center: [-0.06, 0.025, 0], radius: 0.025).material(material {{ color: rgb(0.9, 0.2, 0.1) }})\n\
         sphere(center: [0.05, 0.025, 0.02], radius: 0.025).material(material {{ color: rgb(1, 1, 1), {NO_SHADING}, refract: 1, eta: 1.5 }})\n\
         box(min: [-0.01, 0, -0.08], max: [0.03, 0.04, -0.04]).material(material {{ color: rgb(0.2, 0.5, 0.9), reflect: 0.3 }})\n\
         {extra}\n"
    )
}

const FLOOR: &str = "plane().material(material { color: rgb(0.8, 0.8, 0.7) })";

#[test]
fn a_huge_object_out_of_view_changes_nothing() {
    // Defect 3: a 10⁵ sphere buried 2·10⁶ below used to grow every offset to ~10⁻³, wiping out
    // the small objects' shadows and bending their refraction.
    let plain = render_rtc(&still_life(FLOOR, ""));
    let buried = render_rtc(&still_life(
        FLOOR,
        "sphere(center: [0, -2e6, 0], radius: 1e5)",
    ));
    assert_eq!(differing(&plain, &buried), 0);
}

#[test]
fn small_objects_on_the_earth_look_as_on_a_plane() {
    // Defect 3: on an Earth-radius ground sphere the offset was 0.013, more than half the balls.
    // Over the 0.3 units in view the sphere departs from its tangent plane by < 10⁻⁸.
    let plane = render_rtc(&still_life(FLOOR, ""));
    let earth = render_rtc(&still_life(
        "sphere(center: [0, -6.371e6, 0], radius: 6.371e6).material(material { color: rgb(0.8, 0.8, 0.7) })",
        "",
    ));
    let n = differing_by(&plane, &earth, 1);
    assert!(share(&plane, n) <= 0.001, "{n} pixels differ");
}

#[test]
fn a_scene_far_from_the_origin_keeps_its_shadows() {
    // Defect 4: at 10⁸ from the origin the offset 10⁻⁹·|P| was 0.1 units. The same scene moved
    // there must render as at the origin, but for pixels whose rays round differently (the
    // coordinates' spacing there is 1.5·10⁻⁸, 10⁻⁶ of the view).
    let scene = |shift: [f64; 3]| {
        let p = |x: [f64; 3]| at(1.0, shift, x);
        format!(
            "rtc 1\n\
             camera {{ eye: {}, center: {}, fov: 40deg, resolution: [96, 72] }}\n\
             point_light {{ position: {} }}\n\
             plane(point: {}, normal: Y)\n\
             sphere(center: {}, radius: 0.5)\n\
             box(min: {}, max: {})\n",
            p([0.0, 2.0, 6.0]),
            p([0.0, 0.5, 0.0]),
            p([3.0, 5.0, 2.0]),
            p([0.0, 0.0, 0.0]),
            p([-0.6, 0.5, 0.0]),
            p([0.4, 0.0, -1.0]),
            p([1.2, 0.8, -0.2]),
        )
    };
    let home = render_rtc(&scene([0.0; 3]));
    for shift in [[1e6, 0.0, 0.0], [0.0, 0.0, -1e8], [1e8, 1e8, 1e8]] {
        let far = render_rtc(&scene(shift));
        let n = differing_by(&home, &far, 1);
        assert!(share(&home, n) <= 0.001, "{shift:?}: {n} pixels differ");
    }
}

#[test]
fn a_tiny_ball_beside_a_huge_one_casts_its_shadow() {
    // Mixed scales: a 10⁻⁵ ball on a 10⁵ sphere, seen from 10⁻⁴, looks as on a plane (the big
    // sphere departs from its tangent plane by < 10⁻¹⁵ over the view).
    let scene = |ground: &str| {
        format!(
            "rtc 1\n\
             camera {{ eye: [0, 3e-5, 1e-4], center: [0, 1e-5, 0], fov: 40deg, resolution: [96, 72] }}\n\
             render {{ max_depth: 3 }}\n\
             point_light {{ position: [3e-5, 1e-4, 4e-5] }}\n\
             {ground}\n\
             sphere(center: [-1.5e-5, 1e-5, 0], radius: 1e-5).material(material {{ color: rgb(0.9, 0.2, 0.1) }})\n\
             sphere(center: [1.5e-5, 1e-5, 0], radius: 1e-5).material(material {{ color: rgb(1, 1, 1), {NO_SHADING}, refract: 1, eta: 1.5 }})\n"
        )
    };
    let plane = render_rtc(&scene("plane()"));
    let big = render_rtc(&scene("sphere(center: [0, -1e5, 0], radius: 1e5)"));
    let n = differing_by(&plane, &big, 1);
    assert!(share(&plane, n) <= 0.001, "{n} pixels differ");
    // And the small ball's shadow is there: the floor under the light's side is darker.
    let no_shadows =
        render_rtc(&scene("plane()").replace("max_depth: 3", "max_depth: 3, shadows: false"));
    assert!(differing(&plane, &no_shadows) > 100);
}

#[test]
fn a_glass_shell_one_millionth_thick_is_nearly_invisible() {
    // Clear glass with parallel walls 10⁻⁶ apart shifts what is behind by ~10⁻⁶: the image is the
    // image without it, but for pixels at its rim.
    let scene = |shell: &str| {
        format!(
            "rtc 1\n\
             camera {{ eye: [0, 0, 5], fov: 40deg, resolution: [96, 96] }}\n\
             render {{ max_depth: 8, shadows: false }}\n\
             point_light {{ position: [2, 3, 6] }}\n\
             plane(point: [0, 0, -3], normal: Z).material(material {{ texture: checker(size: 0.5) }})\n\
             {shell}\n"
        )
    };
    let empty = render_rtc(&scene(""));
    let shell = render_rtc(&scene(&format!(
        "(sphere(radius: 1) - sphere(radius: 1 - 1e-6)).material(material {{ color: rgb(1, 1, 1), {NO_SHADING}, refract: 1, eta: 1.5 }})"
    )));
    let n = differing_by(&empty, &shell, 1);
    assert!(share(&empty, n) <= 0.005, "{n} pixels differ");
}

/// Thirty parallel glass plates across z, each `thickness` thick and `gap` apart, scaled by `s`.
fn plates(s: f64, thickness: f64, gap: f64) -> Vec<Object> {
    (0..30)
        .map(|i| {
            let z0 = -(i as f64) * (thickness + gap);
            Object {
                shape: Shape::Box {
                    min: DVec3::new(-50.0, -50.0, z0 - thickness),
                    max: DVec3::new(50.0, 50.0, z0),
                },
                transform: DAffine3::from_scale(DVec3::splat(s)).into(),
                material: None,
                motion: None,
                span: rtc::source::Span::default(),
                visibility: Default::default(),
            }
        })
        .collect()
}

fn world_of(objects: Vec<Object>) -> World {
    geometry_support::world(objects)
}

#[test]
fn sixty_refractions_through_thirty_plates_follow_snells_law() {
    // Through parallel plates a ray leaves parallel to how it came, shifted sideways by
    // thickness·(tan θ − tan θ') per plate: traced with the renderer's spawn rules, every one of
    // the 60 interfaces must be met once, in order, at every scale.
    let eta = 1.5;
    for s in [1e-6, 1.0, 1e6] {
        let (thickness, gap) = (0.01, 0.02);
        let w = world_of(plates(s, thickness, gap));
        let theta: f64 = 0.5;
        let dir0 = DVec3::new(theta.sin(), 0.0, -theta.cos());
        let start = DVec3::new(0.0, 0.0, 1.0) * s;
        let mut ray = Ray::new(start, dir0);
        let mut inside = false;
        let mut interfaces = 0;
        while let Some(h) = w.intersect(&ray, 0.0, f64::INFINITY) {
            interfaces += 1;
            assert!(interfaces <= 60, "scale {s:e}: more than 60 interfaces met");
            let facing = if inside { -h.normal } else { h.normal };
            let (n1, n2) = if inside { (eta, 1.0) } else { (1.0, eta) };
            let dir = refract(ray.dir, facing, n1, n2).expect("no total internal reflection");
            ray = SpawnPoint::of(&h).ray(dir);
            inside = !inside;
        }
        assert_eq!(interfaces, 60, "scale {s:e}");
        assert!(
            (ray.dir - dir0).norm() < 1e-12,
            "scale {s:e}: leaves along {}",
            ray.dir
        );
        // Where the ray crosses the plane z = −1 (below the stack), against the analytic shift.
        let theta_in = (theta.sin() / eta).asin();
        let glass = 30.0 * thickness;
        let z_end = -1.0;
        let x_straight = (1.0 - z_end) * theta.tan();
        let want = x_straight - glass * (theta.tan() - theta_in.tan());
        let t = (z_end * s - ray.origin.z) / ray.dir.z;
        let got = ray.at(t).x / s;
        assert!(
            (got - want).abs() < 1e-9,
            "scale {s:e}: x = {got}, want {want}"
        );
    }
}

#[test]
fn sixty_bounces_render_through_the_stack() {
    // Head-on through 30 plates (60 refractions, max_depth 64): the centre pixel sees the red
    // target exactly as without the plates.
    let scene = |stack: bool| {
        let plates = if stack {
            format!(
                "for i in 0..30 {{ box(min: [-5, -5, -i * 0.03 - 0.01], max: [5, 5, -i * 0.03]).material(material {{ color: rgb(1, 1, 1), {NO_SHADING}, refract: 1, eta: 1.5 }}) }}"
            )
        } else {
            String::new()
        };
        format!(
            "rtc 1\n\
             camera {{ eye: [0, 0, 2], center: [0, 0, 0], fov: 10deg, resolution: [9, 9] }}\n\
             render {{ max_depth: 64 }}\n\
             point_light {{ position: [0, 0, -1.5] }}\n\
             {plates}\n\
             plane(point: [0, 0, -2], normal: Z).material(material {{ color: rgb(1, 0, 0) }})\n"
        )
    };
    let with = render_rtc(&scene(true));
    let without = render_rtc(&scene(false));
    assert_eq!(with.get_pixel(4, 4), without.get_pixel(4, 4));
    assert_ne!(with.get_pixel(4, 4).0, [0, 0, 0]);
}
