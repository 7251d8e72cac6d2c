//! `rtc render`: one frame or a range of frames, optionally sharded or progressive.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use rtc::diag::{Diagnostic, IO_ERROR};
use rtc::eval::EvalOptions;
use rtc::ir::Scene;
use rtc::source::SourceMap;

use crate::cli;
use crate::cli::inputs::SceneInputs;
use crate::cli::report::{self, Format};
use crate::cli::{Outcome, outcome_of, usage_error};

/// What `rtc render` was asked to do, besides the frames.
pub(crate) struct RenderJob<'a> {
    pub(crate) file: &'a Path,
    pub(crate) output: Option<PathBuf>,
    pub(crate) threads: usize,
    pub(crate) format: Format,
    pub(crate) show_stats: bool,
    /// `--target-error`, `--time`, `--samples-from`, `--samples-to`.
    pub(crate) progressive: cli::converge::Request,
    /// `--shard K/N`: a share of the pixels of one frame, or with `--frames` a share of the
    /// frames (task K of N renders the frames at positions K, K+N, … of the range).
    pub(crate) shard: Option<rtc::render::shard::Shard>,
    /// AOV layers for an EXR output (`--aov`).
    pub(crate) aovs: Vec<rtc::render::Channel>,
    /// Seconds each frame's command may take (`--time-limit`).
    pub(crate) time_limit: Option<f64>,
}

/// A `--time-limit` value: a finite number of seconds, at least 0.
pub(crate) fn seconds(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(s) if s.is_finite() && s >= 0.0 => Ok(s),
        _ => Err(format!(
            "`{text}` is not a number of seconds (write e.g. `--time-limit 60` or `2.5`)"
        )),
    }
}

/// Renders `--frame N` (one image), or each frame of `--frames` in turn, each evaluated afresh.
pub(crate) fn render_frames(
    job: &RenderJob<'_>,
    frames: Option<&str>,
    inputs: &SceneInputs,
) -> Outcome {
    let Some(range) = frames else {
        return match inputs.options(inputs.frame) {
            Ok(opts) => render(job, &opts, None, job.shard),
            Err(msg) => usage_error(&msg),
        };
    };
    let frames = match cli::frames::parse_range(range) {
        Ok(f) => f,
        Err(msg) => return usage_error(&msg),
    };
    if let Some(o) = &job.output
        && frames.len() > 1
        && !cli::frames::has_pattern(o)
    {
        return usage_error(&format!(
            "every frame would write `{}`: put `{{frame}}` or `####` in the output name, e.g. `-o shot_####.png`",
            o.display()
        ));
    }
    let mine: Vec<i64> = match job.shard {
        Some(s) => frames
            .into_iter()
            .enumerate()
            .filter(|(i, _)| s.deals(*i))
            .map(|(_, f)| f)
            .collect(),
        None => frames,
    };
    let mut written = std::collections::HashMap::new();
    for frame in mine {
        let opts = match inputs.options(frame) {
            Ok(o) => o,
            Err(msg) => return usage_error(&msg),
        };
        let outcome = render(job, &opts, Some(&mut written), None);
        if !matches!(outcome, Outcome::Ok) {
            return outcome;
        }
    }
    Outcome::Ok
}

/// Renders one frame. `written` (animations) maps each output already written to its frame,
/// so two frames never write the same file.
fn render(
    job: &RenderJob<'_>,
    opts: &EvalOptions,
    written: Option<&mut std::collections::HashMap<PathBuf, i64>>,
    pixel_shard: Option<rtc::render::shard::Shard>,
) -> Outcome {
    let RenderJob {
        file,
        threads,
        format,
        show_stats,
        ..
    } = *job;
    let subject = file.display().to_string();
    let load_start = std::time::Instant::now();
    let deadline = job
        .time_limit
        .map(|s| load_start + std::time::Duration::from_secs_f64(s));
    // `--threads` bounds the evaluation's loop parts too; `--time-limit` covers the evaluation.
    let opts = &EvalOptions {
        loop_parts: rtc::eval::LoopParts::Auto { threads },
        deadline,
        ..opts.clone()
    };
    let mut sources = SourceMap::new();
    // The scene lints run with the preparation, under `--time-limit` (they may read meshes).
    let loaded = rtc::loader::load(file, &mut sources, opts);
    let load_time = load_start.elapsed();
    let color = format == Format::Human && std::io::stderr().is_terminal();
    let print = |diags: &[Diagnostic], sources: &SourceMap| {
        let text = report::render(diags, sources, &subject, format, color);
        if !text.is_empty() {
            eprintln!("{}", text.trim_end());
        }
    };
    print(&loaded.diagnostics.items, &sources);
    let outcome = outcome_of(&loaded.diagnostics, false);
    let (Outcome::Ok, Some(scene)) = (&outcome, loaded.scene) else {
        eprintln!("{}", cli::check::count_line(&loaded.diagnostics));
        return outcome;
    };
    let animated = written.is_some();
    if job.output.is_none()
        && let Some(d) = outside_scene_folder(file, &scene)
    {
        print(std::slice::from_ref(&d), &sources);
        return Outcome::SceneErrors;
    }
    let path = cli::frames::numbered(
        &output_path(file, job.output.clone(), &scene, animated),
        opts.frame,
    );
    if let Some(written) = written
        && let Some(other) = written.insert(path.clone(), opts.frame)
    {
        return usage_error(&format!(
            "frames {other} and {} would both write `{}`: put `{{frame}}` or `####` in the output name",
            opts.frame,
            path.display()
        ));
    }
    if !job.aovs.is_empty() {
        // A shard writes a part; the merge's output name decides the format.
        if pixel_shard.is_none()
            && let Err(msg) = cli::aov::check_output(&path)
        {
            return usage_error(&msg);
        }
        if job.progressive.wanted() {
            return usage_error(
                "`--aov` layers come from a fixed-sampling render: drop `--aov`, or `--target-error`, `--time` and `--samples-from`",
            );
        }
    }
    let image_path = path.clone();
    let path = match pixel_shard {
        Some(s) => cli::shard::part_path(job.output.clone(), &path, s),
        None => path,
    };
    // Found now, not after the whole render: a format rtc cannot write, a missing or
    // read-only folder.
    let destination = match pixel_shard {
        Some(_) => rtc::render::output::check_folder(&path),
        None => rtc::render::output::check_destination(&path),
    };
    if let Err(d) = destination {
        print(std::slice::from_ref(&d), &sources);
        return Outcome::IoOrUsage;
    }
    let start = std::time::Instant::now();
    // A part records the scene's fingerprint; taken here, as the preparation consumes the scene.
    let fingerprint = pixel_shard.map(|_| rtc::opt::fingerprint::scene(&scene));
    // The object-id layer's sidecar (beside the image, or in the part for the merge) reads the
    // objects' spans, so it too is made before the preparation.
    let sidecar = job
        .aovs
        .contains(&rtc::render::Channel::Object)
        .then(|| cli::aov::sidecar(&scene, &sources, &image_path));
    let camera = scene.camera.clone();
    let Some((lints, prepared)) = prepare_before(scene, deadline) else {
        let limit = job.time_limit.unwrap_or_default();
        print(&[time_limit_reached(&camera, limit)], &sources);
        return Outcome::SceneErrors;
    };
    print(&lints.items, &sources);
    let prepared = match prepared {
        Ok(p) => p,
        Err(diags) => {
            print(&diags.items, &sources);
            eprintln!("{}", cli::check::count_line(&diags));
            return outcome_of(&diags, false);
        }
    };
    print(prepared.warnings(), &sources);
    let options = rtc::render::RenderOptions {
        threads,
        shard: pixel_shard,
        aovs: job.aovs.clone(),
    };
    let progressive = &job.progressive;
    if progressive.wanted() && pixel_shard.is_some() {
        return usage_error(
            "a progressive render (--target-error, --time, --samples-from) cannot be sharded: its rounds look at the whole image; shard a fixed-sampling render instead",
        );
    }
    let film = if progressive.wanted() {
        cli::converge::render(&prepared, threads, progressive, &path)
    } else {
        let progress = cli::progress::Bar::on_stderr(deadline);
        rtc::render::render(&prepared, &options, &progress).map_err(|d| match job.time_limit {
            Some(limit) if d.code == rtc::render::CANCELLED => {
                time_limit_reached(prepared.camera(), limit)
            }
            _ => d,
        })
    };
    // What the render saw that the scene should change (an isosurface's `max_gradient`).
    print(&prepared.render_warnings(), &sources);
    let result = film.and_then(|film| {
        if show_stats {
            eprintln!(
                "{}",
                cli::stats::describe(&film, &prepared, load_time, start.elapsed())
            );
        }
        match (pixel_shard, fingerprint) {
            (Some(s), Some(fingerprint)) => {
                cli::shard::write_part(&film, file, fingerprint, s, &path, sidecar)
            }
            _ => {
                rtc::render::output::save_film(&film, &path)?;
                match sidecar {
                    Some(json) => cli::aov::write_sidecar(&json, &cli::aov::sidecar_path(&path)),
                    None => Ok(()),
                }
            }
        }
    });
    match result {
        Ok(()) => {
            eprintln!("wrote {}", path.display());
            Outcome::Ok
        }
        Err(d) => {
            let io = d.code == IO_ERROR;
            print(std::slice::from_ref(&d), &sources);
            if io {
                Outcome::IoOrUsage
            } else {
                Outcome::SceneErrors
            }
        }
    }
}

/// What the scene lints find and the preparation of `scene` (meshes loaded, BVHs built).
type Prepare = (
    rtc::diag::Diagnostics,
    Result<rtc::opt::Prepared, rtc::diag::Diagnostics>,
);

/// The scene lints and the preparation of `scene`, or `None` when `deadline` passes first:
/// they then run on a thread of their own, abandoned when the time is up (the process ends
/// with the error; nothing has been written).
fn prepare_before(scene: rtc::ir::Scene, deadline: Option<std::time::Instant>) -> Option<Prepare> {
    let run = move || (rtc::check::lint(&scene), rtc::opt::prepare_owned(scene));
    let Some(deadline) = deadline else {
        return Some(run());
    };
    let (done, result) = std::sync::mpsc::channel();
    // A stack as deep as the main thread's and more (reserved, not touched): the preparation
    // recurses through CSG trees.
    let spawned = std::thread::Builder::new()
        .stack_size(64 << 20)
        .spawn(move || {
            let _ = done.send(run());
        });
    if spawned.is_err() {
        // No thread to be had (the system's limit): nothing can run, so stop as if timed out.
        return None;
    }
    let left = deadline.saturating_duration_since(std::time::Instant::now());
    result.recv_timeout(left).ok()
}

/// The diagnostic for a render stopped by `--time-limit`, at the camera (what sets the work).
fn time_limit_reached(c: &rtc::ir::Camera, limit: f64) -> Diagnostic {
    Diagnostic::error(
        "rtc::render::time_limit",
        c.span,
        format!(
            "the render did not finish within the time limit of {limit} s; no image was written"
        ),
    )
    .with_label(format!("this {}×{} image", c.width, c.height))
    .with_help(format!(
        "allow more time (`--time-limit {}`), or render fewer pixels or samples per pixel",
        (limit * 4.0).max(10.0).ceil()
    ))
}

/// `-o` wins, then the scene's own `output`, then the input name with `.png` (with `_####`
/// before it for an animation). `{frame}` and `####` in the name are numbered by the caller.
fn output_path(file: &Path, output: Option<PathBuf>, scene: &Scene, animated: bool) -> PathBuf {
    output
        .or_else(|| scene.settings.output.clone())
        .unwrap_or_else(|| {
            if animated {
                cli::frames::default_pattern(file)
            } else {
                file.with_extension("png")
            }
        })
}

/// The error for a scene whose `render { output: ... }` names a file outside the scene's folder
/// (an absolute path, `..` above it, or a symlinked folder leading out): a scene someone sent
/// must not choose which image of the user's it overwrites. `-o` is the user's own choice.
fn outside_scene_folder(file: &Path, scene: &Scene) -> Option<Diagnostic> {
    let out = scene.settings.output.as_ref()?;
    let dir = file.parent().unwrap_or(Path::new(""));
    if inside(dir, out) {
        return None;
    }
    let d = Diagnostic::new(
        rtc::diag::Severity::Error,
        "rtc::render::output",
        scene.settings.output_span,
        format!(
            "the scene's `output` `{}` is outside the scene's folder",
            out.display()
        ),
    )
    .with_label("a scene may only name an image in its own folder or below it")
    .with_help(format!(
        "choose the file yourself with `rtc render {} -o {}`, or name a path inside the scene's folder such as `out/{}`",
        file.display(),
        out.file_name().map_or("image.png".into(), |n| n.to_string_lossy()),
        out.file_name().map_or("image.png".into(), |n| n.to_string_lossy()),
    ));
    Some(d)
}

/// Whether `path` (already joined to `dir`, `..` collapsed) lies in `dir` or below it: it
/// does not climb above `dir` by name, and its deepest existing folder, canonicalised
/// (symlinks followed), is `dir`'s canonical folder or below it.
fn inside(dir: &Path, path: &Path) -> bool {
    use std::path::Component;
    let Ok(rel) = path.strip_prefix(dir) else {
        return false;
    };
    let mut depth = 0i64;
    for c in rel.components() {
        match c {
            Component::Normal(_) => depth += 1,
            Component::CurDir => {}
            Component::ParentDir => depth -= 1,
            Component::RootDir | Component::Prefix(_) => return false,
        }
        if depth < 0 {
            return false;
        }
    }
    let here = |p: &Path| {
        let p = if p.as_os_str().is_empty() {
            Path::new(".")
        } else {
            p
        };
        std::fs::canonicalize(p)
    };
    let Ok(root) = here(dir) else {
        return false;
    };
    // The file itself may be a link: the rename replaces the link, so only folders count.
    let mut folder = path.parent();
    while let Some(f) = folder {
        if let Ok(real) = here(f) {
            return real.starts_with(&root);
        }
        folder = f.parent();
    }
    false
}
