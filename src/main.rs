//! The `rtc` command line: `rtc check FILE` lints a scene, `rtc render FILE` renders it,
//! `rtc watch FILE` serves a live page that re-renders it on every change.
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
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum DenyLevel {
    /// Fail on warnings too.
    Warnings,
}

/// How a command ended.
#[derive(Clone, Copy, Debug)]
enum Outcome {
    Ok,
    SceneErrors,
    IoOrUsage,
}

impl Outcome {
    /// Which outcome wins when several files are checked: I/O over scene errors over success.
    fn severity(self) -> u8 {
        match self {
            Outcome::Ok => 0,
            Outcome::SceneErrors => 1,
            Outcome::IoOrUsage => 2,
        }
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let outcome = match cli.command {
        Command::Check { file, format, deny } => cli::check::run(&file, format, deny.is_some()),
        Command::Render {
            file,
            output,
            threads,
            format,
            stats,
        } => render(&file, output, threads, format, stats),
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
        eprintln!("{}", cli::check::count_line(&loaded.diagnostics));
        return outcome;
    };
    let path = output_path(file, output, &scene);
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
