//! The `rtc` command line: `rtc check FILE` lints a scene, `rtc render FILE` renders it,
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
    /// Parse, evaluate and lint a scene without rendering it.
    Check {
        /// The scene file (`.rtc`, `.in` or `.yaml`).
        file: PathBuf,
        /// How to print diagnostics.
        #[arg(long, value_enum, default_value = "human")]
        format: Format,
        /// Treat warnings as errors (`--deny warnings`).
        #[arg(long, value_name = "warnings")]
        deny: Option<DenyLevel>,
    },
    /// Render a scene to an image (PNG or PPM).
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
    },
    /// Measure what each quality knob of a scene costs in time and buys in error (docs/accuracy.md).
    Accuracy(AccuracyArgs),
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
enum Outcome {
    Ok,
    SceneErrors,
    IoOrUsage,
    Interrupted,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let outcome = match cli.command {
        Command::Check { file, format, deny } => check(&file, format, deny.is_some()),
        Command::Render {
            file,
            output,
            threads,
            format,
            stats,
        } => render(&file, output, threads, format, stats),
        Command::Accuracy(args) => accuracy(&args),
    };
    match outcome {
        Outcome::Ok => ExitCode::SUCCESS,
        Outcome::SceneErrors => ExitCode::from(1),
        Outcome::IoOrUsage => ExitCode::from(2),
        Outcome::Interrupted => ExitCode::from(130),
    }
}

/// Loads a scene and runs the scene lints on it.
fn load(file: &Path, sources: &mut SourceMap) -> Loaded {
    let mut loaded = rtc::loader::load(file, sources, &EvalOptions::default());
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

fn count_line(diags: &Diagnostics) -> String {
    let (e, w) = (diags.error_count(), diags.warning_count());
    format!(
        "{e} error{}, {w} warning{}",
        if e == 1 { "" } else { "s" },
        if w == 1 { "" } else { "s" }
    )
}

fn check(file: &Path, format: Format, deny_warnings: bool) -> Outcome {
    let subject = file.display().to_string();
    let mut sources = SourceMap::new();
    let mut loaded = rtc::loader::load(file, &mut sources, &EvalOptions::default());
    if let Some(scene) = &loaded.scene {
        loaded.diagnostics.extend(rtc::check::check(scene));
    }
    let diags = &loaded.diagnostics;
    let outcome = outcome_of(diags, deny_warnings);
    let color = format == Format::Human && std::io::stderr().is_terminal();
    let summary = match (&outcome, &loaded.scene) {
        (Outcome::Ok, Some(scene)) => {
            format!("{}: ok: {}", file.display(), rtc::check::summary(scene))
        }
        _ => count_line(diags),
    };
    if format == Format::Json {
        let mut doc: serde_json::Value = serde_json::from_str(&report::render(
            &diags.items,
            &sources,
            &subject,
            format,
            false,
        ))
        .unwrap_or_default();
        doc["summary"] = serde_json::Value::String(summary);
        doc["ok"] = serde_json::Value::Bool(matches!(outcome, Outcome::Ok));
        println!("{doc}");
    } else {
        // Diagnostics and the summary are a compiler's messages: stderr. Only `--format json`,
        // which a tool asked for, writes to stdout.
        let text = report::render(&diags.items, &sources, &subject, format, color);
        if !text.is_empty() {
            eprintln!("{}", text.trim_end());
            if format == Format::Short {
                eprintln!();
            }
        }
        eprintln!("{summary}");
    }
    outcome
}

fn render(
    file: &Path,
    output: Option<PathBuf>,
    threads: usize,
    format: Format,
    show_stats: bool,
) -> Outcome {
    let subject = file.display().to_string();
    let mut sources = SourceMap::new();
    let load_start = std::time::Instant::now();
    let loaded = load(file, &mut sources);
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
        eprintln!("{}", count_line(&loaded.diagnostics));
        return outcome;
    };
    let path = output_path(file, output, &scene);
    let start = std::time::Instant::now();
    let prepared = match rtc::opt::prepare(&scene) {
        Ok(p) => p,
        Err(diags) => {
            print(&diags.items, &sources);
            eprintln!("{}", count_line(&diags));
            return outcome_of(&diags, false);
        }
    };
    print(prepared.warnings(), &sources);
    let options = rtc::render::RenderOptions { threads };
    let result = rtc::render::render(&prepared, &options, &cli::progress::Bar::on_stderr())
        .and_then(|film| {
            if show_stats {
                eprintln!(
                    "{}",
                    cli::stats::describe(&film, &prepared.stats(), load_time, start.elapsed())
                );
            }
            rtc::render::output::save(&film.to_image(), &path)
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

/// `-o` wins, then the scene's own `output`, then the input name with `.png`.
fn output_path(file: &Path, output: Option<PathBuf>, scene: &Scene) -> PathBuf {
    output
        .or_else(|| scene.settings.output.clone())
        .unwrap_or_else(|| file.with_extension("png"))
}

fn accuracy(args: &AccuracyArgs) -> Outcome {
    let subject = args.file.display().to_string();
    let mut sources = SourceMap::new();
    let loaded = load(&args.file, &mut sources);
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
        eprintln!("{}", count_line(&loaded.diagnostics));
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
