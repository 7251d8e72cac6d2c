//! The `rtc` command line: `rtc check FILE` lints a scene, `rtc render FILE` renders it,
//! `rtc watch FILE` serves a live page that re-renders it on every change.
//! `rtc accuracy FILE` measures what its quality knobs cost and buy.
//! Exit codes: 0 success, 1 scene errors, 2 usage or I/O problems, 130 an `rtc accuracy` sweep
//! interrupted by Ctrl-C (its partial report is written). Diagnostics go to stderr;
//! stdout carries only what was asked for (`--format json`).
#![forbid(unsafe_code)]
// Diagnostics are returned by value on cold error paths; boxing them buys nothing measurable.
#![allow(clippy::result_large_err)]

mod cli;

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use rtc::diag::IO_ERROR;
use rtc::diag::{Diagnostic, Diagnostics};
use rtc::eval::EvalOptions;
use rtc::ir::Loaded;
use rtc::ir::Scene;
use rtc::source::SourceMap;

use cli::report::{self, Format};

/// rtc: a scene-language compiler and ray tracer.
#[derive(Parser, Debug)]
#[command(name = "rtc", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Parse, evaluate and lint a scene or library module, or every `.rtc` file below a directory.
    Check {
        /// A scene file (`.rtc`, `.in` or `.yaml`), a library module, or a directory.
        file: PathBuf,
        /// How to print diagnostics.
        #[arg(long, value_enum, default_value = "human")]
        format: Format,
        /// Treat warnings as errors (`--deny warnings`).
        #[arg(long, value_name = "warnings")]
        deny: Option<DenyLevel>,
        #[command(flatten)]
        inputs: SceneInputs,
    },
    /// Render a scene to an image (PNG or PPM; EXR for linear, unclamped colour).
    Render {
        /// The scene file (`.rtc`, `.in` or `.yaml`).
        file: PathBuf,
        /// Output image; defaults to the scene's `output`, else the input name with `.png`.
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// Worker threads (0 = all cores).
        #[arg(long, default_value_t = 0)]
        threads: usize,
        /// How to print diagnostics.
        #[arg(long, value_enum, default_value = "human")]
        format: Format,
        /// Print rays traced, rays per second, world build time and memory to stderr.
        #[arg(long)]
        stats: bool,
        /// Stop after this many seconds (counted from the start; the render stops at its next
        /// band of rows): no image is written, the exit code is 1.
        #[arg(long, value_name = "SECONDS", value_parser = seconds)]
        time_limit: Option<f64>,
        /// Render several frames, `A..B` (B excluded), `A..=B` or with a step `A..=B:STEP`;
        /// the output name numbers them with `{frame}` or `####`.
        #[arg(long, value_name = "RANGE", conflicts_with = "frame")]
        frames: Option<String>,
        #[command(flatten)]
        inputs: SceneInputs,
        /// Render progressively until the estimated linear RMSE is at most E (e.g. 0.01).
        #[arg(long, value_name = "E", value_parser = cli::converge::parse_error)]
        target_error: Option<f64>,
        /// Render progressively for at most T (`30s`, `2m`, `1h`) and write the image reached.
        #[arg(long, value_name = "T", value_parser = cli::converge::parse_duration)]
        time: Option<std::time::Duration>,
        /// Reproduce a progressive render exactly from the sample map it wrote.
        #[arg(long, value_name = "FILE", conflicts_with_all = ["target_error", "time"])]
        samples_from: Option<PathBuf>,
        /// Where a progressive render writes its sample map (default: the image path + `.samples`).
        #[arg(long, value_name = "FILE")]
        samples_to: Option<PathBuf>,
        /// Render only shard K of N (`K/N`, from 0) and write it as a part for `rtc merge`;
        /// `auto` reads the task index of a Slurm array job or a Kubernetes Indexed Job.
        #[arg(long, value_name = "K/N|auto")]
        shard: Option<String>,
        /// The number of shards for `--shard auto` where the scheduler does not say it
        /// (Kubernetes Indexed Jobs).
        #[arg(long, value_name = "N")]
        shards: Option<u32>,
    },
    /// Merge the parts of a sharded render (`rtc render --shard K/N`) into one image.
    Merge {
        /// The part files, one per shard, in any order.
        #[arg(required = true)]
        parts: Vec<PathBuf>,
        /// The image to write (PNG, PPM or EXR).
        #[arg(short, long)]
        output: PathBuf,
    },
    /// Serve a live page on 127.0.0.1 that re-renders the scene whenever it or a file it uses changes.
    Watch {
        /// The scene file (`.rtc`, `.in` or `.yaml`).
        file: PathBuf,
        /// Port on 127.0.0.1 (0: any free port).
        #[arg(long, default_value_t = 8290)]
        port: u16,
        /// Open the page in the default browser.
        #[arg(long)]
        open: bool,
        /// Worker threads (0 = all cores).
        #[arg(long, default_value_t = 0)]
        threads: usize,
    },
    /// Measure what each quality knob of a scene costs in time and buys in error (docs/accuracy.md).
    Accuracy(AccuracyArgs),
}

/// What the command line tells the scene before it is evaluated.
#[derive(clap::Args, Debug, Clone)]
struct SceneInputs {
    /// The frame to evaluate: the scene's built-in `frame` (and `time` = frame / fps).
    #[arg(long, default_value_t = 0, allow_hyphen_values = true)]
    frame: i64,
    /// Frames per second, for the built-in `time`.
    #[arg(long, default_value_t = rtc::eval::DEFAULT_FPS)]
    fps: f64,
    /// Overrides a `param` the scene file declares (repeatable): `--set size=3`, `-D size=3`.
    #[arg(long = "set", short = 'D', value_name = "NAME=VALUE")]
    set: Vec<String>,
}

impl SceneInputs {
    /// The evaluation options for `frame`, or what is wrong with the command line.
    fn options(&self, frame: i64) -> Result<EvalOptions, String> {
        if !(self.fps.is_finite() && self.fps > 0.0) {
            return Err(format!(
                "`--fps {}`: frames per second must be a positive number",
                self.fps
            ));
        }
        let mut overrides = Vec::new();
        for s in &self.set {
            let Some((name, value)) = s.split_once('=') else {
                return Err(format!(
                    "`--set {s}` needs a value: write `--set NAME=VALUE`, e.g. `--set size=3`"
                ));
            };
            let name = name.trim();
            let ident = name
                .chars()
                .next()
                .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
                && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
            if !ident {
                return Err(format!(
                    "`--set {s}`: `{name}` is not a parameter name (letters, digits and `_`)"
                ));
            }
            overrides.push((name.to_string(), value.to_string()));
        }
        Ok(EvalOptions {
            frame,
            fps: self.fps,
            overrides,
            ..EvalOptions::default()
        })
    }
}

/// `rtc accuracy`'s options.
#[derive(clap::Args, Debug)]
struct AccuracyArgs {
    /// The scene file (`.rtc`, `.in` or `.yaml`).
    file: PathBuf,
    /// Measure against this image instead of rendering a reference (EXR: linear light; PNG:
    /// sRGB bytes), at the swept size.
    #[arg(long, value_name = "FILE")]
    reference: Option<PathBuf>,
    /// Sweep at this factor of the scene's resolution per side (default: the largest factor
    /// ≤ 1 that keeps the image within --max-pixels).
    #[arg(long, value_parser = cli::accuracy::parse_positive)]
    scale: Option<f64>,
    /// The pixel budget of the automatic scale.
    #[arg(long, default_value_t = rtc::accuracy::scale::DEFAULT_MAX_PIXELS)]
    max_pixels: u64,
    /// Renders per seed and point; the time is their median.
    #[arg(long, default_value_t = 1)]
    repeat: u32,
    /// The first seed (the second is the next integer); default: the scene's own seed.
    #[arg(long)]
    seed: Option<u64>,
    /// Worker threads (0 = all cores).
    #[arg(long, default_value_t = 0)]
    threads: usize,
    /// Skip the joint sweep (ladders only).
    #[arg(long)]
    no_joint: bool,
    /// Neither read nor write the reference cache.
    #[arg(long)]
    no_cache: bool,
    /// The error of the Pareto front, the plot and the recommendations.
    #[arg(long, value_enum, default_value = "flip")]
    metric: MetricArg,
    /// Recommend the cheapest measured setting whose error is at most this.
    #[arg(long, value_parser = cli::accuracy::parse_positive)]
    target_error: Option<f64>,
    /// Recommend the most accurate measured setting whose full-size render takes at most this
    /// (seconds, or with a unit: 30s, 10m, 2h).
    #[arg(long, value_parser = cli::accuracy::parse_seconds)]
    time: Option<f64>,
    /// Stdout: a table, or the JSON report.
    #[arg(long, value_enum, default_value = "table")]
    format: TableFormat,
    /// Directory for report.json, plot.svg and flip-map.png (default: `<scene stem>-accuracy`).
    #[arg(short, long)]
    out_dir: Option<PathBuf>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum MetricArg {
    /// Mean ꟻLIP (sRGB images).
    Flip,
    /// RMSE in linear light.
    Rmse,
    /// Relative MSE in linear light.
    RelMse,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum TableFormat {
    /// A table.
    Table,
    /// The JSON report (schema rtc-accuracy/1).
    Json,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum DenyLevel {
    /// Fail on warnings too.
    Warnings,
}

/// How a command ended.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Outcome {
    Ok,
    SceneErrors,
    IoOrUsage,
    Interrupted,
}

impl Outcome {
    /// Which outcome wins when several files are checked: I/O over scene errors over success.
    fn severity(self) -> u8 {
        match self {
            Outcome::Ok => 0,
            Outcome::SceneErrors => 1,
            Outcome::IoOrUsage => 2,
            Outcome::Interrupted => 3,
        }
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let outcome = match cli.command {
        Command::Check {
            file,
            format,
            deny,
            inputs,
        } => match inputs.options(inputs.frame) {
            Ok(opts) => cli::check::run(&file, format, deny.is_some(), &opts),
            Err(msg) => usage_error(&msg),
        },
        Command::Render {
            file,
            output,
            threads,
            format,
            stats,
            frames,
            inputs,
            target_error,
            time,
            samples_from,
            samples_to,
            shard,
            shards,
            time_limit,
        } => match cli::shard::resolve(shard.as_deref(), shards) {
            Ok(shard) => {
                let job = RenderJob {
                    file: &file,
                    output,
                    threads,
                    format,
                    show_stats: stats,
                    progressive: cli::converge::Request {
                        target_error,
                        time,
                        samples_from,
                        samples_to,
                    },
                    shard,
                    time_limit,
                };
                render_frames(&job, frames.as_deref(), &inputs)
            }
            Err(d) => cli::shard::usage_error(&d),
        },
        Command::Watch {
            file,
            port,
            open,
            threads,
        } => cli::watch::run(&cli::watch::Options {
            file,
            port,
            open,
            threads,
        }),
        Command::Accuracy(args) => accuracy(&args),
        Command::Merge { parts, output } => cli::shard::merge(&parts, &output),
    };
    match outcome {
        Outcome::Ok => ExitCode::SUCCESS,
        Outcome::SceneErrors => ExitCode::from(1),
        Outcome::IoOrUsage => ExitCode::from(2),
        Outcome::Interrupted => ExitCode::from(130),
    }
}

/// Reports a command-line mistake found before any scene is read (exit code 2).
fn usage_error(msg: &str) -> Outcome {
    eprintln!("error: {msg}");
    Outcome::IoOrUsage
}

/// Loads a scene and runs the scene lints on it.
fn load(file: &Path, sources: &mut SourceMap, opts: &EvalOptions) -> Loaded {
    let mut loaded = rtc::loader::load(file, sources, opts);
    if let Some(scene) = &loaded.scene {
        loaded.diagnostics.extend(rtc::check::lint(scene));
    }
    loaded
}

fn outcome_of(diags: &Diagnostics, deny_warnings: bool) -> Outcome {
    if diags.items.iter().any(|d| d.code == IO_ERROR) {
        Outcome::IoOrUsage
    } else if diags.has_errors() || (deny_warnings && diags.warning_count() > 0) {
        Outcome::SceneErrors
    } else {
        Outcome::Ok
    }
}

/// What `rtc render` was asked to do, besides the frames.
struct RenderJob<'a> {
    file: &'a Path,
    output: Option<PathBuf>,
    threads: usize,
    format: Format,
    show_stats: bool,
    /// `--target-error`, `--time`, `--samples-from`, `--samples-to`.
    progressive: cli::converge::Request,
    /// `--shard K/N`: a share of the pixels of one frame, or with `--frames` a share of the
    /// frames (task K of N renders the frames at positions K, K+N, … of the range).
    shard: Option<rtc::render::shard::Shard>,
    /// Seconds each frame's command may take (`--time-limit`).
    time_limit: Option<f64>,
}

/// A `--time-limit` value: a finite number of seconds, at least 0.
fn seconds(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(s) if s.is_finite() && s >= 0.0 => Ok(s),
        _ => Err(format!(
            "`{text}` is not a number of seconds (write e.g. `--time-limit 60` or `2.5`)"
        )),
    }
}

/// Renders `--frame N` (one image), or each frame of `--frames` in turn, each evaluated afresh.
fn render_frames(job: &RenderJob<'_>, frames: Option<&str>, inputs: &SceneInputs) -> Outcome {
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
    let mut sources = SourceMap::new();
    let load_start = std::time::Instant::now();
    let deadline = job
        .time_limit
        .map(|s| load_start + std::time::Duration::from_secs_f64(s));
    let loaded = load(file, &mut sources, opts);
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
    let path = match pixel_shard {
        Some(s) => cli::shard::part_path(job.output.clone(), &path, s),
        None => path,
    };
    let start = std::time::Instant::now();
    let prepared = match rtc::opt::prepare(&scene) {
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
            Some(limit) if d.code == rtc::render::CANCELLED => time_limit_reached(&scene, limit),
            _ => d,
        })
    };
    let result = film.and_then(|film| {
        if show_stats {
            eprintln!(
                "{}",
                cli::stats::describe(&film, &prepared, load_time, start.elapsed())
            );
        }
        match pixel_shard {
            Some(s) => cli::shard::write_part(&film, &scene, s, &path),
            None => rtc::render::output::save_film(&film, &path),
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

/// The diagnostic for a render stopped by `--time-limit`, at the camera (what sets the work).
fn time_limit_reached(scene: &Scene, limit: f64) -> Diagnostic {
    let c = &scene.camera;
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

fn accuracy(args: &AccuracyArgs) -> Outcome {
    let subject = args.file.display().to_string();
    let mut sources = SourceMap::new();
    let loaded = load(&args.file, &mut sources, &EvalOptions::default());
    let color = std::io::stderr().is_terminal();
    let print = |diags: &[Diagnostic], sources: &SourceMap| {
        let text = report::render(diags, sources, &subject, Format::Human, color);
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
    let reference = match &args.reference {
        Some(f) => rtc::accuracy::ReferenceChoice::File(f.clone()),
        None => rtc::accuracy::ReferenceChoice::Render {
            cache_dir: (!args.no_cache).then(cache_dir).flatten(),
        },
    };
    let first_seed = args.seed.unwrap_or(scene.settings.seed);
    let options = rtc::accuracy::StudyOptions {
        scene_name: subject.clone(),
        scale: args.scale,
        max_pixels: args.max_pixels,
        reference,
        measure: rtc::accuracy::MeasureOptions {
            repeat: args.repeat.max(1),
            seeds: [first_seed, first_seed.wrapping_add(1)],
            threads: args.threads,
        },
        joint: !args.no_joint,
        metric: match args.metric {
            MetricArg::Flip => rtc::accuracy::Metric::Flip,
            MetricArg::Rmse => rtc::accuracy::Metric::Rmse,
            MetricArg::RelMse => rtc::accuracy::Metric::RelMse,
        },
        target_error: args.target_error,
        time: args.time,
    };
    cli::accuracy::catch_interrupt();
    let bar = cli::accuracy::SweepBar::on_stderr();
    let study = match rtc::accuracy::study(&scene, &options, &bar) {
        Ok(r) => r,
        Err(diags) => {
            use rtc::accuracy::SweepProgress;
            bar.end();
            print(&diags.items, &sources);
            if diags
                .items
                .iter()
                .any(|d| d.code == rtc::accuracy::NOTHING_MEASURED)
            {
                return Outcome::Interrupted;
            }
            return outcome_of(&diags, false);
        }
    };
    if study.reference_too_noisy() {
        print(&[cli::accuracy::noisy_reference(&study)], &sources);
    }
    if !study.complete {
        eprintln!(
            "interrupted: the report keeps the {} point(s) measured so far",
            study.points.len()
        );
    }
    match args.format {
        TableFormat::Table => print!("{}", cli::accuracy_table::table(&study)),
        TableFormat::Json => println!(
            "{}",
            serde_json::to_string_pretty(&study.to_json()).unwrap_or_default()
        ),
    }
    let dir = args
        .out_dir
        .clone()
        .unwrap_or_else(|| cli::accuracy::default_out_dir(&args.file));
    match cli::accuracy::write_outputs(&study, &dir) {
        Ok(files) => {
            let names: Vec<String> = files.iter().map(|f| f.display().to_string()).collect();
            eprintln!("wrote {}", names.join(", "));
        }
        Err(d) => {
            print(std::slice::from_ref(&d), &sources);
            return Outcome::IoOrUsage;
        }
    }
    if study.complete {
        Outcome::Ok
    } else {
        Outcome::Interrupted
    }
}

/// The reference cache: `$RTC_CACHE_DIR`, else `$XDG_CACHE_HOME/rtc/accuracy`, else
/// `$HOME/.cache/rtc/accuracy`; none when no variable is set.
fn cache_dir() -> Option<PathBuf> {
    let var = |name: &str| {
        std::env::var_os(name)
            .filter(|v| !v.is_empty())
            .map(PathBuf::from)
    };
    var("RTC_CACHE_DIR")
        .or_else(|| var("XDG_CACHE_HOME").map(|d| d.join("rtc").join("accuracy")))
        .or_else(|| var("HOME").map(|d| d.join(".cache").join("rtc").join("accuracy")))
}
