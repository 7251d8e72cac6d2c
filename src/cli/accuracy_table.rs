//! `rtc accuracy`'s human output: the header lines, the table of points and the
//! recommendations, as text for stdout.

use std::fmt::Write as _;

use rtc::accuracy::Report;
use rtc::accuracy::reference::Source;
use rtc::accuracy::report::Recommendation;

/// The whole report as text: what was swept, one row per point, the recommendations.
pub(crate) fn table(r: &Report) -> String {
    let mut out = String::new();
    let s = &r.size;
    let size = if (s.width, s.height) == (s.full_width, s.full_height) {
        format!("{}×{}", s.width, s.height)
    } else {
        format!(
            "{}×{} (scale {:.3} of {}×{})",
            s.width, s.height, s.scale, s.full_width, s.full_height
        )
    };
    let region = s.region.map_or(String::new(), |g| {
        format!(", region {} ({}×{} pixels)", g.text(), g.width, g.height)
    });
    let _ = writeln!(out, "rtc accuracy {}: swept at {size}{region}", r.scene);
    let effects = if r.effects.is_empty() {
        "none".to_string()
    } else {
        r.effects.join(", ")
    };
    let knobs: Vec<&str> = r.knobs.iter().map(|k| k.name()).collect();
    let _ = writeln!(out, "effects: {effects}; knobs swept: {}", knobs.join(", "));
    let _ = writeln!(out, "reference: {}", reference_line(r));
    let seeds = if r.stochastic {
        format!(
            "seeds {} and {} (the scene draws random numbers)",
            r.seeds[0], r.seeds[1]
        )
    } else {
        format!("seed {} (nothing random: one seed)", r.seeds[0])
    };
    let _ = writeln!(
        out,
        "each point: median of {} render(s) per seed, {seeds}; error against the reference",
        r.repeat
    );
    // At most ~100 columns: the setting's width is its longest label; the sweeps a point
    // belongs to, its rays and its relMSE are in the JSON report (`--format json`).
    let width = r
        .points
        .iter()
        .map(|p| p.measurement.setting.label().chars().count())
        .max()
        .unwrap_or(0)
        .max("setting".len());
    let _ = writeln!(
        out,
        "{:>3}  {:<width$} {:>8} {:>8} {:>8} {:>8} {:>8} {:>9} {:>5}",
        "#", "setting", "time ms", "full s", "ꟻLIP", "±", "worst1%", "RMSE", "front"
    );
    for (i, p) in r.points.iter().enumerate() {
        let m = &p.measurement;
        let _ = writeln!(
            out,
            "{i:>3}  {:<width$} {:>8.2} {:>8.3} {:>8.5} {:>8.5} {:>8.5} {:>9.3e} {:>5}",
            m.setting.label(),
            m.seconds * 1e3,
            r.full_seconds(p),
            m.error.flip_mean,
            m.spread.flip_mean,
            m.error.flip_worst,
            m.error.rmse,
            if p.pareto { "*" } else { "" },
        );
    }
    let _ = writeln!(
        out,
        "time ms: median wall time of one render at the swept size; full s: predicted at the\n\
         scene's own size; ±: standard deviation of mean ꟻLIP over the seeds; front: on the\n\
         Pareto front of time and {} (rays, relMSE and the sweeps: `--format json`)",
        r.metric.label()
    );
    for rec in &r.recommendations {
        out += &recommendation(r, rec);
    }
    out
}

fn reference_line(r: &Report) -> String {
    let what = match &r.reference.source {
        Source::Rendered => "rendered".to_string(),
        Source::Cached(files) => format!(
            "from the cache ({})",
            files
                .first()
                .map(|f| f.display().to_string())
                .unwrap_or_default()
        ),
        Source::File(f) => format!("the file {}", f.display()),
    };
    let setting = r
        .reference
        .setting
        .map(|s| format!("{}, ", s.label()))
        .unwrap_or_default();
    let noise = match (r.reference.noise_rmse, r.reference.noise_flip) {
        (Some(rmse), Some(flip)) => format!(
            "its noise: RMSE {rmse:.3e} (two seeds averaged), ꟻLIP between the seeds {flip:.5}"
        ),
        _ if r.stochastic => "its noise is unknown".to_string(),
        _ => "noiseless (nothing random)".to_string(),
    };
    format!("{setting}{what}; {noise}")
}

fn recommendation(r: &Report, rec: &Recommendation) -> String {
    let goal = match rec.goal {
        "target_error" => format!("--target-error {} ({})", rec.value, r.metric.label()),
        "scene_error" => format!(
            "the scene's own {} ({:.5}; `--target-error E` or `--time T` asks for another)",
            r.metric.label(),
            rec.value
        ),
        _ => format!("--time {} s", rec.value),
    };
    match (rec.point, rec.predicted_seconds, rec.predicted_error) {
        (Some(i), Some(t), Some(e)) => format!(
            "{goal}: point {i}, predicted {t:.3} s at {}×{} and {} {e:.5}\n  {}\n",
            r.size.full_width,
            r.size.full_height,
            r.metric.label(),
            r.points[i].measurement.setting.render_block()
        ),
        _ => format!("{goal}: no measured setting meets it\n"),
    }
}
