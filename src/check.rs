//! `rtc check` as a library function: the scene lints (lights that light nothing, a camera
//! inside an object, effects that cannot show) and the preparation stage's findings (shapes,
//! transforms, CSG operands, meshes, textures decoded, ids, limits), so a clean check means the
//! render will start. Nothing here changes the scene.

use glam::DVec3;

use crate::diag::{Diagnostic, Diagnostics};
use crate::ir::{AmbientConvention, LightKind, Object, RenderMode, Scene, Shape};
use crate::opt::{Content, Effects};

/// Every finding about an evaluated scene: the lints, then what preparing it reports.
pub fn check(scene: &Scene) -> Diagnostics {
    let mut out = lint(scene);
    out.extend(crate::opt::validate(scene));
    out
}

/// Runs every scene lint.
pub fn lint(scene: &Scene) -> Diagnostics {
    let mut out = Diagnostics::default();
    no_lights(scene, &mut out);
    // One pass over the objects for the lints that look at each (a million objects make
    // every pass cost): enclosed points now, the moving objects' spans for later.
    let see_motion = !scene.camera.shutter.is_some_and(|s| s.is_open());
    let mut moving = Vec::new();
    for o in &scene.objects {
        enclosed_points(scene, o, &mut out);
        if see_motion {
            moving_spans(o, &mut moving);
        }
    }
    invisible_bounces(scene, &mut out);
    if see_motion {
        invisible_motion(scene, moving, &mut out);
    }
    out
}

/// The spans of `o` and its CSG operands that move, each once, added to `spans`.
fn moving_spans(o: &Object, spans: &mut Vec<crate::source::Span>) {
    if o.motion.is_some() && !spans.contains(&o.span) {
        spans.push(o.span);
    }
    if let Shape::Csg { children, .. } = &o.shape {
        children.iter().for_each(|c| moving_spans(c, spans));
    }
}

/// Motion the film cannot see: something moves (the objects at `spans`, or the camera) but the
/// camera's shutter is not open.
fn invisible_motion(scene: &Scene, mut spans: Vec<crate::source::Span>, out: &mut Diagnostics) {
    let help = "open the shutter over the motion, e.g. `camera { ..., shutter: [0, 1] }` (fractions of a frame), or remove `.moving(...)`";
    if scene.camera.motion.is_some() {
        spans.push(scene.camera.span);
    }
    for span in spans {
        out.push(
            Diagnostic::warning("rtc::motion::invisible", span, "this motion is not visible")
                .with_label("it moves, but the camera's shutter is closed (an instant)")
                .with_help(help),
        );
    }
}

fn no_lights(scene: &Scene, out: &mut Diagnostics) {
    let shaded = scene.settings.mode == RenderMode::Shaded;
    if shaded && scene.lights.is_empty() && !scene.objects.is_empty() {
        out.push(
            Diagnostic::warning(
                "rtc::scene::no_lights",
                scene.camera.span,
                "the scene has no lights",
            )
            .with_label(if scene.settings.ambient == AmbientConvention::Once {
                "only the ambient term lights the image: no diffuse shading, highlights or shadows"
            } else {
                "with no light the image is black (Phong's ambient term is per light)"
            })
            .with_help("add a light, e.g. `point_light { position: [5, 8, 5] }`"),
        );
    }
}

/// The world-space sphere of an opaque object that is a plain (possibly similarity-transformed) sphere.
fn opaque_sphere(scene: &Scene, o: &Object) -> Option<(DVec3, f64)> {
    let Shape::Sphere { center, radius } = o.shape else {
        return None;
    };
    let transparent = o.material.is_some_and(|m| scene.material(m).refract > 0.0);
    if transparent {
        return None;
    }
    let m = o.transform.matrix3;
    let scales = [m.x_axis.length(), m.y_axis.length(), m.z_axis.length()];
    let uniform = (scales[0] - scales[1]).abs() < 1e-9 * scales[0]
        && (scales[0] - scales[2]).abs() < 1e-9 * scales[0];
    uniform.then(|| (o.transform.transform_point3(center), radius * scales[0]))
}

/// A point light or the camera inside the opaque sphere `o` (if it is one).
fn enclosed_points(scene: &Scene, o: &Object, out: &mut Diagnostics) {
    let Some((c, r)) = opaque_sphere(scene, o) else {
        return;
    };
    for l in &scene.lights {
        let p = l.kind.center();
        if matches!(l.kind, LightKind::Point { .. }) && p.distance(c) < r {
            out.push(
                Diagnostic::warning(
                    "rtc::scene::light_enclosed",
                    l.span,
                    format!(
                        "the light at {p} is inside an opaque sphere; it lights nothing outside it"
                    ),
                )
                .with_label("this light")
                .with_secondary(o.span, "encloses the light")
                .with_help("move the light outside the sphere, or make the sphere refractive"),
            );
        }
    }
    if scene.camera.eye.distance(c) < r {
        out.push(
            Diagnostic::warning(
                "rtc::scene::camera_enclosed",
                scene.camera.span,
                "the camera is inside an opaque sphere; the image will show only its inside",
            )
            .with_label("this camera")
            .with_secondary(o.span, "encloses the eye")
            .with_help("move `eye` outside the sphere"),
        );
    }
}

fn invisible_bounces(scene: &Scene, out: &mut Diagnostics) {
    if scene.settings.mode != RenderMode::Shaded || scene.settings.max_depth > 0 {
        return;
    }
    if let Some(m) = scene.materials.iter().find(|m| m.refract > 0.0) {
        out.push(
            Diagnostic::warning(
                "rtc::scene::refraction_unseen",
                m.span,
                "this material refracts, but `max_depth` is 0, so no refracted ray is traced",
            )
            .with_label("refract > 0 here")
            .with_help("set `max_depth` to at least 2 in `render { ... }` (a glass sphere needs two bounces)"),
        );
    }
}

/// `kind` in the plural when `count` is not one ("box" → "boxes").
fn plural(kind: &str, count: usize) -> String {
    match (kind, count) {
        ("csg", 1) => "CSG object".to_string(),
        ("csg", _) => "CSG objects".to_string(),
        (_, 1) => kind.to_string(),
        ("torus", _) => "tori".to_string(),
        _ if kind.ends_with('x') || kind.ends_with('h') => format!("{kind}es"),
        _ => format!("{kind}s"),
    }
}

/// A one-line summary of an evaluated scene: objects by kind, lights, camera, effects.
pub fn summary(scene: &Scene) -> String {
    let mut kinds: Vec<(&str, usize)> = Vec::new();
    // The effects' object content is gathered in the same pass as the kinds.
    let mut content = Content::without_objects(scene);
    for o in &scene.objects {
        content.visit(o);
        let k = o.shape.kind_name();
        match kinds.iter_mut().find(|(n, _)| *n == k) {
            Some((_, c)) => *c += 1,
            None => kinds.push((k, 1)),
        }
    }
    let kinds = kinds
        .iter()
        .map(|(k, c)| format!("{c} {}", plural(k, *c)))
        .collect::<Vec<_>>()
        .join(", ");
    let objects = scene.objects.len();
    let lights = scene.lights.len();
    let kinds = if kinds.is_empty() {
        String::new()
    } else {
        format!(" ({kinds})")
    };
    format!(
        "{objects} object{}{kinds}, {lights} light{}, camera {}x{}; effects: {}",
        if objects == 1 { "" } else { "s" },
        if lights == 1 { "" } else { "s" },
        scene.camera.width,
        scene.camera.height,
        Effects::new(&content, &scene.settings, &scene.camera)
    )
}
