//! Surface-coordinate images: the first hit's (u, v) as red and green (their fractional parts,
//! so a repeating mapping shows its tiles), blue 0; misses are black. For checking how an image
//! or a `.uv()` pattern will lie on a shape.

use glam::DVec3;

use crate::geometry::Ray;
use crate::ir::Color;
use crate::opt::Prepared;

/// The uv-image integrator.
pub(crate) struct UvImage<'a> {
    scene: &'a Prepared,
}

impl<'a> UvImage<'a> {
    /// The scene it images.
    pub(crate) fn scene(&self) -> &'a Prepared {
        self.scene
    }

    /// The integrator for `scene`.
    pub(crate) fn new(scene: &'a Prepared) -> UvImage<'a> {
        UvImage { scene }
    }

    /// The colour of the first hit along `ray`.
    pub(crate) fn color(&self, ray: &Ray) -> Color {
        self.scene
            .world()
            .intersect(ray, 0.0, f64::INFINITY)
            .map_or(Color::ZERO, |h| {
                DVec3::new(h.uv.x - h.uv.x.floor(), h.uv.y - h.uv.y.floor(), 0.0)
            })
    }
}
