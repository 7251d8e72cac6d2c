//! Constructive solid geometry: the rules, apart from the objects they combine.
//!
//! Every operand reports all its boundary crossings along the ray's line (not only the first
//! hit) with whether the ray enters or leaves there, and whether the line starts inside it (a
//! half-space can). Walking the merged crossings in order keeps each operand's inside state;
//! wherever the combined state flips, the node itself has a boundary. States are *set* from
//! `entering`, not toggled, so a crossing reported twice (a mesh edge shared by two
//! triangles) cannot corrupt the classification. The traversal that gathers the crossings is
//! `Primitive`'s; this file holds the membership, boundary and bounds rules.

use glam::DVec3;

use crate::geometry::aabb::Aabb;
use crate::ir::CsgOp;

/// Combines operand memberships under `op` (for `Difference` the first is the base).
pub(crate) fn combine(op: CsgOp, mut states: impl Iterator<Item = bool>) -> bool {
    match op {
        CsgOp::Union | CsgOp::Merge => states.any(|s| s),
        CsgOp::Intersection => states.all(|s| s),
        CsgOp::Difference => states.next().unwrap_or(false) && !states.any(|s| s),
        CsgOp::Inverse => !states.next().unwrap_or(false),
        // A clipped surface has no inside; inside both stands for "shown" where it is asked.
        CsgOp::Clip => states.all(|s| s),
    }
}

/// The node's own boundary among its operands' crossings: `crossings` are `(operand, hit,
/// entering)` sorted along the ray, `states` each operand's membership where the line starts.
/// Calls `boundary(operand, hit, entering)` for every event where the combined membership
/// flips, in order.
///
/// Crossings that `same` says may be one place (within their error bounds: a cutter sharing a
/// face with the base, two boxes of a merge touching) form one event: all their operands change
/// state together and the membership is compared only before and after the whole event. Applied
/// one at a time, in whatever order rounding sorted them, they would flip the result twice and
/// leave a zero-thickness lid (or, in glass, an inner interface). The event's hit is one whose
/// own operand moved the result the way it went (its surface is the one that shows).
pub(crate) fn boundary<H: Copy>(
    op: CsgOp,
    mut states: Vec<bool>,
    crossings: &[(usize, H, bool)],
    same: impl Fn(&H, &H) -> bool,
    mut boundary: impl FnMut(usize, H, bool),
) {
    let mut inside = combine(op, states.iter().copied());
    let mut start = 0;
    while start < crossings.len() {
        let mut end = start + 1;
        while end < crossings.len() && same(&crossings[end - 1].1, &crossings[end].1) {
            end += 1;
        }
        let event = &crossings[start..end];
        for &(i, _, entering) in event {
            states[i] = entering;
        }
        let now = combine(op, states.iter().copied());
        if now != inside {
            let shown = event
                .iter()
                .find(|&&(i, _, entering)| drives(op, i, entering, now))
                .unwrap_or(&event[0]);
            boundary(shown.0, shown.1, now);
            inside = now;
        }
        start = end;
    }
}

/// Whether operand `i` entering (or leaving) moves the result of `op` into (out of) the solid
/// when the result becomes `now`: a subtracted operand does so by leaving.
fn drives(op: CsgOp, i: usize, entering: bool, now: bool) -> bool {
    if flips_normal(op, i) {
        entering != now
    } else {
        entering == now
    }
}

/// Whether a boundary crossing on operand `i` shows that operand's surface turned inside out
/// (a subtracted operand's surface, and an inverted one, faces the other way on the result).
pub(crate) fn flips_normal(op: CsgOp, i: usize) -> bool {
    (op == CsgOp::Difference && i > 0) || op == CsgOp::Inverse
}

/// Bounds of a CSG node from its operands' bounds (all in the node's space): an intersection is
/// bounded by the overlap of its operands, a difference by its base, a union or merge by all
/// operands. An empty intersection gives [`Aabb::EMPTY`], which no ray meets. An inverted
/// solid is unbounded (its surface is its operand's, but bounds here bound the solid, which an
/// intersection or difference around it relies on); a clipped surface lies in the overlap of
/// its surface and its clipper.
pub(crate) fn bounds(op: CsgOp, children: &[Aabb]) -> Aabb {
    let infinite = Aabb::new(DVec3::NEG_INFINITY, DVec3::INFINITY);
    match op {
        CsgOp::Union | CsgOp::Merge => children.iter().fold(Aabb::EMPTY, |b, c| b.union(*c)),
        CsgOp::Intersection | CsgOp::Clip => {
            children.iter().fold(infinite, |b, c| b.intersection(*c))
        }
        CsgOp::Inverse => infinite,
        CsgOp::Difference => children.first().copied().unwrap_or(Aabb::EMPTY),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn b(lo: f64, hi: f64) -> Aabb {
        Aabb::new(DVec3::splat(lo), DVec3::splat(hi))
    }

    #[test]
    fn intersection_is_the_overlap_and_difference_the_base() {
        assert_eq!(
            bounds(CsgOp::Intersection, &[b(0.0, 2.0), b(1.0, 3.0)]),
            b(1.0, 2.0)
        );
        assert_eq!(
            bounds(CsgOp::Difference, &[b(0.0, 2.0), b(-5.0, 5.0)]),
            b(0.0, 2.0)
        );
        assert_eq!(
            bounds(CsgOp::Union, &[b(0.0, 2.0), b(1.0, 3.0)]),
            b(0.0, 3.0)
        );
        assert!(bounds(CsgOp::Intersection, &[b(0.0, 1.0), b(2.0, 3.0)]).is_empty());
    }

    #[test]
    fn boundary_reports_only_where_membership_flips() {
        // Two overlapping intervals [0, 2] and [1, 3] along the line.
        let crossings = [
            (0, 0.0, true),
            (1, 1.0, true),
            (0, 2.0, false),
            (1, 3.0, false),
        ];
        let run = |op| {
            let mut out = Vec::new();
            boundary(
                op,
                vec![false, false],
                &crossings,
                |a: &f64, b: &f64| a == b,
                |_, t, e| out.push((t, e)),
            );
            out
        };
        assert_eq!(run(CsgOp::Union), vec![(0.0, true), (3.0, false)]);
        assert_eq!(run(CsgOp::Intersection), vec![(1.0, true), (2.0, false)]);
        assert_eq!(run(CsgOp::Difference), vec![(0.0, true), (1.0, false)]);
    }

    #[test]
    fn crossings_at_one_place_are_one_event() {
        // A base [0, 2] and a cutter [0, 1] sharing the face at 0, then a cutter [1.5, 2]
        // sharing the face at 2: the difference is [1, 1.5] with no lid at 0 or 2.
        let crossings = [
            (0, 0.0, true),
            (1, 0.0, true),
            (1, 1.0, false),
            (2, 1.5, true),
            (0, 2.0, false),
            (2, 2.0, false),
        ];
        let mut out = Vec::new();
        boundary(
            CsgOp::Difference,
            vec![false; 3],
            &crossings,
            |a: &f64, b: &f64| a == b,
            |i, t, e| out.push((i, t, e)),
        );
        assert_eq!(out, vec![(1, 1.0, true), (2, 1.5, false)]);
        // Two boxes of a merge touching at 1: one solid [0, 2], no face between.
        let touching = [
            (0, 0.0, true),
            (0, 1.0, false),
            (1, 1.0, true),
            (1, 2.0, false),
        ];
        let mut merged = Vec::new();
        boundary(
            CsgOp::Merge,
            vec![false; 2],
            &touching,
            |a: &f64, b: &f64| a == b,
            |_, t, e| merged.push((t, e)),
        );
        assert_eq!(merged, vec![(0.0, true), (2.0, false)]);
    }
}
