//! `rtc render --target-error E`, `--time T` and `--samples-from FILE`: the CLI side of
//! progressive rendering (`rtc::render::progressive`). It owns the clock: a round report per
//! line on stderr with an ETA extrapolated from the measured error slope, the stop when the
//! time is spent, and the sample map that reproduces the image without a clock.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use rtc::diag::{Diagnostic, IO_ERROR, Severity};
use rtc::opt::Prepared;
use rtc::render::Progress;
use rtc::render::film::Film;
use rtc::render::progressive::{self, Budget, Round, SampleMap};

/// What the user asked of a progressive render.
#[derive(Clone, Debug, Default)]
pub(crate) struct Request {
    /// Stop when the error estimate is at most this.
    pub(crate) target_error: Option<f64>,
    /// Stop when this much time is spent (the last complete round is written).
    pub(crate) time: Option<Duration>,
    /// Reproduce the sample counts of this map instead.
    pub(crate) samples_from: Option<PathBuf>,
    /// Where to write the reached sample map (default: the image path with `.samples` added).
    pub(crate) samples_to: Option<PathBuf>,
}

impl Request {
    /// Whether any progressive option was given.
    pub(crate) fn wanted(&self) -> bool {
        self.target_error.is_some() || self.time.is_some() || self.samples_from.is_some()
    }
}

/// Stops the round in progress when the time is spent.
struct Deadline(Option<Instant>);

impl Progress for Deadline {
    fn cancelled(&self) -> bool {
        self.0.is_some_and(|end| Instant::now() >= end)
    }
}

/// Renders progressively, prints a line per round and the budget reached, writes the sample
/// map next to `image`, and returns the film.
pub(crate) fn render(
    prepared: &Prepared,
    threads: usize,
    req: &Request,
    image: &Path,
) -> Result<Film, Diagnostic> {
    let budget = match &req.samples_from {
        Some(file) => Budget::Samples(read_map(file)?),
        None => Budget::TargetError(req.target_error.unwrap_or(0.0)),
    };
    let start = Instant::now();
    let deadline = Deadline(req.time.map(|t| start + t));
    let mut history: Vec<(f64, f64)> = Vec::new();
    let mut report = |r: &Round| {
        let t = start.elapsed().as_secs_f64();
        history.push((t, r.estimate));
        eprintln!("{}", round_line(r, t, req.target_error, &history));
        !deadline.cancelled()
    };
    let out = progressive::render(prepared, threads, &budget, &deadline, &mut report)?;
    let (lo, hi) = out.map.sample_range();
    eprintln!(
        "reached: {} rounds, {:.1} samples per pixel ({lo}..{hi}), estimated RMSE {:.5}, {:.2} s",
        out.last.rounds,
        out.map.mean_samples(),
        out.last.estimate,
        start.elapsed().as_secs_f64()
    );
    let map_path = req.samples_to.clone().unwrap_or_else(|| {
        let mut p = image.as_os_str().to_owned();
        p.push(".samples");
        PathBuf::from(p)
    });
    if req.samples_from.as_deref() != Some(map_path.as_path()) {
        // Atomically, as the image: a signal mid-write leaves no half map.
        rtc::render::output::write_atomically(&map_path, out.map.to_text().as_bytes())?;
        eprintln!(
            "wrote {} (reproduce: --samples-from {})",
            map_path.display(),
            map_path.display()
        );
    }
    Ok(out.film)
}

/// One round's line: samples, estimate and, with a target, the ETA from the error slope.
fn round_line(r: &Round, t: f64, target: Option<f64>, history: &[(f64, f64)]) -> String {
    let pixels_note = if r.next > 0 {
        format!(", refining {} pixels", r.next)
    } else {
        String::new()
    };
    let eta = match (target, eta(history, target.unwrap_or(0.0))) {
        (Some(e), _) if r.estimate <= e => ", target reached".to_string(),
        (Some(_), Some(s)) => format!(", ETA {s:.1} s"),
        _ => String::new(),
    };
    format!(
        "round {}: {} samples, estimated RMSE {:.5}, {t:.2} s{pixels_note}{eta}",
        r.rounds, r.samples, r.estimate
    )
}

/// Seconds until the estimate reaches `target`, extrapolated on a log-log line through the
/// last two rounds (error ∝ time^slope): `None` before two rounds or when the error did not
/// fall.
fn eta(history: &[(f64, f64)], target: f64) -> Option<f64> {
    let [.., (t0, e0), (t1, e1)] = history else {
        return None;
    };
    if target <= 0.0 || *e1 <= target || *t0 <= 0.0 || t1 <= t0 || e1 >= e0 || *e1 <= 0.0 {
        return None;
    }
    let slope = (e1 / e0).ln() / (t1 / t0).ln();
    let reach = t1 * (target / e1).powf(1.0 / slope);
    Some((reach - t1).max(0.0))
}

/// Reads a sample map; a malformed one is `rtc::render::samples` at its line and column.
fn read_map(file: &Path) -> Result<SampleMap, Diagnostic> {
    let text = rtc::source::read_regular(file, rtc::source::MAX_SOURCE_BYTES)
        .and_then(|b| String::from_utf8(b).map_err(std::io::Error::other))
        .map_err(|e| {
            Diagnostic::new(
                Severity::Error,
                IO_ERROR,
                None,
                format!("cannot read {}: {e}", file.display()),
            )
        })?;
    SampleMap::parse(&text).map_err(|(line, col, what)| {
        Diagnostic::new(
            Severity::Error,
            "rtc::render::samples",
            None,
            format!("{}:{line}:{col}: {what}", file.display()),
        )
        .with_help("use a file written by `rtc render --target-error` or `--time`")
    })
}

/// Parses a duration such as `30`, `30s`, `2.5m` or `1h` (seconds without a unit).
pub(crate) fn parse_duration(s: &str) -> Result<Duration, String> {
    let (num, unit) = match s.trim().char_indices().last() {
        Some((i, c)) if c.is_ascii_alphabetic() => (&s.trim()[..i], c),
        _ => (s.trim(), 's'),
    };
    let scale = match unit {
        's' => 1.0,
        'm' => 60.0,
        'h' => 3600.0,
        _ => return Err(format!("unknown unit `{unit}`: use s, m or h")),
    };
    let v: f64 = num
        .parse()
        .map_err(|_| format!("`{s}` is not a duration such as 30s, 2m or 1h"))?;
    Duration::try_from_secs_f64(v * scale)
        .map_err(|_| format!("`{s}` is not a duration of zero or more seconds"))
}

/// Parses a target error: a finite number > 0.
pub(crate) fn parse_error(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        _ => Err(format!(
            "`{s}` is not an error > 0 (a linear RMSE such as 0.01)"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn durations_and_errors_parse_with_units() {
        assert_eq!(parse_duration("30"), Ok(Duration::from_secs(30)));
        assert_eq!(parse_duration("2m"), Ok(Duration::from_secs(120)));
        assert_eq!(parse_duration("1.5s"), Ok(Duration::from_millis(1500)));
        assert!(parse_duration("-1").is_err());
        assert!(parse_duration("3d").is_err());
        assert!(parse_error("0").is_err());
        assert_eq!(parse_error("0.01"), Ok(0.01));
    }

    #[test]
    fn eta_follows_the_error_slope() {
        // Error ∝ t^-1/2: from 0.04 at 1 s and 0.02 at 4 s, 0.01 is reached at 16 s.
        let h = [(1.0, 0.04), (4.0, 0.02)];
        let eta = eta(&h, 0.01).unwrap();
        assert!((eta - 12.0).abs() < 1e-9, "{eta}");
        assert_eq!(super::eta(&h[..1], 0.01), None);
        assert_eq!(super::eta(&[(1.0, 0.02), (2.0, 0.03)], 0.01), None);
    }
}
