//! Shared helpers for the render tests: hand-built course scenes (numbers from COURSE.md §1.1 and
//! the official scene01.yaml) and image comparison against the reference renders.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

use glam::DVec3;
use rtc::ir::{
    Camera, Light, LightKind, Material, Object, Projection, RenderSettings, Scene, Shape,
};
use rtc::render::Image;
use rtc::source::Span;

/// The course's test data folder.
pub fn data(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/course")
        .join(rel)
}

/// The scene of a load that must succeed; the test fails with every error it reported.
pub fn scene_of(loaded: rtc::ir::Loaded, path: &Path) -> Scene {
    let errors: Vec<String> = loaded
        .diagnostics
        .items
        .iter()
        .filter(|d| d.is_error())
        .map(|d| format!("{}: {}", d.code, d.message))
        .collect();
    assert!(errors.is_empty(), "{}: {errors:?}", path.display());
    loaded
        .scene
        .unwrap_or_else(|| panic!("{}: no scene", path.display()))
}

/// The course default camera for `eye` (COURSE.md §2.4).
pub fn course_camera(eye: DVec3) -> Camera {
    Camera {
        eye,
        center: DVec3::new(200.0, 200.0, 0.0),
        up: DVec3::Y,
        width: 400,
        height: 400,
        projection: Projection::Course,
        aperture: 0.0,
        focus_distance: 0.0,
        shutter: None,
        motion: None,
        span: Span::default(),
    }
}

/// A material with the course's keys; `reflect = ks` as the course front end sets it.
pub fn mat(color: [f64; 3], ka: f64, kd: f64, ks: f64, n: f64) -> Material {
    Material {
        color: DVec3::from(color),
        ka,
        kd,
        ks,
        n,
        reflect: ks,
        ..Material::default()
    }
}

/// A white or coloured point light.
pub fn light(pos: [f64; 3], color: [f64; 3]) -> Light {
    Light::new(
        LightKind::Point {
            position: DVec3::from(pos),
        },
        DVec3::from(color),
        Span::default(),
    )
}

/// Adds a sphere with its own material.
pub fn sphere(scene: &mut Scene, center: [f64; 3], radius: f64, m: Material) {
    let id = scene.add_material(m);
    scene.objects.push(Object {
        motion: None,
        shape: Shape::Sphere {
            center: DVec3::from(center),
            radius,
        },
        transform: rtc::ir::Transform::IDENTITY,
        material: Some(id),
        span: Span::default(),
        visibility: Default::default(),
    });
}

/// An empty scene with the course default camera.
pub fn empty(eye: [f64; 3]) -> Scene {
    Scene {
        camera: course_camera(DVec3::from(eye)),
        lights: vec![],
        materials: vec![],
        textures: vec![],
        objects: vec![],
        settings: RenderSettings::default(),
        memory: Default::default(),
    }
}

/// scene01: five spheres of radius 50, one white light, eye (200,200,1000).
pub fn scene01() -> Scene {
    let mut s = empty([200.0, 200.0, 1000.0]);
    s.lights
        .push(light([-200.0, 600.0, 1500.0], [1.0, 1.0, 1.0]));
    sphere(
        &mut s,
        [90.0, 320.0, 100.0],
        50.0,
        mat([0.0, 0.0, 1.0], 0.2, 0.7, 0.5, 64.0),
    );
    sphere(
        &mut s,
        [210.0, 270.0, 300.0],
        50.0,
        mat([0.0, 1.0, 0.0], 0.2, 0.3, 0.5, 8.0),
    );
    sphere(
        &mut s,
        [290.0, 170.0, 150.0],
        50.0,
        mat([1.0, 0.0, 0.0], 0.2, 0.7, 0.8, 32.0),
    );
    sphere(
        &mut s,
        [140.0, 220.0, 400.0],
        50.0,
        mat([1.0, 0.8, 0.0], 0.2, 0.8, 0.0, 1.0),
    );
    sphere(
        &mut s,
        [110.0, 130.0, 200.0],
        50.0,
        mat([1.0, 0.5, 0.0], 0.2, 0.8, 0.5, 32.0),
    );
    s
}

/// scene01 plus the grey backdrop sphere and shadows (scene01-shadows.yaml).
pub fn scene01_shadows() -> Scene {
    let mut s = scene01();
    sphere(
        &mut s,
        [200.0, 200.0, -1000.0],
        1000.0,
        mat([0.4, 0.4, 0.4], 0.2, 0.8, 0.0, 1.0),
    );
    s.settings.shadows = true;
    s
}

/// Per-channel difference statistics between two images of the same size.
#[derive(Debug, Clone, Copy)]
pub struct Diff {
    /// Largest absolute channel difference.
    pub max: u8,
    /// Mean absolute channel difference.
    pub mean: f64,
    /// Share of pixels with some channel differing by more than 1.
    pub over1: f64,
}

/// Compares `got` with a reference PNG (alpha ignored).
pub fn diff(got: &Image, reference: &Path) -> Diff {
    let want = image::open(reference)
        .unwrap_or_else(|e| panic!("reference {}: {e}", reference.display()))
        .to_rgb8();
    assert_eq!(got.dimensions(), want.dimensions(), "image size");
    let (mut max, mut sum, mut over) = (0u8, 0u64, 0usize);
    for (a, b) in got.pixels().zip(want.pixels()) {
        let mut px = 0u8;
        for c in 0..3 {
            let d = a[c].abs_diff(b[c]);
            px = px.max(d);
            sum += u64::from(d);
        }
        max = max.max(px);
        over += usize::from(px > 1);
    }
    let n = f64::from(got.width() * got.height());
    Diff {
        max,
        mean: sum as f64 / (3.0 * n),
        over1: over as f64 / n,
    }
}
