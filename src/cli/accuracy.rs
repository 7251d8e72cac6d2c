//! `rtc accuracy SCENE`: runs the study (`rtc::accuracy`), draws a progress bar over the sweep,
//! keeps the points measured so far on Ctrl-C, prints the table (or JSON) and writes the plot,
//! the ꟻLIP map of the scene's own setting and the JSON report.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rtc::accuracy::report::Report;
use rtc::accuracy::sweep::Sweep;
use rtc::accuracy::{Knob, SweepProgress};
use rtc::diag::{Diagnostic, IO_ERROR, Severity};
use rtc::metrics::plot::{ErrorTimePlot, MarkedPoint, PlotPoint, Series};

/// The plot's file name in the output directory.
pub const PLOT_FILE: &str = "plot.svg";
/// The ꟻLIP map's file name in the output directory.
pub const MAP_FILE: &str = "flip-map.png";
/// The JSON report's file name in the output directory.
pub const JSON_FILE: &str = "report.json";

/// Set by the first Ctrl-C: the sweep stops after the current render, and the partial report is
/// written. A second Ctrl-C ends the process at once.
static INTERRUPTED: AtomicBool = AtomicBool::new(false);

/// Installs the Ctrl-C handler (once per process).
pub fn catch_interrupt() {
    let _ = ctrlc::set_handler(|| {
        if INTERRUPTED.swap(true, Ordering::SeqCst) {
            std::process::exit(130);
        }
    });
}

/// The bar over the sweep's renders on stderr (when it is a terminal); cancels on Ctrl-C.
pub struct SweepBar {
    bar: Option<ProgressBar>,
}

impl SweepBar {
    /// A bar on stderr if it is a terminal.
    pub fn on_stderr() -> SweepBar {
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
        INTERRUPTED.load(Ordering::Relaxed)
    }

    fn end(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
    }
}

/// The default output directory: `<scene stem>-accuracy` in the current directory.
pub fn default_out_dir(scene: &Path) -> PathBuf {
    let stem = scene
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "scene".into());
    PathBuf::from(format!("{stem}-accuracy"))
}

/// Writes the JSON report, the plot and the ꟻLIP map into `dir`; the paths written.
pub fn write_outputs(report: &Report, dir: &Path) -> Result<Vec<PathBuf>, Diagnostic> {
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
pub fn plot(report: &Report) -> ErrorTimePlot {
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
pub fn noisy_reference(report: &Report) -> Diagnostic {
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
pub const NOISY_REFERENCE: &str = "rtc::accuracy::noisy_reference";

/// Parses a duration: seconds, or a number with `s`, `m` or `h`.
pub fn parse_seconds(text: &str) -> Result<f64, String> {
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

/// Parses a positive finite number.
pub fn parse_positive(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        _ => Err(format!("`{text}` is not a positive number")),
    }
}

fn write(path: PathBuf, bytes: &[u8]) -> Result<PathBuf, Diagnostic> {
    std::fs::write(&path, bytes).map_err(|e| io_error(&path, &e))?;
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
