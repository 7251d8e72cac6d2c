//! What every rtc fuzz target does after its front end: check the promises a loaded scene makes
//! (every diagnostic span lies on character boundaries inside a known file) and push the scene
//! through the later stages the CLI runs (`check`'s lints, geometry validation, a render), with
//! the scene's own sizes clamped so one input stays a few milliseconds.

pub mod mesh;
pub mod texture;

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use rtc::diag::Diagnostic;
use rtc::eval::EvalOptions;
use rtc::ir::{Loaded, Sampling, Scene};
use rtc::render::RenderOptions;
use rtc::source::{SourceMap, Span};

/// Evaluation budgets for fuzzing: small, so that an input which loops, recurses or emits
/// without end stops with a budget error within milliseconds. (The budgets themselves are what
/// is under test: an input that hangs at these sizes is a finding.)
pub fn eval_options() -> EvalOptions {
    EvalOptions {
        max_loop_iterations: 20_000,
        max_recursion_depth: 64,
        max_objects: 2_000,
        max_list_len: 20_000,
        max_string_len: 100_000,
        ..EvalOptions::default()
    }
}

/// The rtc checkout this crate lives in (scene paths resolve against it, so seeds that name
/// assets next to them find them).
pub fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// A private scratch directory in memory for inputs that rtc reads by path (meshes, images).
pub fn scratch() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let base = if Path::new("/dev/shm").is_dir() {
            PathBuf::from("/dev/shm")
        } else {
            std::env::temp_dir()
        };
        let dir = base.join(format!("rtc-fuzz-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("create the scratch directory");
        dir
    })
}

/// Checks a front end's result and runs the later stages on its scene. `scene_iff_no_errors`:
/// the front end promises a scene exactly when it reported no error (the course readers do).
pub fn after_load(loaded: Loaded, sources: &SourceMap, scene_iff_no_errors: bool) {
    for d in &loaded.diagnostics.items {
        spans_ok(d, sources);
    }
    if scene_iff_no_errors {
        assert_eq!(
            loaded.scene.is_some(),
            !loaded.diagnostics.has_errors(),
            "{:?}",
            loaded.diagnostics.items
        );
    }
    if let Some(scene) = loaded.scene {
        later_stages(scene, sources);
    }
}

/// A source map for scenes built in code: their spans are the default, 0..0 in file 0.
pub fn synthetic_sources() -> SourceMap {
    let mut sources = SourceMap::new();
    sources.add("fuzz-generated scene", "");
    sources
}

/// `rtc check`'s lints and the preparation stage (geometry, meshes, textures), then a render of
/// at most 4×4 pixels with every AOV layer.
pub fn later_stages(mut scene: Scene, sources: &SourceMap) {
    clamp_work(&mut scene);
    for d in &rtc::check::lint(&scene).items {
        spans_ok(d, sources);
    }
    let prepared = match rtc::opt::prepare(&scene) {
        Ok(p) => p,
        Err(problems) => {
            for d in &problems.items {
                spans_ok(d, sources);
            }
            return;
        }
    };
    for d in prepared.warnings() {
        spans_ok(d, sources);
    }
    // The AOV layers too: their paths (depth, normal, albedo, object id) run only when asked for.
    let options = RenderOptions {
        threads: 1,
        aovs: rtc::render::Channel::AOVS.to_vec(),
        ..RenderOptions::default()
    };
    if let Ok(film) = rtc::render::render(&prepared, &options, &rtc::render::Silent) {
        let _ = film.to_image();
    }
}

/// Keeps one render to a handful of rays: at most 4×4 pixels, 2×2 samples and 4 bounces, so an
/// input costs milliseconds (the image and sample budgets themselves are tested in
/// `tests/budgets.rs` and `tests/render_effects.rs`).
fn clamp_work(scene: &mut Scene) {
    let cam = &mut scene.camera;
    cam.width = cam.width.min(4);
    cam.height = cam.height.min(4);
    let s = &mut scene.settings;
    s.max_depth = s.max_depth.min(4);
    s.sampling = match s.sampling {
        Sampling::Grid { factor } => Sampling::Grid {
            factor: factor.min(2),
        },
        Sampling::Adaptive {
            min,
            max,
            threshold,
        } => Sampling::Adaptive {
            min: min.min(2),
            max: max.min(2),
            threshold,
        },
    };
}

fn spans_ok(d: &Diagnostic, sources: &SourceMap) {
    let spans = d
        .span
        .into_iter()
        .chain(d.labels.iter().map(|l| l.span))
        .chain(d.trace.iter().map(|f| f.span));
    for s in spans {
        span_ok(s, sources, d);
    }
}

fn span_ok(s: Span, sources: &SourceMap, d: &Diagnostic) {
    let text = &sources.get(s.file).text;
    let (a, b) = (s.start as usize, s.end as usize);
    assert!(
        a <= b && b <= text.len() && text.is_char_boundary(a) && text.is_char_boundary(b),
        "span {a}..{b} outside or inside a character of a {}-byte file: {d:?}",
        text.len()
    );
}

/// Bytes as the course readers see a file: UTF-8 when valid, otherwise Latin-1 (one character
/// per byte), as `rtc::compat` decodes old course files.
pub fn decode_text(data: &[u8]) -> String {
    match std::str::from_utf8(data) {
        Ok(s) => s.to_owned(),
        Err(_) => data.iter().map(|&b| char::from(b)).collect(),
    }
}
