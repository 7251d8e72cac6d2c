//! POV-Ray's `prism`: an outline of linear, quadratic, cubic or Bézier spline segments in the
//! ground plane (`[x, z]` points), swept up `y` linearly or conically ([`super::extrusion`]).
//! The points are read as POV-Ray 3.7 reads them (`source/core/shape/prism.cpp`): a sub-outline
//! closes where a point repeats its first point, and the next begins after it.

use glam::DVec2;

use super::extrusion::{Axes, Extrusion, FillRule, Segment, Sweep};
use crate::ir::Spline;

/// Why a prism's outline cannot be built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum OutlineError {
    /// Fewer points than the spline needs.
    TooFew,
    /// A Bézier outline whose count is not a multiple of four.
    NotFours,
    /// A sub-outline that does not come back to its first point.
    NotClosed,
}

/// The closed sub-outlines the points describe, each a list of segments.
pub(crate) fn outline(points: &[DVec2], spline: Spline) -> Result<Vec<Vec<Segment>>, OutlineError> {
    let n = points.len();
    if n < spline.min_points() {
        return Err(OutlineError::TooFew);
    }
    let scale = points
        .iter()
        .fold(0.0f64, |m, p| m.max(p.abs().max_element()));
    let same = |a: DVec2, b: DVec2| (a - b).abs().max_element() <= 1e-10 * scale.max(1.0);
    let p = points;
    let mut subs = Vec::new();
    let mut cur: Vec<Segment> = Vec::new();
    if spline == Spline::Bezier {
        if !n.is_multiple_of(4) {
            return Err(OutlineError::NotFours);
        }
        let mut start = 0;
        for g in (0..n).step_by(4) {
            if g > 0 && !same(p[g], p[g - 1]) {
                // A new sub-outline begins: the last one must have come back to its start.
                if !same(p[g - 1], p[start]) {
                    return Err(OutlineError::NotClosed);
                }
                subs.push(std::mem::take(&mut cur));
                start = g;
            }
            cur.push(Segment::cubic_bezier(p[g], p[g + 1], p[g + 2], p[g + 3]));
        }
        if !same(p[n - 1], p[start]) {
            return Err(OutlineError::NotClosed);
        }
        subs.push(cur);
        return Ok(subs);
    }
    // Points a segment reads past `i`, the first point's offset, and where the next
    // sub-outline begins after one closes at segment `i`.
    let (reach, first_at, next) = match spline {
        Spline::Linear => (1, 0, 2),
        Spline::Quadratic => (2, 1, 3),
        Spline::Cubic => (3, 1, 4),
        Spline::Bezier => unreachable!("handled above"),
    };
    let mut first = p[first_at];
    let mut i = 0;
    while i + 1 < n {
        if i + reach >= n {
            return Err(OutlineError::NotClosed);
        }
        let end = if spline == Spline::Linear {
            i + 1
        } else {
            i + 2
        };
        cur.push(match spline {
            Spline::Linear => Segment::line(p[i], p[i + 1]),
            Spline::Quadratic => Segment::from_power([
                p[i + 1],
                0.5 * (p[i + 2] - p[i]),
                0.5 * p[i] - p[i + 1] + 0.5 * p[i + 2],
                DVec2::ZERO,
            ]),
            _ => Segment::from_power([
                p[i + 1],
                0.5 * (p[i + 2] - p[i]),
                p[i] - 2.5 * p[i + 1] + 2.0 * p[i + 2] - 0.5 * p[i + 3],
                -0.5 * p[i] + 1.5 * p[i + 1] - 1.5 * p[i + 2] + 0.5 * p[i + 3],
            ]),
        });
        if same(p[end], first) {
            subs.push(std::mem::take(&mut cur));
            i += next;
            if i + first_at < n {
                first = p[i + first_at];
            }
        } else {
            i += 1;
        }
    }
    if !cur.is_empty() || subs.is_empty() {
        return Err(OutlineError::NotClosed);
    }
    Ok(subs)
}

/// A prism: the outline swept between `heights` (even-odd fill, as POV-Ray), or `None` when it
/// encloses no area.
pub(crate) fn build(subs: &[Vec<Segment>], sweep: Sweep, h0: f64, h1: f64) -> Option<Extrusion> {
    let all: Vec<Segment> = subs.iter().flatten().copied().collect();
    if all.iter().any(|s| !s.is_finite()) {
        return None;
    }
    // Each sub-outline its own cluster: a box test skips the ones a ray misses.
    Extrusion::new(subs, FillRule::EvenOdd, sweep, Axes::GroundUp, h0, h1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> DVec2 {
        DVec2::new(x, y)
    }

    #[test]
    fn linear_square_with_a_hole_is_two_sub_outlines() {
        let pts = [
            v(-2.0, -2.0),
            v(2.0, -2.0),
            v(2.0, 2.0),
            v(-2.0, 2.0),
            v(-2.0, -2.0),
            v(-1.0, -1.0),
            v(1.0, -1.0),
            v(1.0, 1.0),
            v(-1.0, 1.0),
            v(-1.0, -1.0),
        ];
        let subs = outline(&pts, Spline::Linear).unwrap();
        assert_eq!(subs.iter().map(Vec::len).collect::<Vec<_>>(), vec![4, 4]);
    }

    #[test]
    fn open_outlines_are_refused() {
        let pts = [v(0.0, 0.0), v(1.0, 0.0), v(1.0, 1.0), v(0.0, 1.0)];
        assert_eq!(outline(&pts, Spline::Linear), Err(OutlineError::NotClosed));
        assert_eq!(
            outline(&pts[..2], Spline::Linear),
            Err(OutlineError::TooFew)
        );
        assert_eq!(
            outline(&[v(0.0, 0.0); 5], Spline::Bezier),
            Err(OutlineError::NotFours)
        );
    }

    #[test]
    fn cubic_segments_interpolate_their_inner_points() {
        // POV-Ray's cubic spline passes through p[i+1] and p[i+2].
        let pts = [
            v(0.0, -1.0),
            v(1.0, 0.0),
            v(0.0, 1.0),
            v(-1.0, 0.0),
            v(0.0, -1.0),
            v(1.0, 0.0),
            v(0.0, 1.0),
        ];
        let subs = outline(&pts, Spline::Cubic).unwrap();
        let s = &subs[0];
        assert_eq!(s.len(), 4);
        assert!((s[0].at(0.0) - v(1.0, 0.0)).abs().max_element() < 1e-15);
        assert!((s[0].at(1.0) - v(0.0, 1.0)).abs().max_element() < 1e-15);
    }
}
