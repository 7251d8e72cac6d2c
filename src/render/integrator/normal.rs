//! Normal images: `(N + 1) / 2` of the outward normal at the first hit (COURSE.md §2.5), which
//! quantises to the consensus `trunc(255·(N+1)/2)`; misses are black.

use glam::DVec3;

use crate::geometry::Ray;
use crate::ir::Color;
use crate::opt::Prepared;

/// The normal-image integrator.
pub(crate) struct NormalImage<'a> {
    scene: &'a Prepared,
}

impl<'a> NormalImage<'a> {
    /// The scene it images.
    pub(crate) fn scene(&self) -> &'a Prepared {
        self.scene
    }

    /// The integrator for `scene`.
    pub(crate) fn new(scene: &'a Prepared) -> NormalImage<'a> {
        NormalImage { scene }
    }

    /// The colour of the first hit along `ray`.
    pub(crate) fn color(&self, ray: &Ray) -> Color {
        self.scene
            .world()
            .intersect(ray, 0.0, f64::INFINITY)
            .map_or(Color::ZERO, |h| encode(h.normal))
    }
}

/// The colour that encodes a unit normal.
fn encode(n: DVec3) -> Color {
    (n + DVec3::ONE) * 0.5
}
