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

    /// How [`Repeat::warp`] scales each axis at `p` (its Jacobian's diagonal): `flip` in odd
    /// slabs, 1 elsewhere.
    #[inline]
    pub fn scale_at(&self, p: DVec3) -> DVec3 {
        let slab = (p[self.axis.min(2)] / self.width).floor();
        if slab.rem_euclid(2.0) == 1.0 {
            self.flip
        } else {
            DVec3::ONE
        }
    }
}

/// The angle of `p` about the y axis as a fraction of a turn, from +x towards +z (+x 0, +z ¼,
/// −x ½, −z ¾; just below +x it rounds to 1), as POV-Ray's spherical, cylindrical and toroidal
/// warps measure it; 0 on the axis. (The `radial` pattern measures its angle the other way,
/// from −z.)
#[inline]
pub fn longitude(p: DVec3) -> f64 {
    if p.x == 0.0 && p.z == 0.0 {
        return 0.0;
    }
    let a = libm::atan2(p.z, p.x);
    if a < 0.0 { (a + TAU) / TAU } else { a / TAU }
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
    /// a turn ([`longitude`]: 0 on +x, ¼ on +z), y the latitude as a fraction of the half turn
    /// from the south pole, z the distance from the origin (POV-Ray's `warp { spherical }`).
    /// The origin stays where it is.
    Spherical,
    /// The x–y plane wrapped round the y axis: x is the longitude about y ([`longitude`]), y
    /// stays, z is the distance from the axis (POV-Ray's `warp { cylindrical }`). Points on the
    /// axis stay where they are.
    Cylindrical,
    /// The x–y plane wrapped round a torus about y of this major radius: x is the longitude
    /// about y ([`longitude`]), y the angle round the tube as a fraction of a turn (0 on the
    /// inner equator, ¼ below the core circle, ½ on the outer equator, ¾ above it), z the
    /// distance from the tube's core circle (POV-Ray's `warp { toroidal }`). Points on the y
    /// axis stay where they are.
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
                if r == 0.0 {
                    return p;
                }
                let latitude = libm::acos((-p.y / r).clamp(-1.0, 1.0)) / PI;
                DVec3::new(longitude(p), latitude, r)
            }
            Warp::Cylindrical => {
                let d = libm::hypot(p.x, p.z);
                if d == 0.0 {
                    return p;
                }
                DVec3::new(longitude(p), p.y, d)
            }
            Warp::Toroidal(major) => {
                let across = libm::hypot(p.x, p.z);
                if across == 0.0 {
                    return p;
                }
                let d = across - major;
                // Half a turn from the outer equator, in [0, 1): the inner equator is 0.
                let tube = 0.5 + libm::atan2(p.y, d) / TAU;
                let tube = if tube >= 1.0 { tube - 1.0 } else { tube };
                DVec3::new(longitude(p), tube, libm::hypot(d, p.y))
            }
        }
    }
}
