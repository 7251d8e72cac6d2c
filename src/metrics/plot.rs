//! What accuracy costs in time, as a picture: an SVG plot of error against wall time, log-log, one
//! curve per named series, the Pareto front over all of them highlighted, and one marked point
//! (the scene's own setting).
//!
//! Drawn by `plotters`' SVG backend with its built-in text layout (no system fonts are read):
//! labels are SVG `<text>` elements that the viewer draws in its own sans-serif font.

use plotters::coord::Shift;
use plotters::prelude::*;

use crate::diag::{Diagnostic, Severity};

use super::pareto::pareto_front;

/// Drawing the plot failed.
const PLOT: &str = "rtc::metrics::plot";

/// The time axis' label.
pub const TIME_LABEL: &str = "wall time (s)";

/// The legend entry of the Pareto front.
pub const FRONT_LABEL: &str = "Pareto front";

/// Plot size in SVG pixels.
const SIZE: (u32, u32) = (800, 560);

/// One measured setting: its wall time and its error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlotPoint {
    /// Wall time in seconds.
    pub seconds: f64,
    /// Error against the reference (any metric; the plot's `error_label` names it).
    pub error: f64,
}

/// A named curve: the points of one ladder, in ladder order.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// The legend entry (e.g. "supersampling").
    pub name: String,
    /// The points, in this order.
    pub points: Vec<PlotPoint>,
    /// Draw a line through the points (a ladder); `false` draws them loose (a joint sweep).
    pub joined: bool,
}

/// A point drawn apart from the curves, with its own label (the scene's own setting).
#[derive(Clone, Debug, PartialEq)]
pub struct MarkedPoint {
    /// The legend entry and the text beside the point.
    pub label: String,
    /// Where it is.
    pub point: PlotPoint,
}

/// An error-versus-time plot.
#[derive(Clone, Debug, PartialEq)]
pub struct ErrorTimePlot {
    /// The caption above the plot.
    pub title: String,
    /// The error axis' label (e.g. "mean ꟻLIP").
    pub error_label: String,
    /// The curves.
    pub series: Vec<Series>,
    /// The highlighted setting, if any.
    pub marked: Option<MarkedPoint>,
}

impl ErrorTimePlot {
    /// The plot as an SVG document. Points with a time or error that is not positive and finite
    /// cannot sit on log axes and are left out (an exact setting has error 0).
    pub fn to_svg(&self) -> Result<String, Diagnostic> {
        let mut svg = String::new();
        {
            let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
            self.draw(&root).map_err(|e| {
                Diagnostic::new(
                    Severity::Error,
                    PLOT,
                    None,
                    format!("cannot draw the plot: {e}"),
                )
                .with_help("report this as a bug")
            })?;
        }
        Ok(svg)
    }

    fn draw(
        &self,
        root: &DrawingArea<SVGBackend<'_>, Shift>,
    ) -> Result<(), DrawingAreaErrorKind<<SVGBackend<'_> as DrawingBackend>::ErrorType>> {
        root.fill(&WHITE)?;
        let drawable = |p: &PlotPoint| on_log_axes(p.seconds) && on_log_axes(p.error);
        let all: Vec<PlotPoint> = self
            .series
            .iter()
            .flat_map(|s| s.points.iter().copied())
            .chain(self.marked.iter().map(|m| m.point))
            .filter(drawable)
            .collect();
        let (x_range, y_range) = (
            log_range(all.iter().map(|p| p.seconds)),
            log_range(all.iter().map(|p| p.error)),
        );
        let mut chart = ChartBuilder::on(root)
            .caption(&self.title, ("sans-serif", 22))
            .margin(16)
            .x_label_area_size(48)
            .y_label_area_size(72)
            .build_cartesian_2d(x_range.log_scale(), y_range.log_scale())?;
        chart
            .configure_mesh()
            .x_desc(TIME_LABEL)
            .y_desc(self.error_label.as_str())
            .x_label_formatter(&|v| short_number(*v))
            .y_label_formatter(&|v| short_number(*v))
            .label_style(("sans-serif", 14))
            .axis_desc_style(("sans-serif", 16))
            .draw()?;

        // The front first, wide and pale, so the curves stay readable on top of it.
        let pairs: Vec<(f64, f64)> = all.iter().map(|p| (p.seconds, p.error)).collect();
        let front: Vec<(f64, f64)> = pareto_front(&pairs).iter().map(|&i| pairs[i]).collect();
        let front_style = RGBColor(255, 170, 0).mix(0.55).stroke_width(10);
        chart
            .draw_series(LineSeries::new(front.iter().copied(), front_style))?
            .label(FRONT_LABEL)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], front_style));

        for (i, series) in self.series.iter().enumerate() {
            let color = Palette99::pick(i).to_rgba();
            let points: Vec<(f64, f64)> = series
                .points
                .iter()
                .filter(|p| drawable(p))
                .map(|p| (p.seconds, p.error))
                .collect();
            if series.joined {
                chart
                    .draw_series(LineSeries::new(
                        points.iter().copied(),
                        color.stroke_width(2),
                    ))?
                    .label(series.name.as_str())
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                    });
                chart.draw_series(points.iter().map(|&p| Circle::new(p, 4, color.filled())))?;
            } else {
                chart
                    .draw_series(points.iter().map(|&p| Circle::new(p, 3, color.filled())))?
                    .label(series.name.as_str())
                    .legend(move |(x, y)| Circle::new((x + 10, y), 3, color.filled()));
            }
        }

        if let Some(marked) = self.marked.as_ref().filter(|m| drawable(&m.point)) {
            let at = (marked.point.seconds, marked.point.error);
            let ring = BLACK.stroke_width(3);
            chart
                .draw_series([Circle::new(at, 9, ring)])?
                .label(marked.label.as_str())
                .legend(move |(x, y)| Circle::new((x + 10, y), 6, ring));
            // The text sits right of and above the ring, clear of the curve through it.
            let text_style = ("sans-serif", 14).into_font().color(&BLACK);
            chart.draw_series([
                EmptyElement::at(at) + Text::new(marked.label.clone(), (12, -22), text_style)
            ])?;
        }

        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 14))
            .draw()?;
        root.present()
    }
}

/// True for values a log axis can show.
fn on_log_axes(v: f64) -> bool {
    v.is_finite() && v > 0.0
}

/// A range around the values with half a decade of room on each side (1 to 10 when empty).
fn log_range(values: impl Iterator<Item = f64>) -> std::ops::Range<f64> {
    let (lo, hi) = values.fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if !lo.is_finite() {
        return 1.0..10.0;
    }
    let room = 10f64.sqrt();
    (lo / room)..(hi * room)
}

/// A tick label: plain for 0.001 to 10 000, scientific otherwise.
fn short_number(v: f64) -> String {
    if (1e-3..1e4).contains(&v.abs()) {
        let s = format!("{v:.4}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        format!("{v:.0e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tick_labels_are_short() {
        assert_eq!(short_number(0.5), "0.5");
        assert_eq!(short_number(20.0), "20");
        assert_eq!(short_number(0.0001), "1e-4");
        assert_eq!(short_number(1e5), "1e5");
    }

    #[test]
    fn ranges_leave_room_and_survive_no_points() {
        let r = log_range([0.1, 10.0].into_iter());
        assert!(r.start < 0.1 && r.end > 10.0);
        assert_eq!(log_range(std::iter::empty()), 1.0..10.0);
    }
}
