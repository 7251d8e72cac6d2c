//! Constructive solid geometry: classification along the whole ray.
//!
//! Every operand reports all its boundary crossings along the ray's line (not only the first
//! hit) with whether the ray enters or leaves there, and whether the line starts inside it (a
//! half-space can). Walking the merged crossings in order keeps each operand's inside state;
//! wherever the combined state flips, the node itself has a boundary. States are *set* from
//! `entering`, not toggled, so a crossing reported twice (a mesh edge shared by two
//! triangles) cannot corrupt the classification.

use super::Ray;
use super::primitive::{GeoHit, Primitive, PrimitiveCrossing};
use crate::ir::CsgOp;

/// Combines operand memberships under `op` (for `Difference` the first is the base).
pub fn combine(op: CsgOp, mut states: impl Iterator<Item = bool>) -> bool {
    match op {
        CsgOp::Union | CsgOp::Merge => states.any(|s| s),
        CsgOp::Intersection => states.all(|s| s),
        CsgOp::Difference => states.next().unwrap_or(false) && !states.any(|s| s),
    }
}

/// The node's own boundary crossings along the whole line, in order.
pub fn crossings(op: CsgOp, children: &[Primitive], ray: &Ray, out: &mut Vec<PrimitiveCrossing>) {
    let mut all: Vec<(usize, PrimitiveCrossing)> = Vec::new();
    let mut tmp = Vec::new();
    for (i, c) in children.iter().enumerate() {
        tmp.clear();
        c.crossings(ray, &mut tmp);
        all.extend(tmp.iter().map(|x| (i, *x)));
    }
    all.sort_by(|a, b| a.1.hit.t.total_cmp(&b.1.hit.t));
    let mut states: Vec<bool> = children.iter().map(|c| c.inside_at_start(ray)).collect();
    let mut inside = combine(op, states.iter().copied());
    for (i, c) in all {
        states[i] = c.entering;
        let now = combine(op, states.iter().copied());
        if now != inside {
            let mut hit = c.hit;
            // A subtracted operand's surface faces the other way on the result.
            if op == CsgOp::Difference && i > 0 {
                hit.normal = -hit.normal;
                hit.geometric_normal = -hit.geometric_normal;
            }
            out.push(PrimitiveCrossing { hit, entering: now });
            inside = now;
        }
    }
}

/// Nearest hit in (t_min, t_max). A union keeps its operands' inner surfaces (visible through
/// transparent materials); merge, intersection and difference show only the result's boundary.
pub fn intersect(
    op: CsgOp,
    children: &[Primitive],
    ray: &Ray,
    t_min: f64,
    t_max: f64,
) -> Option<GeoHit> {
    if op == CsgOp::Union {
        let mut best: Option<GeoHit> = None;
        let mut far = t_max;
        for c in children {
            if let Some(h) = c.intersect(ray, t_min, far) {
                far = h.t;
                best = Some(h);
            }
        }
        return best;
    }
    let mut out = Vec::new();
    crossings(op, children, ray, &mut out);
    out.into_iter()
        .map(|c| c.hit)
        .find(|h| h.t > t_min && h.t < t_max)
}
