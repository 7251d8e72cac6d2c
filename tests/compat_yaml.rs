//! The course YAML front end on the official scenes and on the student extensions.

use rtc::num::Norm;
use std::path::{Path, PathBuf};

use glam::DVec3;
use rtc::compat::{load_yaml, load_yaml_source};
use rtc::ir::Loaded;
use rtc::ir::{
    DepthRange, Mapping, Projection, RenderMode, Sampling, ShadingModel, Shape, Texture,
};
use rtc::source::SourceMap;

const YAML: &str = "tests/data/course/yaml";

fn load(rel: &str) -> (Loaded, SourceMap) {
    let mut sources = SourceMap::new();
    let loaded = load_yaml(&Path::new(YAML).join(rel), &mut sources);
    (loaded, sources)
}

fn describe(loaded: &Loaded, sources: &SourceMap) -> String {
    loaded
        .diagnostics
        .items
        .iter()
        .map(|d| {
            let at = d.span.map_or(String::new(), |s| {
                let (l, c) = sources.get(s.file).line_col(s.start as usize);
                format!("{l}:{c}")
            });
            format!("{} {} {} {}", d.severity.as_str(), at, d.code, d.message)
        })
        .collect::<Vec<_>>()
        .join("\n")
}

fn official_files() -> Vec<PathBuf> {
    let mut files = Vec::new();
    for dir in [YAML.to_string(), format!("{YAML}/uoit")] {
        for e in std::fs::read_dir(&dir).expect("course yaml folder") {
            let p = e.expect("dir entry").path();
            let name = p.file_name().and_then(|n| n.to_str()).unwrap_or("");
            // The 2009 first draft has the 4-element colour typo: a negative case (see below).
            if p.extension().is_some_and(|x| x == "yaml") && !name.contains("2009-01-01-first") {
                files.push(p);
            }
        }
    }
    files.sort();
    files
}

#[test]
fn every_official_scene_loads_without_errors_or_warnings() {
    let files = official_files();
    assert!(files.len() >= 24, "found only {} files", files.len());
    for path in files {
        let mut sources = SourceMap::new();
        let loaded = load_yaml(&path, &mut sources);
        let text = describe(&loaded, &sources);
        assert!(
            loaded.diagnostics.items.is_empty(),
            "{}:\n{text}",
            path.display()
        );
        assert!(loaded.scene.is_some(), "{}", path.display());
    }
}

fn scene_of(rel: &str) -> rtc::ir::Scene {
    let (loaded, sources) = load(rel);
    assert!(
        !loaded.diagnostics.has_errors(),
        "{rel}:\n{}",
        describe(&loaded, &sources)
    );
    loaded.scene.expect("a scene")
}

fn codes_of(text: &str) -> Vec<&'static str> {
    let loaded = load_yaml_source(Path::new("t.yaml"), text, &mut SourceMap::new());
    loaded.diagnostics.items.iter().map(|d| d.code).collect()
}

#[test]
fn render_modes_map_onto_the_ir() {
    assert_eq!(
        scene_of("scene01-phong.yaml").settings.mode,
        RenderMode::Shaded
    );
    assert_eq!(
        scene_of("scene01-normal.yaml").settings.mode,
        RenderMode::Normal
    );
    assert_eq!(
        scene_of("scene01-zbuffer.yaml").settings.mode,
        RenderMode::Depth(DepthRange::Auto)
    );
    let gooch = scene_of("scene01-gooch.yaml").settings;
    assert_eq!(gooch.mode, RenderMode::Shaded);
    let ShadingModel::Gooch(p) = gooch.shading else {
        panic!("not gooch: {:?}", gooch.shading)
    };
    assert_eq!((p.b, p.y, p.alpha, p.beta), (0.55, 0.3, 0.25, 0.5));
}

#[test]
fn shadows_depth_and_supersampling() {
    let s = scene_of("scene01-zoom-ss-reflect-lights-shadows.yaml").settings;
    assert!(s.shadows);
    assert_eq!(s.max_depth, 2);
    assert_eq!(s.sampling, Sampling::Grid { factor: 4 });
    let plain = scene_of("scene01.yaml").settings;
    assert!(!plain.shadows);
    assert_eq!(plain.max_depth, 0);
    assert_eq!(plain.sampling, Sampling::Grid { factor: 1 });
}

#[test]
fn camera_block_gives_the_course_camera() {
    let zoom = scene_of("scene01-zoom-ss-reflect-lights-shadows.yaml").camera;
    assert_eq!(zoom.projection, Projection::Course);
    assert_eq!(zoom.up, DVec3::new(0.0, 0.75, 0.0));
    assert_eq!((zoom.width, zoom.height), (800, 400));
    // The official "camera" scene spells out the default view: same camera as Eye alone.
    let explicit = scene_of("scene01-camera-ss-reflect-lights-shadows.yaml").camera;
    let default = scene_of("scene01-reflect-lights-shadows.yaml").camera;
    assert_eq!(
        (
            explicit.eye,
            explicit.center,
            explicit.up,
            explicit.width,
            explicit.height
        ),
        (
            default.eye,
            default.center,
            default.up,
            default.width,
            default.height
        )
    );
}

#[test]
fn textured_spheres_are_oriented_by_pole_and_angle() {
    let s = scene_of("blue-earth.yaml");
    let earth = &s.objects[0];
    assert_eq!(
        earth.shape,
        Shape::Sphere {
            center: DVec3::ZERO,
            radius: 6378.1
        }
    );
    let pole = DVec3::new(0.0, 0.917_407_699_357_488_3, -0.397_948_631_307_610_4);
    let north = earth.transform.affine().transform_vector3(DVec3::Y);
    assert!((north - pole.unit()).norm() < 1e-9, "{north}");
    assert_eq!(
        earth.transform.affine().translation,
        DVec3::new(0.0, 0.0, 149_597_890.0)
    );
    let m = s.material(earth.material.expect("material"));
    let tex = m.texture.expect("texture");
    let Texture::Image { path, mapping, .. } = &s.textures[tex.0 as usize] else {
        panic!("not an image texture")
    };
    assert_eq!(*mapping, Mapping::Spherical);
    assert!(
        path.ends_with("bluegrid.png") && path.is_file(),
        "{}",
        path.display()
    );
    assert_eq!(s.lights[0].color, DVec3::new(1.5, 1.0, 1.5));
}

#[test]
fn uoit_reflect_refract_eta_are_explicit() {
    let s = scene_of("uoit/scene06.yaml");
    let reflects: Vec<f64> = s.materials.iter().map(|m| m.reflect).collect();
    assert!(reflects.contains(&0.9), "{reflects:?}");
    let glass = s
        .materials
        .iter()
        .find(|m| m.refract > 0.0)
        .expect("a refracting material");
    assert_eq!((glass.refract, glass.eta), (0.9, 1.5));
}

#[test]
fn student_geometry_spellings_map_onto_ir_shapes() {
    let s = scene_of("student-extensions/scene01-additional-geometry__cpo.yaml");
    let kinds: Vec<&str> = s.objects.iter().map(|o| o.shape.kind_name()).collect();
    assert_eq!(
        kinds,
        vec!["box", "sphere", "quad", "cylinder", "triangle", "plane"]
    );
    let t = scene_of("student-extensions/scene03-triangles__jes.yaml");
    assert_eq!(
        t.objects
            .iter()
            .filter(|o| o.shape.kind_name() == "triangle")
            .count(),
        3
    );
    let tl = scene_of("student-extensions/scene01-triangle__tlos.yaml");
    assert!(
        tl.objects
            .iter()
            .any(|o| matches!(o.shape, Shape::Triangle { .. }))
    );
    let cyl = scene_of("student-extensions/scene01-cylinder__tlos.yaml");
    assert!(cyl.settings.shadows, "`shadow: true` is read as Shadows");
    assert!(
        cyl.objects
            .iter()
            .any(|o| matches!(o.shape, Shape::Cylinder { .. }))
    );
    let plane = scene_of("student-extensions/scene03__gui.yaml");
    assert!(matches!(plane.objects[4].shape, Shape::Plane { normal, .. } if normal == DVec3::Y));
    let mesh = scene_of("student-extensions/scene05-dolphins__jes.yaml");
    assert!(
        matches!(&mesh.objects[1].shape, Shape::Mesh { source: rtc::ir::MeshSource::File(path), .. } if path.ends_with("dolphins.obj"))
    );
}

#[test]
fn student_files_that_cannot_load_say_why() {
    let (ole, _) = load("student-extensions/dolphins__ole.yaml");
    let errors: Vec<&str> = ole
        .diagnostics
        .items
        .iter()
        .filter(|d| d.is_error())
        .map(|d| d.code)
        .collect();
    assert_eq!(
        errors,
        vec![
            "rtc::yaml::missing_key",
            "rtc::yaml::missing_key",
            "rtc::yaml::missing_key",
        ],
        "its Camera uses position/lookat/resolution; the model is found in models/ by name"
    );
    let (cpo, _) = load("student-extensions/scene01-reflect-refract-lights-shadows__cpo.yaml");
    let errors: Vec<&str> = cpo
        .diagnostics
        .items
        .iter()
        .filter(|d| d.is_error())
        .map(|d| d.code)
        .collect();
    assert_eq!(
        errors,
        vec!["rtc::compat::out_of_range"],
        "yellow: kt 0.4 with eta 0"
    );
}

#[test]
fn student_spellings_warn_but_load() {
    let warned = codes_of(
        "Eye: [0,0,10]\nrenderMode: \"PHONG\"\nshadow: true\nSuperSampling: 2\nLights: []\nObjects: []\n",
    );
    assert_eq!(
        warned,
        vec![
            "rtc::yaml::spelling",
            "rtc::yaml::spelling",
            "rtc::yaml::spelling",
            "rtc::yaml::spelling"
        ]
    );
}

#[test]
fn the_2009_typo_colour_with_four_components_is_rejected() {
    let (loaded, sources) = load("scene01__mhe-2009-01-01-first.yaml");
    let d = &loaded.diagnostics.items[0];
    assert_eq!(d.code, "rtc::yaml::arity");
    assert_eq!(
        d.help.as_deref(),
        Some("a colour has three components: [r, g, b]")
    );
    let span = d.span.expect("span");
    assert_eq!(sources.snippet(span), "[1.0,1,0,1.0]");
    assert!(loaded.scene.is_none());
}

#[test]
fn both_list_indentations_read_the_same() {
    let flush = "Eye: [1,2,3]\nLights:\n- position: [0,0,0]\n  color: [1,1,1]\nObjects: []\n";
    let indented =
        "Eye: [1,2,3]\nLights:\n    - position: [0,0,0]\n      color: [1,1,1]\nObjects: []\n";
    let mut sources = SourceMap::new();
    let a = load_yaml_source(Path::new("a.yaml"), flush, &mut sources)
        .scene
        .expect("flush");
    let b = load_yaml_source(Path::new("b.yaml"), indented, &mut sources)
        .scene
        .expect("indented");
    assert_eq!(rtc::compat::erase_spans(&a), rtc::compat::erase_spans(&b));
}

#[test]
fn camera_wins_over_eye_with_a_warning() {
    let text = "Eye: [1,2,3]\nCamera:\n  eye: [0,0,5]\n  center: [0,0,0]\n  up: [0,2,0]\n  viewSize: [10,20]\nLights: []\nObjects: []\n";
    let loaded = load_yaml_source(Path::new("t.yaml"), text, &mut SourceMap::new());
    let codes: Vec<&str> = loaded.diagnostics.items.iter().map(|d| d.code).collect();
    assert_eq!(codes, vec!["rtc::compat::camera_override"]);
    let cam = loaded.scene.expect("scene").camera;
    assert_eq!(
        (cam.eye, cam.width, cam.height),
        (DVec3::new(0.0, 0.0, 5.0), 10, 20)
    );
}
