//! `rtc accuracy SCENE`: runs the study (`rtc::accuracy`), draws a progress bar over the sweep,
//! keeps the points measured so far on Ctrl-C, prints the table (or JSON) and writes the plot,
//! the ꟻLIP map of the scene's own setting and the JSON report.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use rtc::eval::EvalOptions;
use rtc::source::SourceMap;

use crate::cli::report::{self, Format};
use crate::cli::{Outcome, load, outcome_of};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rtc::accuracy::report::Report;
use rtc::accuracy::sweep::Sweep;
use rtc::accuracy::{Knob, SweepProgress};
use rtc::diag::{Diagnostic, IO_ERROR, Severity};
use rtc::metrics::plot::{ErrorTimePlot, MarkedPoint, PlotPoint, Series};

/// The plot's file name in the output directory.
const PLOT_FILE: &str = "plot.svg";
/// The ꟻLIP map's file name in the output directory.
const MAP_FILE: &str = "flip-map.png";
/// The JSON report's file name in the output directory.
const JSON_FILE: &str = "report.json";

/// The bar over the sweep's renders on stderr (when it is a terminal); cancels on Ctrl-C.
struct SweepBar {
    bar: Option<ProgressBar>,
}

impl SweepBar {
    /// A bar on stderr if it is a terminal.
    fn on_stderr() -> SweepBar {
        if !std::io::stderr().is_terminal() {
            return SweepBar { bar: None };
        }
        let style = ProgressStyle::with_template(
            "{spinner} sweep [{bar:30}] {pos}/{len} renders {elapsed}, ETA {eta}: {msg}",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> ");
        let bar =
            ProgressBar::with_draw_target(Some(0), ProgressDrawTarget::stderr()).with_style(style);
        SweepBar { bar: Some(bar) }
    }
}

impl SweepProgress for SweepBar {
    fn begin(&self, renders: u64) {
        if let Some(b) = &self.bar {
            b.set_length(renders);
        }
    }

    fn point(&self, label: &str) {
        if let Some(b) = &self.bar {
            b.set_message(label.to_string());
        }
    }

    fn render_done(&self) {
        if let Some(b) = &self.bar {
            b.inc(1);
        }
    }

    fn cancelled(&self) -> bool {
        super::interrupt::interrupted()
    }

    fn end(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
    }
}

/// The default output directory: `<scene stem>-accuracy` in the current directory.
fn default_out_dir(scene: &Path) -> PathBuf {
    let stem = scene
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "scene".into());
    PathBuf::from(format!("{stem}-accuracy"))
}

/// Writes the JSON report, the plot and the ꟻLIP map into `dir`; the paths written.
fn write_outputs(report: &Report, dir: &Path) -> Result<Vec<PathBuf>, Diagnostic> {
    std::fs::create_dir_all(dir).map_err(|e| io_error(dir, &e))?;
    let mut written = Vec::new();
    let json = serde_json::to_string_pretty(&report.to_json()).unwrap_or_default();
    written.push(write(dir.join(JSON_FILE), json.as_bytes())?);
    written.push(write(
        dir.join(PLOT_FILE),
        plot(report).to_svg()?.as_bytes(),
    )?);
    if let Some(own) = report.own() {
        let png = own.measurement.flip_map.magma_png()?;
        written.push(write(dir.join(MAP_FILE), &png)?);
    }
    Ok(written)
}

/// The error-versus-time plot: one curve per knob's ladder (in order of rays), the joint sweep
/// as loose points, the scene's own setting marked.
fn plot(report: &Report) -> ErrorTimePlot {
    let metric = report.metric;
    let point = |p: &rtc::accuracy::report::Point| PlotPoint {
        seconds: p.measurement.seconds,
        error: metric.of(&p.measurement.error),
    };
    let mut series: Vec<Series> = report
        .knobs
        .iter()
        .map(|&k: &Knob| {
            let mut on: Vec<_> = report
                .points
                .iter()
                .filter(|p| p.sweeps.contains(&Sweep::Ladder(k)))
                .collect();
            on.sort_by_key(|p| p.measurement.rays);
            Series {
                name: k.name().to_string(),
                points: on.into_iter().map(point).collect(),
                joined: true,
            }
        })
        .collect();
    let joint: Vec<PlotPoint> = report
        .points
        .iter()
        .filter(|p| p.sweeps.contains(&Sweep::Joint))
        .map(point)
        .collect();
    if !joint.is_empty() {
        series.push(Series {
            name: "joint sweep".into(),
            points: joint,
            joined: false,
        });
    }
    ErrorTimePlot {
        title: format!(
            "{}: {} against time ({}×{})",
            report.scene,
            metric.label(),
            report.size.width,
            report.size.height
        ),
        error_label: metric.label().to_string(),
        series,
        marked: report.own().map(|p| MarkedPoint {
            label: format!("scene's setting ({})", p.measurement.setting.label()),
            point: point(p),
        }),
    }
}

/// The warning for a reference whose own noise is large against the smallest measured error.
fn noisy_reference(report: &Report) -> Diagnostic {
    let noise = report.reference.noise_rmse.unwrap_or(0.0);
    Diagnostic::new(
        Severity::Warning,
        NOISY_REFERENCE,
        None,
        format!(
            "the reference's own noise (RMSE {noise:.3e}) is more than {:.0}% of the smallest \
             measured RMSE: the most accurate settings' errors are partly the reference's noise",
            100.0 * rtc::accuracy::report::NOISY_REFERENCE_SHARE
        ),
    )
    .with_help(
        "trust the ranking of the cheap settings only, or give a converged image with --reference",
    )
}

/// The reference's noise is large against the smallest measured error.
const NOISY_REFERENCE: &str = "rtc::accuracy::noisy_reference";

/// Parses a duration: seconds, or a number with `s`, `m` or `h`.
fn parse_seconds(text: &str) -> Result<f64, String> {
    let t = text.trim();
    let (number, unit) = match t.char_indices().last() {
        Some((i, 's')) => (&t[..i], 1.0),
        Some((i, 'm')) => (&t[..i], 60.0),
        Some((i, 'h')) => (&t[..i], 3600.0),
        _ => (t, 1.0),
    };
    match number.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v * unit),
        _ => Err(format!(
            "`{text}` is not a positive duration (e.g. 30, 30s, 10m, 2h)"
        )),
    }
}

/// Parses `--region X,Y,W,H` (fitting it to the image comes after the scene is loaded).
fn parse_region(text: &str) -> Result<rtc::render::Region, String> {
    rtc::render::Region::parse(text).map_err(|d| match &d.help {
        Some(h) => format!("{}; {h}", d.message),
        None => d.message,
    })
}

/// Parses a positive finite number.
fn parse_positive(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        _ => Err(format!("`{text}` is not a positive number")),
    }
}

/// Writes a report file atomically (a signal mid-write leaves the old file or none).
fn write(path: PathBuf, bytes: &[u8]) -> Result<PathBuf, Diagnostic> {
    rtc::render::output::write_atomically(&path, bytes)?;
    Ok(path)
}

fn io_error(path: &Path, e: &std::io::Error) -> Diagnostic {
    Diagnostic::new(
        Severity::Error,
        IO_ERROR,
        None,
        format!("cannot write {}: {e}", path.display()),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn durations_and_numbers_parse() {
        assert_eq!(parse_seconds("30"), Ok(30.0));
        assert_eq!(parse_seconds("2m"), Ok(120.0));
        assert_eq!(parse_seconds("1.5h"), Ok(5400.0));
        assert!(parse_seconds("-1").is_err());
        assert!(parse_seconds("soon").is_err());
        assert_eq!(parse_positive("0.01"), Ok(0.01));
        assert!(parse_positive("0").is_err());
    }
}

/// `rtc accuracy`'s options.
#[derive(clap::Args, Debug)]
pub(crate) struct AccuracyArgs {
    /// The scene file (`.rtc`, `.in` or `.yaml`).
    file: PathBuf,
    /// Measure against this image instead of rendering a reference (EXR: linear light; PNG:
    /// sRGB bytes), at the swept size.
    #[arg(long, value_name = "FILE")]
    reference: Option<PathBuf>,
    /// Sweep at this factor of the scene's resolution per side (default: the largest factor
    /// ≤ 1 that keeps the image within --max-pixels).
    #[arg(long, value_parser = parse_positive)]
    scale: Option<f64>,
    /// The pixel budget of the automatic scale (with --region, of the region).
    #[arg(long, default_value_t = rtc::accuracy::scale::DEFAULT_MAX_PIXELS)]
    max_pixels: u64,
    /// Sweep only this sub-rectangle: X,Y,W,H (left, top, width, height) in the scene's own
    /// pixels, scaled with the image under --scale.
    #[arg(long, value_name = "X,Y,W,H", value_parser = parse_region)]
    region: Option<rtc::render::Region>,
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
    #[arg(long, value_parser = parse_positive)]
    target_error: Option<f64>,
    /// Recommend the most accurate measured setting whose full-size render takes at most this
    /// (seconds, or with a unit: 30s, 10m, 2h).
    #[arg(long, value_parser = parse_seconds)]
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

/// Runs `rtc accuracy` and prints its table or JSON.
pub(crate) fn run(args: &AccuracyArgs) -> Outcome {
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
        eprintln!("{}", crate::cli::check::count_line(&loaded.diagnostics));
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
        region: args.region,
        reference,
        measure: rtc::accuracy::MeasureOptions {
            repeat: args.repeat.max(1),
            seeds: [first_seed, first_seed.wrapping_add(1)],
            threads: args.threads,
            region: None,
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
    // The first signal stops the sweep after the current render; a second ends it.
    super::interrupt::graceful();
    let bar = SweepBar::on_stderr();
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
    let cache_notes: Vec<Diagnostic> = study
        .reference
        .cache_notes
        .iter()
        .map(|n| {
            Diagnostic::new(Severity::Note, "rtc::accuracy::cache", None, n.clone())
                .with_help("the cache only saves time: delete the entry, or pass `--no-cache`")
        })
        .collect();
    print(&cache_notes, &sources);
    if study.reference_too_noisy() {
        print(&[noisy_reference(&study)], &sources);
    }
    if !study.complete {
        eprintln!(
            "interrupted: the report keeps the {} point(s) measured so far",
            study.points.len()
        );
    }
    match args.format {
        TableFormat::Table => print!("{}", crate::cli::accuracy_table::table(&study)),
        TableFormat::Json => println!(
            "{}",
            serde_json::to_string_pretty(&study.to_json()).unwrap_or_default()
        ),
    }
    let dir = args
        .out_dir
        .clone()
        .unwrap_or_else(|| default_out_dir(&args.file));
    match write_outputs(&study, &dir) {
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
