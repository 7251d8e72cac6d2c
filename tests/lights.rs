//! Spot, parallel, cylinder, fading and shadowless lights, visible lights (`looks_like`) and
//! objects hidden from some rays (issue 37), checked against their stated rules
//! (docs/language.md §17, after POV-Ray 3.7's `Attenuate_Light`): a white diffuse plane
//! (`ka: 0, kd: 1, ks: 0`) seen face on, one world unit per pixel, so that a pixel is
//! `max(0, N·L)` times the light's share at the world point it looks at; every expected value is
//! computed here from the rule, never read from a render.

use std::path::Path;

use glam::DVec3;
use rtc::eval::{EvalOptions, load_source};
use rtc::ir::Scene;
use rtc::num::Norm;
use rtc::render::film::Film;
use rtc::render::{RenderOptions, render_scene};
use rtc::source::SourceMap;

const W: u32 = 96;
const H: u32 = 64;

fn load(src: &str) -> Result<Scene, Vec<String>> {
    let mut sources = SourceMap::default();
    let text = format!("rtc 1.1\n{src}");
    let loaded = load_source(
        Path::new("lights.rtc"),
        &text,
        &mut sources,
        &EvalOptions::default(),
    );
    loaded.scene.ok_or_else(|| {
        loaded
            .diagnostics
            .items
            .iter()
            .map(|d| d.code.to_string())
            .collect()
    })
}

/// The white diffuse plane z = 0 seen face on under `lights`, with `extra` objects.
fn plane_under(lights: &str, extra: &str) -> Scene {
    load(&format!(
        "camera {{ eye: [0, 0, 1000], center: [0, 0, 0], up: Y, fov: 2 * atan({H} / 2 / 1000),
                   resolution: [{W}, {H}] }}
         {lights}
         plane(point: [0, 0, 0], normal: Z).material(material {{ color: rgb(1, 1, 1), ka: 0, kd: 1, ks: 0 }})
         {extra}
         render {{ shadows: true, max_depth: 0 }}"
    ))
    .unwrap()
}

fn render(scene: &Scene, threads: usize) -> Film {
    let opts = RenderOptions {
        threads,
        ..Default::default()
    };
    render_scene(scene, &opts).unwrap()
}

/// The world point pixel (i, j) looks at.
fn world(i: u32, j: u32) -> DVec3 {
    DVec3::new(
        f64::from(i) + 0.5 - f64::from(W) / 2.0,
        f64::from(H) / 2.0 - f64::from(j) - 0.5,
        0.0,
    )
}

/// Every pixel's red channel against `expect` at its world point (`None`: not checked).
fn assert_pixels(film: &Film, mut expect: impl FnMut(DVec3) -> Option<f64>) {
    let mut checked = 0;
    for j in 0..H {
        for i in 0..W {
            let p = world(i, j);
            if let Some(want) = expect(p) {
                let got = film.get(i, j).x;
                assert!(
                    (got - want).abs() < 1e-6,
                    "pixel ({i}, {j}) at {p}: got {got}, want {want}"
                );
                checked += 1;
            }
        }
    }
    assert!(
        checked > (W * H) as usize / 2,
        "only {checked} pixels checked"
    );
}

/// POV-Ray's spot share: `cos^tightness`, times the smoothstep of the cosine between the
/// falloff's and the radius's.
fn spot_share(cos: f64, radius: f64, falloff: f64, tightness: f64) -> f64 {
    if cos <= 0.0 {
        return 0.0;
    }
    let (inner, outer) = (radius.to_radians().cos(), falloff.to_radians().cos());
    let base = cos.powf(tightness);
    if cos >= inner {
        base
    } else if cos < outer {
        0.0
    } else {
        let t = (cos - outer) / (inner - outer);
        base * t * t * (3.0 - 2.0 * t)
    }
}

#[test]
fn a_spot_light_is_full_inside_its_radius_and_ends_at_its_falloff() {
    let light = DVec3::new(3.0, -2.0, 40.0);
    let target = DVec3::new(5.0, 1.0, 0.0);
    let axis = (target - light).unit();
    for tightness in [0.0, 3.0] {
        let scene = plane_under(
            &format!(
                "spot_light {{ position: [3, -2, 40], target: [5, 1, 0], radius: 20deg,
                               falloff: 35deg, tightness: {tightness} }}"
            ),
            "",
        );
        let film = render(&scene, 2);
        assert_pixels(&film, |p| {
            let l = (light - p).unit();
            let cos = (-l).dot(axis);
            Some(l.z * spot_share(cos, 20.0, 35.0, tightness))
        });
        // Both edges are in the picture: some pixels full, some dark, some between.
        let reds: Vec<f64> = film.color().iter().map(|c| c.x).collect();
        assert!(reds.contains(&0.0));
        assert!(reds.iter().any(|&r| r > 0.9));
    }
}

#[test]
fn a_fading_light_has_its_colour_at_the_fade_distance() {
    let light = DVec3::new(-4.0, 3.0, 10.0);
    for power in [1.0, 2.0] {
        let scene = plane_under(
            &format!(
                "point_light {{ position: [-4, 3, 10], color: rgb(0.5, 0.5, 0.5), fade_distance: 15, fade_power: {power} }}"
            ),
            "",
        );
        assert_pixels(&render(&scene, 2), |p| {
            let d = (light - p).norm();
            let l = (light - p) / d;
            Some(0.5 * l.z * 2.0 / (1.0 + (d / 15.0).powf(power)))
        });
    }
}

/// Whether the ray from `p` along `l` meets the sphere (`centre`, `radius`), and how clearly:
/// the distance of its closest approach from the sphere's surface.
fn shadow_margin(p: DVec3, l: DVec3, centre: DVec3, radius: f64) -> (bool, f64) {
    let t = (centre - p).dot(l).max(0.0);
    let miss = (p + t * l - centre).norm();
    (miss < radius, (miss - radius).abs())
}

#[test]
fn a_parallel_light_lights_everything_alike_and_casts_a_parallel_shadow() {
    // The sun low in +x: a ball out of view at (60, 0, 10) shadows the middle of the picture.
    let l = DVec3::new(6.0, 0.0, 1.0).unit();
    let centre = DVec3::new(60.0, 0.0, 10.0);
    let ball = "sphere(center: [60, 0, 10], radius: 5)";
    for shadows in [true, false] {
        let scene = plane_under(
            &format!("parallel_light {{ direction: [-6, 0, -1], shadows: {shadows} }}"),
            ball,
        );
        let film = render(&scene, 2);
        let mut dark = 0;
        assert_pixels(&film, |p| {
            let (hit, margin) = shadow_margin(p, l, centre, 5.0);
            if margin < 0.05 {
                return None;
            }
            dark += usize::from(hit && shadows);
            Some(if hit && shadows { 0.0 } else { l.z })
        });
        assert_eq!(dark > 100, shadows, "shadow pixels: {dark}");
    }
}

#[test]
fn the_new_lights_render_the_same_bytes_on_one_and_two_threads() {
    let scene = plane_under(
        "spot_light { position: [0, 0, 30], target: [0, 0, 0], radius: 15deg, falloff: 30deg }
         parallel_light { direction: [-6, 0, -1], color: rgb(0.3, 0.3, 0.3) }",
        "sphere(center: [10, 0, 3], radius: 3)",
    );
    assert_eq!(render(&scene, 1).color(), render(&scene, 2).color());
}

#[test]
fn bad_lights_are_refused_with_a_code() {
    let cases = [
        (
            "spot_light { position: [0, 5, 0], target: [0, 5, 0] }",
            "rtc::light::aim",
        ),
        (
            "spot_light { position: [0, 5, 0], target: [0, 0, 0], radius: 30deg, falloff: 20deg }",
            "rtc::light::falloff",
        ),
        (
            "point_light { position: [0, 5, 0], fade_power: 2 }",
            "rtc::light::fade",
        ),
        ("parallel_light { direction: [0, 0, 0] }", "rtc::"),
        (
            "cylinder_light { position: [0, 5, 0], target: [0, 5, 0] }",
            "rtc::light::aim",
        ),
        (
            "cylinder_light { position: [0, 5, 0], target: [0, 0, 0], radius: 2, falloff: 1 }",
            "rtc::light::falloff",
        ),
        (
            "cylinder_light { position: [0, 5, 0], target: [0, 0, 0], radius: -1 }",
            "rtc::param::out_of_range",
        ),
        (
            "area_light { corner: [0, 5, 0], u: [1, 0, 0], v: [0, 0, 1], orient: true }",
            "rtc::light::orient",
        ),
        (
            "point_light { position: [0, 5, 0], looks_like: 3 }",
            "rtc::type::mismatch",
        ),
    ];
    for (light, code) in cases {
        let codes = load(&format!(
            "camera {{ eye: [0, 0, 5], center: [0, 0, 0], up: Y }}\n{light}\nsphere()"
        ))
        .expect_err(light);
        assert!(
            codes.iter().any(|c| c.starts_with(code)),
            "{light}: {codes:?}"
        );
    }
}

/// POV-Ray's cylinder share at distance `r` from the axis: `(1 − r/falloff)^tightness`, times
/// the smoothstep from 0 at the falloff to 1 at the radius.
fn cylinder_share(r: f64, radius: f64, falloff: f64, tightness: f64) -> f64 {
    if r >= falloff {
        return 0.0;
    }
    let dist = 1.0 - r / falloff;
    let base = dist.powf(tightness);
    if r <= radius {
        base
    } else {
        let t = dist / (1.0 - radius / falloff);
        base * t * t * (3.0 - 2.0 * t)
    }
}

#[test]
fn a_cylinder_light_is_full_inside_its_radius_and_ends_at_its_falloff() {
    let position = DVec3::new(3.0, -2.0, 40.0);
    for (target, tightness) in [([3.0, -2.0, 0.0], 0.0), ([9.0, 1.0, 0.0], 2.0)] {
        let target = DVec3::from_array(target);
        let axis = (target - position).unit();
        let scene = plane_under(
            &format!(
                "cylinder_light {{ position: [3, -2, 40], target: [{}, {}, 0], radius: 12,
                                   falloff: 20, tightness: {tightness} }}",
                target.x, target.y
            ),
            "",
        );
        let film = render(&scene, 2);
        assert_pixels(&film, |p| {
            let along = (p - position).dot(axis);
            let off = ((p - position) - along * axis).norm();
            // Beams arrive along the axis: N·L is the axis's slope towards the plane.
            Some(-axis.z * cylinder_share(off, 12.0, 20.0, tightness))
        });
        let reds: Vec<f64> = film.color().iter().map(|c| c.x).collect();
        assert!(reds.contains(&0.0));
        assert!(reds.iter().any(|&r| r > 0.9 * -axis.z));
    }
}

#[test]
fn a_cylinder_light_casts_a_shadow_along_its_axis_and_nothing_behind_its_plane() {
    // A ball between the tilted light and the plane shadows what its silhouette along the
    // axis covers; a plane behind the light's start gets nothing.
    let position = DVec3::new(0.0, 0.0, 40.0);
    let axis = (DVec3::new(-20.0, 0.0, 0.0) - position).unit();
    let centre = DVec3::new(10.0, 5.0, 8.0);
    let scene = plane_under(
        "cylinder_light { position: [0, 0, 40], target: [-20, 0, 0], radius: 30, falloff: 60 }",
        "sphere(center: [10, 5, 8], radius: 6)",
    );
    let film = render(&scene, 2);
    let mut dark = 0;
    assert_pixels(&film, |p| {
        // Seen from above the ball covers part of the plane: check the rest.
        if (p.truncate() - centre.truncate()).norm() < 6.0 + 0.75 {
            return None;
        }
        let (hit, margin) = shadow_margin(p, -axis, centre, 6.0);
        if margin < 0.05 {
            return None;
        }
        dark += usize::from(hit);
        let along = (p - position).dot(axis);
        let off = ((p - position) - along * axis).norm();
        Some(if hit {
            0.0
        } else {
            -axis.z * cylinder_share(off, 30.0, 60.0, 0.0)
        })
    });
    assert!(dark > 30, "shadow pixels beside the ball: {dark}");
    let behind = plane_under(
        "cylinder_light { position: [0, 0, -5], target: [0, 0, -40], radius: 30, falloff: 60 }",
        "",
    );
    assert!(render(&behind, 1).color().iter().all(|c| c.x == 0.0));
}

#[test]
fn a_light_that_looks_like_an_object_shows_it_and_is_not_shadowed_by_it() {
    let light = "point_light { position: [20, 0, 30], color: rgb(0.8, 0.8, 0.8)";
    let bulb = "looks_like: sphere(radius: 3).material(material { color: rgb(1, 0.5, 0.25), ka: 1, kd: 0 })";
    let plain = render(&plane_under(&format!("{light} }}"), ""), 1);
    let shown = render(&plane_under(&format!("{light}, {bulb} }}"), ""), 1);
    let mut same = 0;
    for j in 0..H {
        for i in 0..W {
            let p = world(i, j);
            let seen_on_bulb = (p.truncate() - glam::DVec2::new(20.0, 0.0)).norm() < 3.0 + 0.75;
            if seen_on_bulb {
                continue;
            }
            // Everywhere else the plane is lit exactly as without the bulb: it casts no shadow.
            assert_eq!(shown.get(i, j), plain.get(i, j), "pixel ({i}, {j})");
            same += 1;
        }
    }
    assert!(same > 5000);
    // The bulb itself is drawn at the light (ambient 1 of its colour, no ambient light set:
    // the default `per_light` convention times the light colour).
    let (i, j) = (20 + W / 2, H / 2);
    let c = shown.get(i, j);
    assert!(
        c.x > 0.5 && c.y > 0.2 && c.y < c.x,
        "the bulb's colour, got {c}"
    );
}

/// The flat-lit sphere (`ka: 1, kd: 0`, `ambient: once`) over a plane straight under a
/// parallel light, with `flags` on the sphere; `mirror` makes the plane a perfect mirror.
fn hidden_scene(flags: &str, mirror: bool) -> Scene {
    let plane = if mirror {
        "material { color: rgb(1, 1, 1), ka: 0, kd: 0, ks: 0, reflect: 1 }"
    } else {
        "material { color: rgb(1, 1, 1), ka: 0, kd: 1, ks: 0 }"
    };
    load(&format!(
        "camera {{ eye: [0, 0, 1000], center: [0, 0, 0], up: Y, fov: 2 * atan({H} / 2 / 1000),
                   resolution: [{W}, {H}] }}
         parallel_light {{ direction: [0, 0, -1] }}
         plane(point: [0, 0, 0], normal: Z).material({plane})
         sphere(center: [0, 0, 10], radius: 8).material(material {{ color: rgb(0.25, 0.5, 1), ka: 1, kd: 0, ks: 0 }}){flags}
         render {{ shadows: true, max_depth: 1, ambient: once, background: rgb(0.5, 0, 0) }}"
    ))
    .unwrap()
}

#[test]
fn hidden_objects_are_passed_by_the_rays_they_hide_from() {
    let inside = |p: DVec3| p.truncate().norm() < 8.0 - 0.75;
    let outside = |p: DVec3| p.truncate().norm() > 8.0 + 0.75;
    let sphere = DVec3::new(0.25, 0.5, 1.0);
    let check = |flags: &str, mirror: bool, want: &dyn Fn(DVec3) -> Option<DVec3>| {
        let film = render(&hidden_scene(flags, mirror), 2);
        let mut checked = 0;
        for j in 0..H {
            for i in 0..W {
                if let Some(w) = want(world(i, j)) {
                    assert_eq!(
                        film.get(i, j),
                        w,
                        "{flags} mirror {mirror}: pixel ({i}, {j})"
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked > 100, "{flags}: {checked}");
    };
    let lit = DVec3::ONE;
    // Seen: the sphere in front of its own shadow.
    check("", false, &|p| {
        if inside(p) {
            Some(sphere)
        } else {
            outside(p).then_some(lit)
        }
    });
    // Not in the image: the camera sees the shadow it still casts.
    check(".no_image()", false, &|p| {
        if inside(p) {
            Some(DVec3::ZERO)
        } else {
            outside(p).then_some(lit)
        }
    });
    // No shadow and no image: as if it were not there.
    check(".no_image().no_shadow()", false, &|_| Some(lit));
    // No shadow: seen, and the plane beside it fully lit.
    check(".no_shadow()", false, &|p| {
        if inside(p) {
            Some(sphere)
        } else {
            outside(p).then_some(lit)
        }
    });
    // A mirror shows a sphere the camera cannot see, straight back along each ray...
    check(".no_image()", true, &|p| inside(p).then_some(sphere));
    // ... but not one hidden from reflections: the mirror shows the background there.
    check(".no_image().no_reflection()", true, &|p| {
        inside(p).then_some(DVec3::new(0.5, 0.0, 0.0))
    });
    // The camera still sees a sphere hidden from reflections.
    check(".no_reflection()", true, &|p| inside(p).then_some(sphere));
}

#[test]
fn a_flag_on_a_group_holds_for_its_members() {
    let film = render(
        &load(&format!(
            "camera {{ eye: [0, 0, 1000], center: [0, 0, 0], up: Y, fov: 2 * atan({H} / 2 / 1000),
                       resolution: [{W}, {H}] }}
             parallel_light {{ direction: [0, 0, -1] }}
             plane(point: [0, 0, 0], normal: Z).material(material {{ color: rgb(1, 1, 1), ka: 0, kd: 1, ks: 0 }})
             group([sphere(center: [-10, 0, 10], radius: 5), sphere(center: [10, 0, 10], radius: 5)]).no_image().no_shadow()
             render {{ shadows: true, max_depth: 0 }}"
        ))
        .unwrap(),
        1,
    );
    assert!(film.color().iter().all(|c| *c == DVec3::ONE));
}
