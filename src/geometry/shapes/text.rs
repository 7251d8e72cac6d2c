//! `text`: glyph outlines laid out on a line (by the asset service's font reader), each glyph a
//! cluster of the shared swept-outline core ([`super::extrusion`]) with its own box, filled by
//! the nonzero rule as TrueType draws them, extruded from `z = 0` back to `z = −thickness`.

use super::extrusion::{Axes, Extrusion, FillRule, Segment, Sweep};
use crate::ir::{GlyphCurve, TextGlyphs};

/// The segment a glyph curve is.
fn segment(c: &GlyphCurve) -> Segment {
    match *c {
        GlyphCurve::Line([p, q]) => Segment::line(p, q),
        GlyphCurve::Quad([p0, p1, p2]) => Segment::quad_bezier(p0, p1, p2),
        GlyphCurve::Cubic([p0, p1, p2, p3]) => Segment::cubic_bezier(p0, p1, p2, p3),
    }
}

/// The solid of `glyphs` extruded `thickness` deep, or `None` when no glyph has area (a string
/// of spaces) or a coordinate is not finite.
pub(crate) fn build(glyphs: &TextGlyphs, thickness: f64) -> Option<Extrusion> {
    let clusters: Vec<Vec<Segment>> = glyphs
        .glyphs
        .iter()
        .map(|g| {
            g.iter()
                .map(segment)
                // A curve that starts where it ends with no extent adds nothing.
                .filter(|s| s.at(0.0) != s.at(1.0) || s.at(0.5) != s.at(0.0))
                .collect::<Vec<_>>()
        })
        .filter(|g: &Vec<Segment>| !g.is_empty())
        .collect();
    if clusters.iter().flatten().any(|s| !s.is_finite()) {
        return None;
    }
    Extrusion::new(
        &clusters,
        FillRule::NonZero,
        Sweep::Linear,
        Axes::FrontBack,
        0.0,
        thickness,
    )
}

/// The width of a glyph's box (tests).
#[cfg(test)]
fn width(g: &[GlyphCurve]) -> f64 {
    use glam::DVec2;
    let xs = g.iter().flat_map(|c| match c {
        GlyphCurve::Line(p) => p.to_vec(),
        GlyphCurve::Quad(p) => p.to_vec(),
        GlyphCurve::Cubic(p) => p.to_vec(),
    });
    let (lo, hi) = xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p: DVec2| {
        (l.min(p.x), h.max(p.x))
    });
    hi - lo
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::ray::Ray;
    use glam::{DVec2, DVec3};

    /// A square ring: outer clockwise, inner counter-clockwise (TrueType's hole).
    fn ring() -> TextGlyphs {
        let v = DVec2::new;
        let outer = [v(0.0, 0.0), v(0.0, 1.0), v(1.0, 1.0), v(1.0, 0.0)];
        let inner = [v(0.25, 0.25), v(0.75, 0.25), v(0.75, 0.75), v(0.25, 0.75)];
        let mut g = Vec::new();
        for c in [&outer, &inner] {
            for i in 0..4 {
                g.push(GlyphCurve::Line([c[i], c[(i + 1) % 4]]));
            }
        }
        TextGlyphs { glyphs: vec![g] }
    }

    #[test]
    fn a_hole_lets_a_ray_through_and_the_rim_stops_it() {
        let glyphs = ring();
        assert_eq!(width(&glyphs.glyphs[0]), 1.0);
        let x = build(&glyphs, 0.2).unwrap();
        let down = DVec3::new(0.0, 0.0, -1.0);
        let through = Ray::new(DVec3::new(0.5, 0.5, 5.0), down);
        assert!(x.intersect(&through, 0.0, f64::INFINITY).is_none());
        let rim = Ray::new(DVec3::new(0.1, 0.5, 5.0), down);
        let h = x.intersect(&rim, 0.0, f64::INFINITY).unwrap();
        assert!((h.t - 5.0).abs() < 1e-12 && h.normal == DVec3::Z);
        // From the side, the hole's wall faces into the hole.
        let side = Ray::new(DVec3::new(0.5, 0.5, -0.1), DVec3::X);
        let h = x.intersect(&side, 0.0, f64::INFINITY).unwrap();
        assert!((h.t - 0.25).abs() < 1e-12, "{h:?}");
        assert!((h.normal - DVec3::NEG_X).abs().max_element() < 1e-12);
        assert!(x.contains(DVec3::new(0.1, 0.5, -0.1)));
        assert!(!x.contains(DVec3::new(0.5, 0.5, -0.1)));
        assert!(!x.contains(DVec3::new(0.1, 0.5, 0.1)));
    }
}
