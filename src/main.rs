//! The `rtc` command line: `rtc check FILE` lints a scene, `rtc render FILE` renders it.
//! Exit codes: 0 success, 1 scene errors, 2 usage or I/O problems. Diagnostics go to stderr;
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
        /// The image to write (PNG or PPM).
        #[arg(short, long)]
        output: PathBuf,
    },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum DenyLevel {
    /// Fail on warnings too.
    Warnings,
}

/// How a command ended.
pub(crate) enum Outcome {
    Ok,
    SceneErrors,
    IoOrUsage,
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
            shard,
            shards,
        } => match cli::shard::resolve(shard.as_deref(), shards) {
            Ok(shard) => render(&file, output, threads, format, stats, shard),
            Err(d) => cli::shard::usage_error(&d),
        },
        Command::Merge { parts, output } => cli::shard::merge(&parts, &output),
    };
    match outcome {
        Outcome::Ok => ExitCode::SUCCESS,
        Outcome::SceneErrors => ExitCode::from(1),
        Outcome::IoOrUsage => ExitCode::from(2),
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
    shard: Option<rtc::render::shard::Shard>,
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
    let path = match shard {
        Some(s) => cli::shard::part_path(output, &output_path(file, None, &scene), s),
        None => output_path(file, output, &scene),
    };
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
    let options = rtc::render::RenderOptions { threads, shard };
    let result = rtc::render::render(&prepared, &options, &cli::progress::Bar::on_stderr())
        .and_then(|film| {
            if show_stats {
                eprintln!(
                    "{}",
                    cli::stats::describe(&film, &prepared.stats(), load_time, start.elapsed())
                );
            }
            match shard {
                Some(s) => cli::shard::write_part(&film, &scene, s, &path),
                None => rtc::render::output::save(&film.to_image(), &path),
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

/// `-o` wins, then the scene's own `output`, then the input name with `.png`.
fn output_path(file: &Path, output: Option<PathBuf>, scene: &Scene) -> PathBuf {
    output
        .or_else(|| scene.settings.output.clone())
        .unwrap_or_else(|| file.with_extension("png"))
}
