//! The rules of the shapes drawn from a spline outline, `prism` (an outline in the ground
//! plane, swept up) and `lathe` (a profile, revolved): how many points each spline needs, the
//! outline closed, some area, each flaw naming the parameter to blame. They return the shape,
//! not its `Leaf`, so this file stays below the module root (no circle through `mod.rs`).

use glam::DVec2;

use crate::diag::number;
use crate::ir::{PrismSweep, Spline};

use super::extrusion::{Extrusion, Sweep};
use super::flaw::{NOT_CLOSED, OUT_OF_RANGE, ShapeFlaw, in_range};
use super::lathe::{Lathe, segment_count};
use super::prism::{self, OutlineError};

/// A prism's rules: heights in order (and not below the apex for a conic sweep), enough points
/// for the spline, every sub-outline closed, some area.
pub(super) fn prism_leaf(
    points: &[DVec2],
    heights: [f64; 2],
    spline: Spline,
    sweep: PrismSweep,
) -> Result<Extrusion, ShapeFlaw> {
    let [h0, h1] = heights;
    in_range(h0.is_finite(), "heights", "finite", h0)?;
    in_range(h1.is_finite(), "heights", "finite", h1)?;
    if h1 <= h0 {
        return Err(ShapeFlaw::other(
            "heights",
            OUT_OF_RANGE,
            "a prism's `heights` must be `[low, high]` with low < high",
            format!("[{}, {}]", number(h0), number(h1)),
            format!(
                "write `heights: [{}, {}]`",
                number(h1.min(h0)),
                number(h1.max(h0) + if h1 == h0 { 1.0 } else { 0.0 })
            ),
        ));
    }
    let conic = sweep == PrismSweep::Conic;
    if conic && h0 < 0.0 {
        return Err(ShapeFlaw::other(
            "heights",
            OUT_OF_RANGE,
            "a conic prism's heights must be at least 0 (the apex is at the origin)",
            format!("low height {}", number(h0)),
            "write `heights: [0, 1]` and place the prism with `.translate(..)`",
        ));
    }
    if points.iter().any(|p| !p.is_finite()) {
        return Err(ShapeFlaw::range("points", "finite", f64::NAN));
    }
    let subs = prism::outline(points, spline).map_err(|e| {
        let name = spline.name();
        match e {
            OutlineError::TooFew => ShapeFlaw::other(
                "points",
                OUT_OF_RANGE,
                format!(
                    "a {name} prism needs at least {} points, found {}",
                    spline.min_points(),
                    points.len()
                ),
                "too few points",
                match spline {
                    Spline::Linear => "list three or more corners and repeat the first at the end",
                    Spline::Quadratic => "add a control point before the first corner and repeat the first corner at the end",
                    Spline::Cubic => "add a control point before the first corner, repeat the first corner, then one control point after it",
                    Spline::Bezier => "give four points per segment: start, two controls, end",
                },
            ),
            OutlineError::NotFours => ShapeFlaw::other(
                "points",
                OUT_OF_RANGE,
                format!("a bezier prism needs four points per segment, found {}", points.len()),
                format!("{} points is not a multiple of 4", points.len()),
                "give each segment as start, control, control, end",
            ),
            OutlineError::NotClosed => ShapeFlaw::other(
                "points",
                NOT_CLOSED,
                format!("the {name} prism's outline does not close"),
                "a sub-outline does not come back to its first point",
                match spline {
                    Spline::Linear => "repeat the first point of each sub-outline at its end",
                    Spline::Quadratic => "end each sub-outline with its first corner (the point after its control point)",
                    Spline::Cubic => "end each sub-outline with its first corner (the point after its control point), then one more control point",
                    Spline::Bezier => "end the last segment of each sub-outline on the first segment's start point",
                },
            ),
        }
    })?;
    let how = if conic { Sweep::Conic } else { Sweep::Linear };
    prism::build(&subs, how, h0, h1).ok_or_else(|| {
        ShapeFlaw::degenerate(
            "points",
            "the prism's outline encloses no area",
            "its points lie on one line",
            "spread the points out so they enclose an area",
        )
    })
}

/// A lathe's rules: enough points for its spline, each finite with `r >= 0`, and a profile
/// with some extent.
pub(super) fn lathe(points: &[[f64; 2]], spline: Spline) -> Result<Lathe, ShapeFlaw> {
    let (least, what) = match spline {
        Spline::Linear => (2, "2 points"),
        Spline::Quadratic => (3, "3 points (the first only steers)"),
        Spline::Cubic => (4, "4 points (the first and last only steer)"),
        Spline::Bezier => (4, "4 points per segment"),
    };
    let name = spline.name();
    if points.len() < least || (spline == Spline::Bezier && !points.len().is_multiple_of(4)) {
        return Err(ShapeFlaw::other(
            "points",
            OUT_OF_RANGE,
            format!(
                "a `{name}` lathe needs at least {what}, found {}",
                points.len()
            ),
            format!("{} points", points.len()),
            if spline == Spline::Bezier {
                "give 4 points per Bézier segment (end, control, control, end)".to_owned()
            } else {
                format!("add points until there are at least {least}")
            },
        ));
    }
    for p in points {
        if !(p[0].is_finite() && p[1].is_finite()) {
            return Err(ShapeFlaw::other(
                "points",
                OUT_OF_RANGE,
                "a lathe point is not finite",
                "a coordinate is infinite or not a number",
                "use finite `[r, y]` pairs",
            ));
        }
        in_range(
            p[0] >= 0.0,
            "points",
            "r >= 0 (the profile is right of the axis)",
            p[0],
        )?;
    }
    debug_assert!(segment_count(spline, points.len()) > 0);
    Lathe::new(points, spline).ok_or_else(|| {
        ShapeFlaw::degenerate(
            "points",
            "the lathe's profile encloses no area",
            "its points lie on one line or on the axis",
            "move points away from the axis and off one line, e.g. `[[0, 0], [1, 0], [1, 1], [0, 1]]`",
        )
    })
}
