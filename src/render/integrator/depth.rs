//! Depth images: grey from white at `near` to black at `far`, linear in the distance along the
//! camera ray, clamped; misses are black. With [`DepthRange::Auto`] an image-wide pass first
//! finds the nearest and farthest hit distance over every camera sample (so the nearest hit is
//! white and the farthest black). The student convention `255·(1000 − t)/500` of
//! `scene01-zbuffer__ole.png` is `Fixed { near: 500, far: 1000 }`.

use glam::DVec3;

use crate::diag::Diagnostic;
use crate::geometry::Ray;
use crate::ir::{Color, DepthRange, Visibility};
use crate::opt::Prepared;
use crate::render::progress::Silent;
use crate::render::shard::Rows;
use crate::render::tiles;
use crate::render::view::FirstRays;

/// The depth-image integrator with its distance range.
pub(crate) struct DepthImage<'a> {
    scene: &'a Prepared,
    near: f64,
    far: f64,
}

impl<'a> DepthImage<'a> {
    /// The scene it images.
    pub(crate) fn scene(&self) -> &'a Prepared {
        self.scene
    }

    /// The integrator for `range`; an automatic range is measured over the rays of `first`.
    pub(crate) fn new(
        scene: &'a Prepared,
        range: DepthRange,
        first: &FirstRays<'_>,
        pool: &rayon::ThreadPool,
    ) -> Result<DepthImage<'a>, Diagnostic> {
        let (near, far) = match range {
            DepthRange::Fixed { near, far } => (near, far),
            DepthRange::Auto => hit_range(scene, first, pool)?,
        };
        Ok(DepthImage { scene, near, far })
    }

    /// The grey of the first hit along `ray`.
    pub(crate) fn color(&self, ray: &Ray) -> Color {
        self.scene
            .world()
            .intersect(ray, 0.0, f64::INFINITY)
            .map_or(Color::ZERO, |h| grey(h.t, self.near, self.far))
    }
}

/// The grey of a hit at distance `t` for the range `near..far`.
fn grey(t: f64, near: f64, far: f64) -> Color {
    let g = if far == near {
        if t <= near { 1.0 } else { 0.0 }
    } else {
        (far - t) / (far - near)
    };
    DVec3::splat(g.clamp(0.0, 1.0))
}

/// The nearest and farthest camera-ray hit distances over every sample of the image; (0, 0)
/// when nothing is hit.
fn hit_range(
    scene: &Prepared,
    first: &FirstRays<'_>,
    pool: &rayon::ThreadPool,
) -> Result<(f64, f64), Diagnostic> {
    let (w, h) = first.size;
    let (ranges, _) = tiles::run(pool, w, h, 1, Rows::All, &Silent, |x, y, _ctx, out| {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for k in 0..first.samples {
            let ray = (first.ray)(x, y, k);
            if crate::render::panorama::is_blind(&ray) {
                continue;
            }
            if let Some(hit) = scene.seen_hit(&ray, 0.0, f64::INFINITY, Visibility::NO_IMAGE) {
                lo = lo.min(hit.t);
                hi = hi.max(hit.t);
            }
        }
        out[0] = DVec3::new(lo, hi, 0.0);
    })?;
    let lo = ranges.iter().map(|r| r.x).fold(f64::INFINITY, f64::min);
    let hi = ranges.iter().map(|r| r.y).fold(f64::NEG_INFINITY, f64::max);
    Ok(if lo.is_finite() { (lo, hi) } else { (0.0, 0.0) })
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
