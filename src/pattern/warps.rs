//! Warps: functions of position applied before a pattern reads the point (POV-Ray's `warp { }`
//! and `turbulence`). Transforms are not here: the caller brings the point into the pattern's
//! space first.

use std::f64::consts::{PI, TAU};

use glam::{DAffine3, DVec3};

use crate::num::Norm;

pub use super::turbulence::Turbulence;

/// POV-Ray's repeat warp: space cut into slabs `width` thick along `axis`, each slab showing the
/// first one (`0 ≤ p[axis] < width`), odd slabs mirrored by `flip`, slab `k` moved by `k·offset`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Repeat {
    /// 0, 1 or 2: x, y or z.
    pub axis: usize,
    /// The slab thickness (positive).
    pub width: f64,
    /// Added to the point, once per slab counted from the first.
    pub offset: DVec3,
    /// Per-axis factor of odd slabs: 1 keeps an axis, −1 mirrors it (a mirrored repeat axis
    /// is mirrored within the slab).
    pub flip: DVec3,
}

impl Repeat {
    /// Plain repetition along `axis` every `width`.
    pub fn along(axis: usize, width: f64) -> Repeat {
        Repeat {
            axis,
            width,
            offset: DVec3::ZERO,
            flip: DVec3::ONE,
        }
    }

    /// The point as the first slab sees it.
    #[inline]
    pub fn warp(&self, p: DVec3) -> DVec3 {
        let a = self.axis.min(2);
        let slab = (p[a] / self.width).floor();
        let mut q = p;
        q[a] -= slab * self.width;
        if slab.rem_euclid(2.0) == 1.0 {
            q *= self.flip;
            if self.flip[a] < 0.0 {
                q[a] += self.width;
            }
        }
        q + slab * self.offset
    }
}

/// One step a point goes through before the pattern reads it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Warp {
    /// A turbulence warp.
    Turbulence(Turbulence),
    /// A repeat warp.
    Repeat(Repeat),
    /// An affine map of the point (prepared from a [`Warp::Placement`]: its inverse).
    Transform(DAffine3),
    /// Transforms written before a later warp, as written: the placement of the pattern's space
    /// in the space outside it (what the IR keeps, so that `rtc convert` writes it exactly).
    /// The point meets its inverse; the preparation stage turns it into a [`Warp::Transform`]
    /// once, since inverting per evaluation is slow.
    Placement(DAffine3),
    /// The x–y plane wrapped round the unit sphere: x is the longitude about y as a fraction of
    /// a turn (as [`super::geometric::radial`]), y the latitude as a fraction of the half turn
    /// from the south pole, z the distance from the origin.
    Spherical,
    /// The x–y plane wrapped round the y axis: x is the angle about y as a fraction of a turn,
    /// y stays, z is the distance from the axis.
    Cylindrical,
    /// The x–y plane wrapped round a torus about y of this major radius: x is the angle about
    /// y, y the angle round the tube (both fractions of a turn), z the distance from the tube's
    /// core circle.
    Toroidal(f64),
}

impl Warp {
    /// The warped point.
    #[inline]
    pub fn apply(&self, p: DVec3) -> DVec3 {
        match self {
            Warp::Turbulence(t) => t.warp(p),
            Warp::Repeat(r) => r.warp(p),
            Warp::Transform(m) => m.transform_point3(p),
            Warp::Placement(m) => m.inverse().transform_point3(p),
            Warp::Spherical => {
                let r = p.norm();
                let latitude = if r > 0.0 {
                    libm::acos((-p.y / r).clamp(-1.0, 1.0)) / PI
                } else {
                    0.0
                };
                DVec3::new(super::geometric::radial(p), latitude, r)
            }
            Warp::Cylindrical => {
                let d = libm::hypot(p.x, p.z);
                DVec3::new(super::geometric::radial(p), p.y, d)
            }
            Warp::Toroidal(major) => {
                let d = libm::hypot(p.x, p.z) - major;
                let tube = libm::atan2(p.y, d).rem_euclid(TAU) / TAU;
                DVec3::new(super::geometric::radial(p), tube, libm::hypot(d, p.y))
            }
        }
    }
}
