//! The error-versus-time SVG plot (src/metrics/plot.rs): well-formed XML whose text carries the
//! series names, the axis labels, the Pareto front's legend and the marked setting.

use rtc::metrics::plot::{ErrorTimePlot, FRONT_LABEL, MarkedPoint, PlotPoint, Series, TIME_LABEL};

fn points(list: &[(f64, f64)]) -> Vec<PlotPoint> {
    list.iter()
        .map(|&(seconds, error)| PlotPoint { seconds, error })
        .collect()
}

fn example() -> ErrorTimePlot {
    ErrorTimePlot {
        title: "five_spheres.rtc: error against time".into(),
        error_label: "mean ꟻLIP".into(),
        series: vec![
            Series {
                name: "uniform f×f".into(),
                points: points(&[(0.05, 0.04), (0.12, 0.015), (0.4, 0.006), (1.5, 0.002)]),
                joined: true,
            },
            Series {
                name: "adaptive <min, max>".into(),
                points: points(&[(0.07, 0.02), (0.1, 0.007), (0.3, 0.003)]),
                joined: false,
            },
            Series {
                name: "exact".into(),
                // A zero error or time cannot sit on log axes: left out, not a failure.
                points: points(&[(6.0, 0.0), (0.0, 0.1)]),
                joined: true,
            },
        ],
        marked: Some(MarkedPoint {
            label: "scene's setting".into(),
            point: PlotPoint {
                seconds: 0.4,
                error: 0.006,
            },
        }),
    }
}

/// Every `<text>` element's content.
fn texts(svg: &str) -> Vec<String> {
    let doc = roxmltree::Document::parse(svg).unwrap_or_else(|e| panic!("not well-formed: {e}"));
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    doc.descendants()
        .filter(|n| n.has_tag_name("text"))
        .map(|n| n.text().unwrap_or("").trim().to_string())
        .collect()
}

#[test]
fn the_svg_is_well_formed_and_labelled() {
    let svg = example().to_svg().expect("draws");
    let texts = texts(&svg);
    for wanted in [
        "five_spheres.rtc: error against time",
        "mean ꟻLIP",
        TIME_LABEL,
        "uniform f×f",
        "adaptive <min, max>",
        "exact",
        FRONT_LABEL,
        "scene's setting",
    ] {
        assert!(
            texts.iter().any(|t| t == wanted),
            "no <text> reads {wanted:?}; texts: {texts:?}"
        );
    }
    // Log axes: tick labels span the decades of the data (times 0.05 to 1.5 s).
    assert!(texts.iter().any(|t| t == "0.1"), "{texts:?}");
    assert!(texts.iter().any(|t| t == "1"), "{texts:?}");
    // One dot per drawable point (7), the marked setting's ring and its legend ring, and the
    // legend dot of the loose (not joined) adaptive series.
    assert_eq!(svg.matches("<circle").count(), 10);
    // Joining the adaptive series adds its line and its legend's line, and drops its legend dot.
    let mut joined = example();
    joined.series[1].joined = true;
    let joined = joined.to_svg().expect("draws");
    assert_eq!(
        joined.matches("<polyline").count(),
        svg.matches("<polyline").count() + 2
    );
    assert_eq!(joined.matches("<circle").count(), 9);
}

#[test]
fn an_empty_plot_still_draws() {
    let plot = ErrorTimePlot {
        title: "nothing measured".into(),
        error_label: "RMSE".into(),
        series: Vec::new(),
        marked: None,
    };
    let texts = texts(&plot.to_svg().expect("draws"));
    assert!(texts.iter().any(|t| t == "RMSE"));
    assert!(texts.iter().any(|t| t == TIME_LABEL));
}
