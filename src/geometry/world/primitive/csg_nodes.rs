//! The walks of CSG nodes along a ray: a node's own boundary among its operands' crossings
//! (the rules are `geometry::shapes::csg`'s), its nearest hit, and a clipped surface's.

use crate::geometry::ray::Ray;
use crate::geometry::rounding;
use crate::geometry::shapes::csg;
use crate::ir::CsgOp;

use super::{GeoHit, Primitive, PrimitiveCrossing};

/// A CSG node's own boundary crossings along the whole line, in order.
pub(super) fn csg_crossings(
    op: CsgOp,
    children: &[Primitive],
    ray: &Ray,
    out: &mut Vec<PrimitiveCrossing>,
) {
    let mut all: Vec<(usize, GeoHit, bool)> = Vec::new();
    let mut tmp = Vec::new();
    for (i, c) in children.iter().enumerate() {
        tmp.clear();
        c.crossings(ray, &mut tmp);
        all.extend(tmp.iter().map(|x| (i, x.hit, x.entering)));
    }
    all.sort_by(|a, b| a.1.t.total_cmp(&b.1.t));
    let starts = children.iter().map(|c| c.inside_at_start(ray)).collect();
    let same = |a: &GeoHit, b: &GeoHit| {
        rounding::same_event(
            a.point,
            a.error,
            a.geometric_normal,
            b.point,
            b.error,
            b.geometric_normal,
        )
    };
    csg::boundary(op, starts, &all, same, |i, mut hit, entering| {
        if csg::flips_normal(op, i) {
            hit.normal = -hit.normal;
            hit.geometric_normal = -hit.geometric_normal;
        }
        out.push(PrimitiveCrossing { hit, entering });
    });
}

/// A CSG node's nearest hit in (t_min, t_max). A union keeps its operands' inner surfaces
/// (visible through transparent materials); merge, intersection and difference show only the
/// result's boundary.
pub(super) fn csg_intersect(
    op: CsgOp,
    children: &[Primitive],
    ray: &Ray,
    t_min: f64,
    t_max: f64,
) -> Option<GeoHit> {
    if op == CsgOp::Clip {
        return clip_intersect(children, ray, t_min, t_max);
    }
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
    csg_crossings(op, children, ray, &mut out);
    out.into_iter()
        .map(|c| c.hit)
        .find(|h| h.t > t_min && h.t < t_max)
}

/// How many of its surface's hits a clipped object tries along one ray before it gives up (a
/// dense mesh clipped to a sliver); each try is one nearest-hit query of the surface.
const CLIP_TRIES: usize = 4096;

/// A clipped surface's nearest hit in (t_min, t_max): the first hit of the surface (the first
/// operand) that lies inside the clipper (the second, a solid). The clipper's crossings along
/// the whole line are gathered once, and only when the surface is hit at all; a hit exactly on
/// the clipper's boundary counts as outside.
fn clip_intersect(children: &[Primitive], ray: &Ray, t_min: f64, t_max: f64) -> Option<GeoHit> {
    let (surface, clippers) = children.split_first()?;
    let mut hit = surface.intersect(ray, t_min, t_max)?;
    let clips: Vec<(bool, Vec<PrimitiveCrossing>)> = clippers
        .iter()
        .map(|c| {
            let mut crossings = Vec::new();
            c.crossings(ray, &mut crossings);
            (c.inside_at_start(ray), crossings)
        })
        .collect();
    for _ in 0..CLIP_TRIES {
        let inside = clips.iter().all(|(start, crossings)| {
            crossings
                .iter()
                .take_while(|c| c.hit.t < hit.t)
                .last()
                .map_or(*start, |c| c.entering)
        });
        if inside {
            return Some(hit);
        }
        hit = surface.intersect(ray, hit.t, t_max)?;
    }
    None
}
