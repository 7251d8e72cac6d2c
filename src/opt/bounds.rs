//! Tight bounds for CSG: an intersection is bounded by the overlap of its operands, a
//! difference by its base, a union or merge by all operands.

use glam::DVec3;

use crate::geometry::Aabb;
use crate::ir::CsgOp;

/// Bounds of a CSG node from its operands' bounds (all in the node's space). An empty
/// intersection gives [`Aabb::EMPTY`], which no ray meets.
pub fn csg_bounds(op: CsgOp, children: &[Aabb]) -> Aabb {
    let infinite = Aabb::new(DVec3::NEG_INFINITY, DVec3::INFINITY);
    match op {
        CsgOp::Union | CsgOp::Merge => children.iter().fold(Aabb::EMPTY, |b, c| b.union(*c)),
        CsgOp::Intersection => children.iter().fold(infinite, |b, c| b.intersection(*c)),
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
            csg_bounds(CsgOp::Intersection, &[b(0.0, 2.0), b(1.0, 3.0)]),
            b(1.0, 2.0)
        );
        assert_eq!(
            csg_bounds(CsgOp::Difference, &[b(0.0, 2.0), b(-5.0, 5.0)]),
            b(0.0, 2.0)
        );
        assert_eq!(
            csg_bounds(CsgOp::Union, &[b(0.0, 2.0), b(1.0, 3.0)]),
            b(0.0, 3.0)
        );
        assert!(csg_bounds(CsgOp::Intersection, &[b(0.0, 1.0), b(2.0, 3.0)]).is_empty());
    }
}
