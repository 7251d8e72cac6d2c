//! The rtc back end round trip: every scene of the repository that evaluates without errors
//! (`scenes/` and its folders, `tests/lang/*.rtc`, `tests/diagnostics/*.rtc`) is written back
//! as rtc source by `rtc::convert::to_source` (what `rtc convert` writes), the text is
//! evaluated again, and the two IR scenes are the same: spans apart, materials and textures
//! compared by what they are (equal materials share one `let`, so their ids change), asset and
//! output paths canonical. A scene whose mesh is missing (an asset outside the repository) is
//! skipped with a message.

mod cli_support;

use std::path::{Component, Path, PathBuf};

use rtc::eval::{EvalOptions, load_file};
use rtc::ir::{Bump, Material, MaterialId, Object, RenderSettings, Scene, Shape, Texture};
use rtc::pattern::Pattern;
use rtc::pattern::program::{Op, Program};
use rtc::source::{SourceMap, Span};
use std::sync::Arc;

use glam::DVec3;

use cli_support::{files_below, scratch};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every scene file of the corpus, sorted: `scenes/` (with its folders), the top level of
/// `tests/lang` and `tests/diagnostics`, and `tests/data/convert` (scenes that use every part of
/// the IR).
fn corpus() -> Vec<PathBuf> {
    let mut files = files_below(&root().join("scenes"), &["rtc"]);
    for dir in ["tests/lang", "tests/diagnostics", "tests/data/convert"] {
        let mut here: Vec<PathBuf> = std::fs::read_dir(root().join(dir))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.is_file() && p.extension().is_some_and(|e| e == "rtc"))
            .collect();
        here.sort();
        files.extend(here);
    }
    files
}

/// `p` absolute and without `.`, `..` and symbolic links where the file exists.
fn canonical(p: &Path) -> PathBuf {
    std::fs::canonicalize(p).unwrap_or_else(|_| {
        let mut out = PathBuf::new();
        for c in p.components() {
            match c {
                Component::ParentDir => {
                    out.pop();
                }
                Component::CurDir => {}
                other => out.push(other),
            }
        }
        out
    })
}

/// A texture as what it is: canonical path, no span.
fn texture(t: &Texture) -> Texture {
    match t {
        Texture::Image {
            path,
            mapping,
            filter,
            ..
        } => Texture::Image {
            path: canonical(path),
            mapping: *mapping,
            filter: *filter,
            span: Span::default(),
        },
        Texture::Pattern(p) => {
            let mut p = p.clone();
            if let Pattern::Function(f) = &p.field.pattern {
                p.field.pattern = Pattern::Function(values(f));
            }
            Texture::Pattern(p)
        }
        other => other.clone(),
    }
}

/// A compiled function as what it computes: its values at fixed points, held as the constants
/// of a program (the written function compiles to other operations computing the same bits).
fn values(f: &Program) -> Arc<Program> {
    let ops = (0..64u16)
        .map(|i| {
            let k = f64::from(i);
            let p = DVec3::new(
                libm::sin(1.7 * k) * 2.1,
                libm::cos(0.9 * k) * 1.3,
                (k - 32.0) * 0.07,
            );
            let v = f.run(p);
            Op::Const {
                dst: 3 + i,
                // NaN is never equal to itself: its bits stand for it.
                value: if v.is_nan() {
                    f64::from_bits(v.to_bits() >> 12)
                } else {
                    v
                },
            }
        })
        .collect();
    Arc::new(Program::new(ops, 3).expect("a valid program"))
}

/// A material as what it is: no span, its textures resolved.
#[derive(Debug, PartialEq)]
struct Look {
    material: Material,
    texture: Option<Texture>,
    bump: Option<(Texture, f64)>,
}

/// A scene in comparable form: materials numbered in order of first use (equal ones share a
/// number), spans erased, paths canonical.
#[derive(Debug, PartialEq)]
struct Canon {
    camera: rtc::ir::Camera,
    lights: Vec<rtc::ir::Light>,
    settings: RenderSettings,
    looks: Vec<Look>,
    objects: Vec<Object>,
}

fn canon(scene: &Scene) -> Canon {
    let mut looks: Vec<Look> = Vec::new();
    let mut number = |id: MaterialId| {
        let m = scene.material(id);
        let look = Look {
            material: Material {
                span: Span::default(),
                texture: None,
                bump: None,
                ..m.clone()
            },
            texture: m.texture.map(|t| texture(&scene.textures[t.0 as usize])),
            bump: m
                .bump
                .map(|Bump { texture: t, scale }| (texture(&scene.textures[t.0 as usize]), scale)),
        };
        let at = looks.iter().position(|l| *l == look).unwrap_or_else(|| {
            looks.push(look);
            looks.len() - 1
        });
        MaterialId(at as u32)
    };
    fn object(o: &Object, number: &mut dyn FnMut(MaterialId) -> MaterialId) -> Object {
        let mut out = o.clone();
        out.span = Span::default();
        out.material = o.material.map(&mut *number);
        match &mut out.shape {
            Shape::Mesh {
                source: rtc::ir::MeshSource::File(path),
                ..
            } => *path = canonical(path),
            Shape::Csg { children, .. } => {
                *children = children.iter().map(|c| object(c, number)).collect();
            }
            Shape::Isosurface { function, .. } => *function = values(function),
            _ => {}
        }
        out
    }
    let mut settings = scene.settings.clone();
    settings.default_material = settings.default_material.map(&mut number);
    settings.output = settings.output.as_deref().map(canonical);
    settings.output_span = None;
    let objects = scene
        .objects
        .iter()
        .map(|o| object(o, &mut number))
        .collect();
    let mut camera = scene.camera.clone();
    camera.span = Span::default();
    let mut lights = scene.lights.clone();
    lights.iter_mut().for_each(|l| l.span = Span::default());
    Canon {
        camera,
        lights,
        settings,
        looks,
        objects,
    }
}

/// What became of one file.
enum Outcome {
    /// Its IR came back the same.
    Same,
    /// It does not evaluate to a scene (errors are its point, or it is a module).
    NotAScene,
    /// An asset it needs is not in the repository, or it holds what cannot be written back.
    Skipped(String),
    /// Its IR came back different: where.
    Differs(String),
}

fn round_trip(path: &Path, dir: &Path) -> Outcome {
    let options = EvalOptions::default();
    let loaded = load_file(path, &mut SourceMap::default(), &options);
    let missing: Vec<String> = loaded
        .diagnostics
        .items
        .iter()
        .filter(|d| d.is_error() && d.code.starts_with("rtc::asset"))
        .map(|d| d.message.clone())
        .collect();
    if !missing.is_empty() {
        return Outcome::Skipped(missing.join("; "));
    }
    let Some(scene) = loaded.scene.filter(|_| !loaded.diagnostics.has_errors()) else {
        return Outcome::NotAScene;
    };
    let text = rtc::convert::to_source(&scene, dir);
    // Compiled functions (an isosurface's `f`, `pattern(f)`) are written back as `fn(p)`
    // literals: never as the string naming why not.
    assert!(
        !text.contains("a compiled function cannot be written back as source"),
        "{}: {text}",
        path.display()
    );
    let name = path
        .strip_prefix(root())
        .unwrap()
        .to_string_lossy()
        .replace('/', "_");
    let out = dir.join(name);
    std::fs::write(&out, &text).unwrap();
    let back = load_file(&out, &mut SourceMap::default(), &options);
    let errors: Vec<String> = back
        .diagnostics
        .items
        .iter()
        .filter(|d| d.is_error())
        .map(|d| format!("{}: {}", d.code, d.message))
        .collect();
    assert!(
        errors.is_empty(),
        "{}: the written text has errors {errors:?}\n{text}",
        path.display()
    );
    let back = back.scene.expect("a scene");
    let (a, b) = (canon(&scene), canon(&back));
    let shown = out.display();
    let part = if a.camera != b.camera {
        format!("camera\n{:?}\n{:?}", a.camera, b.camera)
    } else if a.lights != b.lights {
        format!("lights\n{:?}\n{:?}", a.lights, b.lights)
    } else if a.looks != b.looks {
        format!("materials\n{:?}\n{:?}", a.looks, b.looks)
    } else if a.settings != b.settings {
        format!("settings\n{:?}\n{:?}", a.settings, b.settings)
    } else if a.objects.len() != b.objects.len() {
        format!("{} objects, {} back", a.objects.len(), b.objects.len())
    } else if let Some(i) = (0..a.objects.len()).find(|&i| a.objects[i] != b.objects[i]) {
        format!("object {i}\n{:?}\n{:?}", a.objects[i], b.objects[i])
    } else {
        return Outcome::Same;
    };
    Outcome::Differs(format!("{}: {part}\n(written to {shown})", path.display()))
}

#[test]
fn every_scene_of_the_repository_round_trips_through_rtc_source() {
    let dir = scratch("convert-roundtrip");
    let (mut same, mut skipped, mut not_scenes) = (Vec::new(), Vec::new(), 0);
    let mut differ = Vec::new();
    for path in corpus() {
        let rel = path.strip_prefix(root()).unwrap().display().to_string();
        match round_trip(&path, &dir) {
            Outcome::Same => same.push(rel),
            Outcome::NotAScene => not_scenes += 1,
            Outcome::Skipped(why) => {
                eprintln!("skipped {rel}: {why}");
                skipped.push(rel);
            }
            Outcome::Differs(why) => differ.push(why),
        }
    }
    assert!(
        differ.is_empty(),
        "{} scene(s) differ after the round trip:\n{}",
        differ.len(),
        differ.join("\n\n")
    );
    eprintln!(
        "{} scenes round-trip, {} skipped (missing assets), {not_scenes} files are no scene",
        same.len(),
        skipped.len()
    );
    for must in [
        "scenes/motion_blur.rtc",
        "scenes/showcase.rtc",
        "scenes/gallery.rtc",
        "tests/data/convert/everything.rtc",
        "tests/data/convert/course_camera.rtc",
    ] {
        assert!(same.iter().any(|s| s == must), "{must} round-trips");
    }
    assert!(same.len() >= 40, "only {} scenes round-trip", same.len());
    let _ = std::fs::remove_dir_all(&dir);
}
