//! Depth buffer: grey from white at `near` to black at `far`, linear in the distance along the
//! camera ray, clamped; misses are black. With [`DepthRange::Auto`](crate::ir::DepthRange) the
//! renderer first finds the nearest and farthest hit distance over the whole image and uses those
//! (so the nearest hit is white and the farthest black). The student convention
//! `255·(1000 − t)/500` of `scene01-zbuffer__ole.png` is `Fixed { near: 500, far: 1000 }`.

use glam::DVec3;

use crate::ir::Color;

/// The grey of a hit at distance `t` for the range `near..far`.
pub fn grey(t: f64, near: f64, far: f64) -> Color {
    let g = if far == near {
        if t <= near { 1.0 } else { 0.0 }
    } else {
        (far - t) / (far - near)
    };
    DVec3::splat(g.clamp(0.0, 1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn near_is_white_far_is_black() {
        assert_eq!(grey(500.0, 500.0, 1000.0), DVec3::ONE);
        assert_eq!(grey(1000.0, 500.0, 1000.0), DVec3::ZERO);
        assert_eq!(grey(750.0, 500.0, 1000.0), DVec3::splat(0.5));
        assert_eq!(grey(2000.0, 500.0, 1000.0), DVec3::ZERO);
        assert_eq!(grey(3.0, 3.0, 3.0), DVec3::ONE);
    }
}
