//! Packets of rays and the shape-specific packet code: a [`RayLanes`] (origins and directions of
//! up to [`crate::lanes::WIDTH`] rays, in the leaf's structure-of-arrays vectors), the loose
//! spheres' lanes ([`spheres`], [`sphere_packet`]) and the culling of a packet's candidates
//! ([`cull`]). The plain lane maths (`V3`, `Lanes`, masks, selects and folds) is the leaf
//! [`crate::lanes`].

pub mod cull;
pub(crate) mod sphere_packet;
pub(crate) mod spheres;

use crate::geometry::ray::Ray;
use crate::lanes::{Lanes, V3, WIDTH};

/// A packet of rays: origins and directions (world space; the directions unit).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct RayLanes {
    /// Origins.
    pub(crate) origin: V3,
    /// Directions.
    pub(crate) dir: V3,
}

impl RayLanes {
    /// The packet of `rays` (lanes past them hold zeros).
    #[inline(always)]
    pub(crate) fn of(rays: &[Ray]) -> RayLanes {
        let mut p = RayLanes::default();
        for (i, r) in rays.iter().enumerate().take(WIDTH) {
            p.origin.set(i, r.origin);
            p.dir.set(i, r.dir);
        }
        p
    }

    /// The points at `t` (`Ray::at`: `origin + t·dir`).
    #[inline(always)]
    pub(crate) fn at(&self, t: &Lanes) -> V3 {
        self.origin.add(&self.dir.scale(t))
    }
}
