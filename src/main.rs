//! The `rtc` command line: `rtc check FILE` lints a scene, `rtc render FILE` renders it,
//! `rtc watch FILE` serves a live page that re-renders it on every change.
//! `rtc accuracy FILE` measures what its quality knobs cost and buy.
//! `rtc why FILE X Y` explains what made one pixel.
//! Exit codes: 0 success, 1 scene errors, 2 usage or I/O problems, 130 a command ended by
//! Ctrl-C, SIGTERM or SIGHUP (no temporary file left; an `rtc accuracy` sweep writes its
//! partial report first). Diagnostics go to stderr;
//! stdout carries only what was asked for (`--format json`).
#![forbid(unsafe_code)]
// Diagnostics are returned by value on cold error paths; boxing them buys nothing measurable.
#![allow(clippy::result_large_err)]

mod cli;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use cli::Outcome;
use cli::report::Format;

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
        inputs: cli::inputs::SceneInputs,
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
        #[arg(long, value_name = "SECONDS", value_parser = cli::render::seconds)]
        time_limit: Option<f64>,
        /// Render several frames, `A..B` (B excluded), `A..=B` or with a step `A..=B:STEP`;
        /// the output name numbers them with `{frame}` or `####`.
        #[arg(long, value_name = "RANGE", conflicts_with = "frame")]
        frames: Option<String>,
        #[command(flatten)]
        inputs: cli::inputs::SceneInputs,
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
        /// Add AOV layers to an EXR output (comma-separated): depth, normal, albedo, object
        /// (the object ids map to source spans in `<output>.objects.json`).
        #[arg(long, value_name = "LAYERS", value_delimiter = ',', value_parser = cli::aov::parse)]
        aov: Vec<rtc::render::Channel>,
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
    /// Lay `.rtc` files out in the canonical layout, in place (or `--check`: show the diff, exit 1).
    Fmt {
        /// Files, directories (every `.rtc` below) or `-` (standard input to standard output).
        #[arg(required = true)]
        paths: Vec<PathBuf>,
        /// Write nothing: print a diff of what would change and exit 1 if anything would.
        #[arg(long)]
        check: bool,
        /// How to print diagnostics.
        #[arg(long, value_enum, default_value = "human")]
        format: Format,
    },
    /// Measure what each quality knob of a scene costs in time and buys in error (docs/accuracy.md).
    Accuracy(cli::accuracy::AccuracyArgs),
    /// Convert a course scene (`.in`, `.yaml`) to rtc source that renders the same image.
    Convert {
        /// The course scene file (`.in`, `.yaml` or `.yml`).
        file: PathBuf,
        /// Write the rtc source here (atomically) instead of to stdout.
        #[arg(short, long)]
        output: Option<PathBuf>,
        /// How to print diagnostics.
        #[arg(long, value_enum, default_value = "human")]
        format: Format,
    },
    /// Explain one pixel: its rays, what they hit, the loops and calls that made it (docs/why.md).
    Why(cli::why::WhyArgs),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum DenyLevel {
    /// Fail on warnings too.
    Warnings,
}

fn main() -> ExitCode {
    if let Some(missing) = missing_cpu_features() {
        eprintln!(
            "error: this rtc was built for x86-64-v3 (AVX2), and this CPU lacks {missing}; \
             rebuild it for this machine with CARGO_TARGET_X86_64_UNKNOWN_LINUX_GNU_RUSTFLAGS= cargo build --release"
        );
        return ExitCode::from(2);
    }
    let cli = Cli::parse();
    cli::interrupt::install();
    let outcome = match cli.command {
        Command::Check {
            file,
            format,
            deny,
            inputs,
        } => match inputs.options(inputs.frame) {
            Ok(opts) => cli::check::run(&file, format, deny.is_some(), &opts),
            Err(msg) => cli::usage_error(&msg),
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
            aov,
        } => match cli::shard::resolve(shard.as_deref(), shards) {
            Ok(shard) => {
                let job = cli::render::RenderJob {
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
                    aovs: cli::aov::dedup(&aov),
                };
                cli::render::render_frames(&job, frames.as_deref(), &inputs)
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
        Command::Accuracy(args) => cli::accuracy::run(&args),
        Command::Why(args) => cli::why::run(&args),
        Command::Merge { parts, output } => cli::shard::merge(&parts, &output),
        Command::Convert {
            file,
            output,
            format,
        } => cli::convert::run(&file, output.as_deref(), format),
        Command::Fmt {
            paths,
            check,
            format,
        } => cli::fmt::run(&paths, check, format),
    };
    match outcome {
        Outcome::Ok => ExitCode::SUCCESS,
        Outcome::SceneErrors => ExitCode::from(1),
        Outcome::IoOrUsage => ExitCode::from(2),
        Outcome::Interrupted => ExitCode::from(130),
    }
}

/// The instruction set extensions this binary was built to use that the CPU does not have
/// (`.cargo/config.toml` builds for x86-64-v3): without the check, the first AVX2 instruction
/// would kill the process with SIGILL.
fn missing_cpu_features() -> Option<&'static str> {
    #[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
    if !std::arch::is_x86_feature_detected!("avx2") {
        return Some("AVX2");
    }
    None
}
