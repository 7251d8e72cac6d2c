//! `rtc check` as a library function: the scene lints (lights that light nothing, a camera
//! inside an object, effects that cannot show) and the preparation stage's findings (shapes,
//! transforms, CSG operands, meshes, textures decoded, ids, limits), so a clean check means the
//! render will start. Nothing here changes the scene.

mod enclosed;

use crate::diag::{Diagnostic, Diagnostics};
use crate::ir::{AmbientConvention, Object, RenderMode, Scene, Shape};
use crate::opt::{Content, Effects};

/// Every finding about an evaluated scene: the lints, then what preparing it reports. One pass
/// over the objects serves both (a million objects make every pass cost).
pub fn check(scene: &Scene) -> Diagnostics {
    walk(scene, &scene.objects, None)
}

/// [`check`] and [`summary`] of a scene not needed afterwards (`rtc check`): one pass over the
/// objects serves the lints, the preparation's checks and the summary, and frees each object
/// once visited (no pass of its own to drop them).
pub fn check_owned(mut scene: Scene) -> (Diagnostics, String) {
    let objects = std::mem::take(&mut scene.objects);
    let mut survey = Survey::new(&scene, objects.len());
    let diags = walk(&scene, objects, Some(&mut survey));
    (diags, survey.finish(&scene))
}

/// [`check`] over `objects`, the scene's (which `scene.objects` may no longer hold), each also
/// given to `survey`.
fn walk<O: std::borrow::Borrow<Object>>(
    scene: &Scene,
    objects: impl IntoIterator<Item = O, IntoIter: ExactSizeIterator>,
    mut survey: Option<&mut Survey>,
) -> Diagnostics {
    let objects = objects.into_iter();
    let mut lints = Lints::new(scene, objects.len() == 0);
    let mut prepare = crate::opt::Validator::new(scene);
    for o in objects {
        let o = o.borrow();
        lints.object(o);
        prepare.object(o);
        if let Some(s) = survey.as_deref_mut() {
            s.object(o);
        }
    }
    let mut out = lints.finish();
    out.extend(prepare.finish());
    out
}

/// Runs every scene lint.
pub fn lint(scene: &Scene) -> Diagnostics {
    let mut lints = Lints::new(scene, scene.objects.is_empty());
    for o in &scene.objects {
        lints.object(o);
    }
    lints.finish()
}

/// The scene lints, fed the objects one at a time: enclosed points as each comes, the moving
/// objects' spans for the end.
struct Lints<'a> {
    scene: &'a Scene,
    out: Diagnostics,
    see_motion: bool,
    moving: Vec<crate::source::Span>,
    enclosures: enclosed::Enclosures,
}

impl<'a> Lints<'a> {
    /// The lints of `scene`, whose objects (none if `no_objects`) come next.
    fn new(scene: &'a Scene, no_objects: bool) -> Lints<'a> {
        let mut out = Diagnostics::default();
        no_lights(scene, no_objects, &mut out);
        Lints {
            scene,
            out,
            see_motion: !scene.camera.shutter.is_some_and(|s| s.is_open()),
            moving: Vec::new(),
            enclosures: enclosed::Enclosures::new(),
        }
    }

    fn object(&mut self, o: &Object) {
        self.enclosures.object(self.scene, o);
        if self.see_motion {
            moving_spans(o, &mut self.moving);
        }
    }

    fn finish(mut self) -> Diagnostics {
        self.enclosures.finish(self.scene, &mut self.out);
        invisible_bounces(self.scene, &mut self.out);
        if self.see_motion {
            invisible_motion(self.scene, self.moving, &mut self.out);
        }
        self.out
    }
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

fn no_lights(scene: &Scene, no_objects: bool, out: &mut Diagnostics) {
    let shaded = scene.settings.mode == RenderMode::Shaded;
    let s = &scene.settings;
    // The path tracer is lit by what emits, too: glowing surfaces and the environment.
    let path_lit = matches!(s.integrator, crate::ir::Integrator::Path(_))
        && (s.background != glam::DVec3::ZERO
            || s.sky.is_some()
            || scene
                .materials
                .iter()
                .any(|m| m.emission != glam::DVec3::ZERO));
    if shaded && scene.lights.is_empty() && !no_objects && !path_lit {
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

fn invisible_bounces(scene: &Scene, out: &mut Diagnostics) {
    let path = matches!(scene.settings.integrator, crate::ir::Integrator::Path(_));
    if scene.settings.mode != RenderMode::Shaded || scene.settings.max_depth > 0 || path {
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
    let mut survey = Survey::new(scene, scene.objects.len());
    for o in &scene.objects {
        survey.object(o);
    }
    survey.finish(scene)
}

/// What [`summary`] gathers, fed the objects one at a time: the kinds and, in the same pass, the
/// effects' object content.
struct Survey {
    objects: usize,
    kinds: Vec<(&'static str, usize)>,
    content: Content,
}

impl Survey {
    fn new(scene: &Scene, objects: usize) -> Survey {
        Survey {
            objects,
            kinds: Vec::new(),
            content: Content::without_objects(scene),
        }
    }

    fn object(&mut self, o: &Object) {
        self.content.visit(o);
        let k = o.shape.kind_name();
        match self.kinds.iter_mut().find(|(n, _)| *n == k) {
            Some((_, c)) => *c += 1,
            None => self.kinds.push((k, 1)),
        }
    }

    fn finish(self, scene: &Scene) -> String {
        let kinds = self
            .kinds
            .iter()
            .map(|(k, c)| format!("{c} {}", plural(k, *c)))
            .collect::<Vec<_>>()
            .join(", ");
        let objects = self.objects;
        let lights = scene.lights.len();
        let kinds = if kinds.is_empty() {
            String::new()
        } else {
            format!(" ({kinds})")
        };
        let effects = Effects::new(&self.content, &scene.settings, &scene.camera);
        let patterns = if effects.textures || effects.bump {
            patterns(scene)
        } else {
            String::new()
        };
        format!(
            "{objects} object{}{kinds}, {lights} light{}, camera {}x{}; effects: {effects}{patterns}",
            if objects == 1 { "" } else { "s" },
            if lights == 1 { "" } else { "s" },
            scene.camera.width,
            scene.camera.height,
        )
    }
}

/// The patterns the scene's materials read, for the effects line: `; patterns: marble, granite
/// (bump: wrinkles)` (each name once, in first use; empty without patterns).
fn patterns(scene: &Scene) -> String {
    let name = |t: crate::ir::TextureId| match scene.textures.get(t.0 as usize) {
        Some(crate::ir::Texture::Pattern(p)) => Some(p.name()),
        _ => None,
    };
    let (mut colour, mut bump) = (Vec::new(), Vec::new());
    let add = |list: &mut Vec<&'static str>, n: Option<&'static str>| {
        if let Some(n) = n.filter(|n| !list.contains(n)) {
            list.push(n);
        }
    };
    for m in &scene.materials {
        add(&mut colour, m.texture.and_then(name));
        if let Some(crate::ir::Mix::Map { texture, .. }) = m.mix.as_deref() {
            add(&mut colour, name(*texture));
        }
        add(&mut bump, m.bump.and_then(|b| name(b.texture)));
    }
    let mut out = String::new();
    if !colour.is_empty() {
        out = format!("; patterns: {}", colour.join(", "));
    }
    if !bump.is_empty() {
        let sep = if out.is_empty() { "; patterns:" } else { "" };
        out += &format!("{sep} (bump: {})", bump.join(", "));
    }
    out
}
