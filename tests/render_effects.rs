//! Refraction, reflection, energy, nested media, sampling and determinism on small hand-built scenes.

mod common;

use common::{empty, light, mat, scene01_shadows, sphere};
use glam::DVec3;
use proptest::prelude::*;
use rtc::ir::limits::MAX_DEPTH;
use rtc::ir::{LightKind, Material, Object, Sampling, Scene, Shape, Texture};
use rtc::render::{RenderOptions, render_image, render_scene};
use rtc::source::Span;

fn opts(threads: usize) -> RenderOptions {
    RenderOptions {
        threads,
        ..Default::default()
    }
}

/// Clear glass: no local shading, all light transmitted.
fn glass(eta: f64, refract: f64, reflect: f64) -> Material {
    Material {
        ka: 0.0,
        kd: 0.0,
        ks: 0.0,
        reflect,
        refract,
        eta,
        ..Material::default()
    }
}

/// A 3×3 course camera at `eye` looking along `dir`; pixel (1, 1) looks exactly along `dir`.
fn tiny_view(s: &mut Scene, eye: DVec3, dir: DVec3, pixel: f64) {
    s.camera.eye = eye;
    s.camera.center = eye + dir;
    s.camera.up = dir.any_orthonormal_vector() * pixel;
    s.camera.width = 3;
    s.camera.height = 3;
}

#[test]
fn a_ray_through_a_glass_sphere_centre_is_undeviated() {
    // A small red target far behind a big glass sphere, on the axis through its centre.
    let mut s = empty([0.0, 0.0, 0.0]);
    s.lights.push(light([0.0, 0.0, 1000.0], [1.0, 1.0, 1.0]));
    sphere(&mut s, [0.0, 0.0, -300.0], 100.0, glass(1.5, 1.0, 0.0));
    sphere(
        &mut s,
        [0.0, 0.0, -2000.0],
        1.0,
        mat([1.0, 0.0, 0.0], 1.0, 0.0, 0.0, 1.0),
    );
    s.settings.max_depth = 4;
    tiny_view(&mut s, DVec3::ZERO, DVec3::NEG_Z, 1e-4);
    let film = render_scene(&s, &opts(1)).unwrap();
    assert_eq!(
        film.get(1, 1),
        DVec3::new(1.0, 0.0, 0.0),
        "sees the target through the glass"
    );
    // A ray 5 units off the axis bends away and misses the 1-unit target.
    tiny_view(&mut s, DVec3::new(5.0, 0.0, 0.0), DVec3::NEG_Z, 1e-4);
    let off = render_scene(&s, &opts(1)).unwrap();
    assert_eq!(off.get(1, 1), DVec3::ZERO);
}

#[test]
fn total_internal_reflection_beyond_the_critical_angle() {
    // Eye inside a glass sphere of radius 100 at height 90, looking horizontally: the wall is met
    // at 64.2° from its normal. The critical angle is 41.8° for eta 1.5 (the light is trapped and
    // the pixel stays black) and 72.2° for eta 1.05 (it leaves into the white background).
    let wall_angle = (90.0f64 / 100.0).asin().to_degrees();
    assert!((64.0..64.5).contains(&wall_angle));
    for (eta, trapped) in [(1.5, true), (1.05, false)] {
        let mut s = empty([0.0, 0.0, 0.0]);
        sphere(&mut s, [0.0, 0.0, 0.0], 100.0, glass(eta, 1.0, 0.0));
        s.settings.background = DVec3::ONE;
        s.settings.max_depth = 6;
        tiny_view(&mut s, DVec3::new(0.0, 90.0, 0.0), DVec3::X, 1e-4);
        let c = render_scene(&s, &opts(1)).unwrap().get(1, 1);
        if trapped {
            assert_eq!(c, DVec3::ZERO, "eta {eta}");
        } else {
            assert_eq!(c, DVec3::ONE, "eta {eta}");
        }
    }
}

/// A checkerboard backdrop sphere behind the view, so any bending of rays shows.
fn checker_backdrop(s: &mut Scene) {
    let t = s.add_texture(Texture::Checker {
        a: DVec3::new(1.0, 0.2, 0.2),
        b: DVec3::new(0.2, 0.2, 1.0),
        size: 20.0,
    });
    let mut m = mat([1.0, 1.0, 1.0], 1.0, 0.0, 0.0, 1.0);
    m.texture = Some(t);
    sphere(s, [200.0, 200.0, -1000.0], 1000.0, m);
}

#[test]
fn nested_media_refract_by_the_ratio_of_both_sides() {
    // A glass sphere holding a concentric sphere of the same glass: at the inner boundary both
    // sides have index 1.5, so the inner sphere must be invisible.
    let scene = |inner: Option<f64>| {
        let mut s = empty([200.0, 200.0, 1000.0]);
        s.lights
            .push(light([200.0, 200.0, 1000.0], [1.0, 1.0, 1.0]));
        checker_backdrop(&mut s);
        sphere(&mut s, [200.0, 200.0, 300.0], 150.0, glass(1.5, 1.0, 0.0));
        if let Some(eta) = inner {
            sphere(&mut s, [200.0, 200.0, 300.0], 80.0, glass(eta, 1.0, 0.0));
        }
        s.settings.max_depth = 8;
        s
    };
    let without = render_image(&scene(None), &opts(2)).unwrap();
    let same = render_image(&scene(Some(1.5)), &opts(2)).unwrap();
    let other = render_image(&scene(Some(1.2)), &opts(2)).unwrap();
    let differ = |a: &rtc::render::Image, b: &rtc::render::Image| {
        a.pixels().zip(b.pixels()).filter(|(p, q)| p != q).count()
    };
    // Rays crossing the inner boundary split there (a new origin), so allow a few edge pixels.
    assert!(differ(&without, &same) < 40, "{}", differ(&without, &same));
    assert!(
        differ(&without, &other) > 5000,
        "a different inner glass must show"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]
    /// Transparent chains with reflect + refract ≤ 1 and no local light never brighten the
    /// background they show (including total internal reflection, which moves the refracted
    /// share to the reflection).
    #[test]
    fn refraction_chains_never_create_energy(
        spheres in prop::collection::vec(
            ((100.0..300.0f64, 100.0..300.0f64, -200.0..400.0f64), 10.0..120.0f64,
             1.0..2.5f64, 0.0..1.0f64, 0.0..1.0f64),
            1..5),
        depth in 1u32..8,
    ) {
        let mut s = empty([200.0, 200.0, 1000.0]);
        s.camera.width = 24;
        s.camera.height = 24;
        s.camera.up = DVec3::new(0.0, 400.0 / 24.0, 0.0);
        s.settings.background = DVec3::new(0.25, 0.5, 0.75);
        s.settings.max_depth = depth;
        for ((x, y, z), r, eta, a, b) in spheres {
            let (refract, reflect) = (a, (1.0 - a) * b);
            sphere(&mut s, [x, y, z], r, glass(eta, refract, reflect));
        }
        let film = render_scene(&s, &opts(1)).unwrap();
        for c in film.color() {
            prop_assert!(c.cmple(s.settings.background + 1e-12).all(), "{c:?}");
        }
    }
}

/// scene01 with shadows, reflection, an area light, a thin lens and 2×2 supersampling:
/// everything that draws random numbers.
fn random_scene() -> Scene {
    let mut s = scene01_shadows();
    s.camera.width = 120;
    s.camera.height = 120;
    s.camera.up = DVec3::new(0.0, 400.0 / 120.0, 0.0);
    s.camera.aperture = 8.0;
    s.camera.focus_distance = 700.0;
    s.lights[0].kind = LightKind::Area {
        corner: DVec3::new(-250.0, 550.0, 1500.0),
        u: DVec3::new(100.0, 0.0, 0.0),
        v: DVec3::new(0.0, 100.0, 0.0),
        samples: [3, 3],
        circular: false,
        orient: false,
    };
    s.settings.max_depth = 2;
    s.settings.sampling = Sampling::Grid { factor: 2 };
    s.settings.seed = 7;
    s
}

#[test]
fn same_bytes_for_one_and_two_threads() {
    let s = random_scene();
    let one = render_image(&s, &opts(1)).unwrap();
    let two = render_image(&s, &opts(2)).unwrap();
    assert!(one == two);
    let mut other_seed = s.clone();
    other_seed.settings.seed = 8;
    assert!(
        render_image(&other_seed, &opts(2)).unwrap() != two,
        "the seed matters"
    );
}

#[test]
fn area_lights_soften_shadow_edges() {
    let hard = scene01_shadows();
    let mut soft = hard.clone();
    soft.lights[0].kind = LightKind::Area {
        corner: DVec3::new(-300.0, 500.0, 1500.0),
        u: DVec3::new(200.0, 0.0, 0.0),
        v: DVec3::new(0.0, 200.0, 0.0),
        samples: [4, 4],
        circular: false,
        orient: false,
    };
    // On the grey backdrop a hard shadow leaves each pixel either fully lit (as without
    // shadows) or at the ambient level trunc(255·0.2·0.4) = 20; a penumbra lies in between.
    let mut unshadowed = hard.clone();
    unshadowed.settings.shadows = false;
    let lit = render_image(&unshadowed, &opts(2)).unwrap();
    let partial = |s: &Scene| {
        let img = render_image(s, &opts(2)).unwrap();
        img.pixels()
            .zip(lit.pixels())
            .filter(|(p, l)| p[0] == p[1] && p[1] == p[2] && l[0] == l[1] && l[1] == l[2])
            .filter(|(p, l)| p[0] > 23 && p[0] + 3 < l[0])
            .count()
    };
    let (soft, hard) = (partial(&soft), partial(&hard));
    assert!(
        hard < 50 && soft > 3000,
        "penumbra pixels: {soft} soft, {hard} hard"
    );
}

#[test]
fn adaptive_sampling_refines_only_at_edges_and_matches_the_fine_grid_there() {
    let mut coarse = scene01_shadows();
    coarse.settings.sampling = Sampling::Adaptive {
        min: 1,
        max: 4,
        threshold: 0.1,
    };
    let film = render_scene(&coarse, &opts(2)).unwrap();
    let refined = film.stats.refined_pixels;
    assert!(refined > 1000 && refined < 40_000, "{refined}");
    let mut fine = coarse.clone();
    fine.settings.sampling = Sampling::Grid { factor: 4 };
    let fine = render_image(&fine, &opts(2)).unwrap();
    let adaptive = film.to_image();
    let mut one = scene01_shadows();
    one.settings.sampling = Sampling::Grid { factor: 1 };
    let one = render_image(&one, &opts(2)).unwrap();
    // Every pixel equals either the 1-sample or the 4×4 render.
    for ((a, f), o) in adaptive.pixels().zip(fine.pixels()).zip(one.pixels()) {
        assert!(a == f || a == o);
    }
}

#[test]
fn missing_material_and_texture_ids_are_diagnosed_not_panics() {
    let mut s = empty([200.0, 200.0, 1000.0]);
    s.objects.push(Object {
        motion: None,
        shape: Shape::Sphere {
            center: DVec3::ZERO,
            radius: 1.0,
        },
        transform: rtc::ir::Transform::IDENTITY,
        material: Some(rtc::ir::MaterialId(9)),
        span: Span::default(),
        visibility: Default::default(),
    });
    assert_eq!(
        render_image(&s, &opts(1)).unwrap_err().items[0].code,
        "rtc::render::material"
    );
    let mut s = empty([200.0, 200.0, 1000.0]);
    let m = Material {
        texture: Some(rtc::ir::TextureId(3)),
        ..Material::default()
    };
    sphere(&mut s, [0.0, 0.0, 0.0], 1.0, m);
    assert_eq!(
        render_image(&s, &opts(1)).unwrap_err().items[0].code,
        "rtc::render::texture"
    );
    // Cameras that cannot make rays: `up` along the view, an empty image, no field of view.
    let bad_cameras: [fn(&mut rtc::ir::Camera); 3] = [
        |c| c.up = DVec3::Z,
        |c| c.width = 0,
        |c| c.projection = rtc::ir::Projection::Perspective { fov_y: 0.0 },
    ];
    for spoil in bad_cameras {
        let mut s = empty([200.0, 200.0, 1000.0]);
        spoil(&mut s.camera);
        assert_eq!(
            render_image(&s, &opts(1)).unwrap_err().items[0].code,
            "rtc::render::camera"
        );
    }
}

#[test]
fn hatching_draws_black_ink_on_the_material_colour_denser_in_shade() {
    let mut s = common::scene01();
    s.settings.shading = rtc::ir::ShadingModel::Hatching;
    let film = render_scene(&s, &opts(2)).unwrap();
    // Ink per half of the red sphere (centre (290,170,150) projects to pixel (305.9, 234.8),
    // radius ≈ 59 px): the light is up and to the left, so the lower right is darker. The red
    // sphere's paper is its colour and the ink black, so every pixel there is the colour times
    // the uncovered share (anti-aliased strokes give the shares between 0 and 1).
    let red = DVec3::new(1.0, 0.0, 0.0);
    let mut ink = [0.0f64; 2];
    for y in 0..film.height {
        for x in 0..film.width {
            let (dx, dy) = (f64::from(x) - 305.9, f64::from(y) - 234.8);
            if dx * dx + dy * dy < 45.0 * 45.0 {
                let p = film.get(x, y);
                let paper = p.x / red.x;
                assert!(
                    (p - paper * red).abs().max_element() < 1e-9,
                    "{x},{y}: {p:?}"
                );
                ink[usize::from(dx + dy > 0.0)] += 1.0 - paper;
            }
        }
    }
    // Ink covers the darkness share of the paper continuously (lit parts get thin strokes
    // too), so the halves differ by their mean darkness: 1.77× here.
    assert!(ink[1] > 1.5 * ink[0].max(1.0), "{ink:?}");
}

#[test]
fn deep_recursion_between_mirrors_and_oversized_settings() {
    // Two mirrors facing each other: the ray along the axis bounces the full MAX_DEPTH times
    // (curved mirrors send the off-axis rays away sooner).
    let mut s = empty([0.0, 0.0, 0.0]);
    s.lights.push(light([0.0, 50.0, 0.0], [1.0, 1.0, 1.0]));
    let mirror = || Material {
        reflect: 1.0,
        ..mat([0.5, 0.5, 0.5], 0.01, 0.1, 0.0, 1.0)
    };
    sphere(&mut s, [-200.0, 0.0, 0.0], 100.0, mirror());
    sphere(&mut s, [200.0, 0.0, 0.0], 100.0, mirror());
    s.settings.max_depth = MAX_DEPTH;
    tiny_view(&mut s, DVec3::ZERO, DVec3::X, 1e-6);
    let film = render_scene(&s, &opts(2)).unwrap();
    assert!(
        film.stats.secondary_rays >= u64::from(MAX_DEPTH),
        "{:?}",
        film.stats
    );
    let code = |s: &Scene| render_image(s, &opts(1)).unwrap_err().items[0].code;
    let mut deep = s.clone();
    deep.settings.max_depth = MAX_DEPTH + 1;
    assert_eq!(code(&deep), "rtc::render::limit");
    let mut huge = s.clone();
    huge.camera.width = u32::MAX;
    huge.camera.height = u32::MAX;
    assert_eq!(code(&huge), "rtc::render::limit");
    let mut dense = s.clone();
    dense.settings.sampling = Sampling::Grid { factor: 100_000 };
    assert_eq!(code(&dense), "rtc::render::limit");
}

/// A textured sphere inside a CSG node or a union maps its texture about its own centre, as it
/// does on its own: the mapping frame travels with the hit. (The renderer used to look up the
/// top-level object's shape, so a sphere inside CSG mapped about the origin: nearly every
/// textured pixel differed.)
#[test]
fn a_textured_sphere_maps_the_same_inside_csg() {
    let textured = |s: &mut Scene| {
        let t = s.add_texture(Texture::Image {
            path: common::data("textures/earthmap1k.png"),
            mapping: rtc::ir::Mapping::Spherical,
            filter: rtc::ir::ImageFilter::Nearest,
            span: Span::default(),
        });
        s.add_material(Material {
            texture: Some(t),
            ..mat([1.0, 1.0, 1.0], 0.3, 0.7, 0.0, 1.0)
        })
    };
    let ball = |m| Object {
        motion: None,
        shape: Shape::Sphere {
            center: DVec3::new(260.0, 230.0, 100.0),
            radius: 120.0,
        },
        transform: rtc::ir::Transform::IDENTITY,
        material: Some(m),
        span: Span::default(),
        visibility: Default::default(),
    };
    let render_with = |wrap: &dyn Fn(Object) -> Object| {
        let mut s = empty([200.0, 200.0, 1000.0]);
        s.lights
            .push(light([-200.0, 600.0, 1500.0], [1.0, 1.0, 1.0]));
        let m = textured(&mut s);
        s.objects.push(wrap(ball(m)));
        render_image(&s, &opts(2)).unwrap()
    };
    let csg = |op, other: Shape| {
        move |b: Object| Object {
            motion: None,
            shape: Shape::Csg {
                op,
                children: vec![
                    b,
                    Object {
                        motion: None,
                        shape: other.clone(),
                        transform: rtc::ir::Transform::IDENTITY,
                        material: None,
                        span: Span::default(),
                        visibility: Default::default(),
                    },
                ],
            },
            transform: rtc::ir::Transform::IDENTITY,
            material: None,
            span: Span::default(),
            visibility: Default::default(),
        }
    };
    let alone = render_with(&|b| b);
    let around = Shape::Box {
        min: DVec3::splat(-1000.0),
        max: DVec3::splat(1000.0),
    };
    let far = Shape::Sphere {
        center: DVec3::new(-5000.0, 0.0, 0.0),
        radius: 1.0,
    };
    let textured_pixels = alone.pixels().filter(|p| p.0 != [0, 0, 0]).count();
    assert!(textured_pixels > 10_000, "{textured_pixels}");
    for (name, wrap) in [
        ("intersection", csg(rtc::ir::CsgOp::Intersection, around)),
        ("union", csg(rtc::ir::CsgOp::Union, far)),
    ] {
        let inside = render_with(&wrap);
        // Hits inside CSG come from the crossing computation, whose `t` may differ in the last
        // bits: a texel boundary may fall on the other side of a few pixels, no more.
        let differing = alone
            .pixels()
            .zip(inside.pixels())
            .filter(|(a, b)| a != b)
            .count();
        assert!(
            differing * 200 < textured_pixels,
            "{name}: {differing} of {textured_pixels} pixels differ"
        );
    }
}

/// One preparation serves renders at several qualities (what `rtc accuracy` needs): the render
/// after `set_quality` equals preparing the scene with those settings from the start.
#[test]
fn a_prepared_scene_renders_at_other_qualities() {
    let mut s = scene01_shadows();
    s.materials[0].reflect = 0.5;
    let mut prepared = rtc::opt::prepare(&s).unwrap();
    let quality = rtc::opt::Quality {
        sampling: Sampling::Grid { factor: 2 },
        max_depth: 2,
        ..rtc::opt::Quality::of(&s.settings)
    };
    prepared.set_quality(quality).unwrap();
    let again = rtc::render::render(&prepared, &opts(2), &rtc::render::Silent).unwrap();
    let mut direct = s.clone();
    direct.settings.sampling = quality.sampling;
    direct.settings.max_depth = quality.max_depth;
    assert_eq!(again.to_image(), render_image(&direct, &opts(2)).unwrap());
    assert_ne!(again.to_image(), render_image(&s, &opts(2)).unwrap());
    let past = rtc::opt::Quality {
        max_depth: MAX_DEPTH + 1,
        ..quality
    };
    assert_eq!(
        prepared.set_quality(past).unwrap_err().code,
        "rtc::render::limit"
    );
}

/// Progress goes to the caller's callback (rows of every pass), and the callback can cancel.
#[test]
fn progress_reaches_the_callback_and_cancels() {
    use std::sync::atomic::{AtomicU64, Ordering};
    struct Count {
        total: AtomicU64,
        done: AtomicU64,
        stop_after: u64,
    }
    impl rtc::render::Progress for Count {
        fn start(&self, rows: u64) {
            self.total.store(rows, Ordering::Relaxed);
        }
        fn advance(&self, rows: u64) {
            self.done.fetch_add(rows, Ordering::Relaxed);
        }
        fn cancelled(&self) -> bool {
            self.done.load(Ordering::Relaxed) >= self.stop_after
        }
    }
    let mut s = scene01_shadows();
    s.settings.sampling = Sampling::Adaptive {
        min: 1,
        max: 2,
        threshold: 0.1,
    };
    let prepared = rtc::opt::prepare(&s).unwrap();
    let count = |stop_after| Count {
        total: AtomicU64::new(0),
        done: AtomicU64::new(0),
        stop_after,
    };
    let all = count(u64::MAX);
    rtc::render::render(&prepared, &opts(2), &all).unwrap();
    // Two passes (coarse and refined) over 400 rows.
    assert_eq!(all.total.load(Ordering::Relaxed), 800);
    assert_eq!(all.done.load(Ordering::Relaxed), 800);
    let early = count(40);
    let err = rtc::render::render(&prepared, &opts(2), &early).unwrap_err();
    assert_eq!(err.code, "rtc::render::cancelled");
    assert!(early.done.load(Ordering::Relaxed) < 800);
}
