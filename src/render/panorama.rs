//! The panoramic cameras' ray directions: equirectangular (POV-Ray's `spherical`), equidistant
//! fisheye and vertical cylinder (POV-Ray's `cylinder 1`), from continuous pixel coordinates.

use glam::DVec3;

use crate::ir::{self, Projection};
use crate::num::Norm;

/// The direction of a camera ray that is not traced: a fisheye's pixels outside its circle.
/// The integrators read such a ray as black ([`is_blind`]).
pub(crate) const BLIND: DVec3 = DVec3::ZERO;

/// Whether `ray` is a camera ray that is not traced ([`BLIND`]): its pixel sample is black.
pub(crate) fn is_blind(ray: &crate::geometry::Ray) -> bool {
    ray.dir == BLIND
}

/// A panoramic projection with the camera's frame.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Panorama {
    /// Unit view direction, right and up.
    forward: DVec3,
    right: DVec3,
    up: DVec3,
    /// Image width and height in pixels.
    w: f64,
    h: f64,
    /// Which panorama and its angle.
    shape: Shape,
}

/// The panoramas.
#[derive(Clone, Copy, Debug)]
enum Shape {
    /// 360° × 180°.
    Equirectangular,
    /// Equidistant, this full angle across the inscribed circle.
    Fisheye(f64),
    /// Vertical cylinder, this horizontal angle across the image.
    Cylindrical(f64),
}

impl Panorama {
    /// The panorama of camera `c` (a panoramic projection) with its unit frame.
    pub(crate) fn new(c: &ir::Camera, forward: DVec3, right: DVec3, up: DVec3) -> Panorama {
        let shape = match c.projection {
            Projection::Fisheye { fov } => Shape::Fisheye(fov),
            Projection::Cylindrical { fov } => Shape::Cylindrical(fov),
            _ => Shape::Equirectangular,
        };
        Panorama {
            forward,
            right,
            up,
            w: f64::from(c.width),
            h: f64::from(c.height),
            shape,
        }
    }

    /// Whether this is a fisheye (with pixels outside its circle).
    pub(crate) fn is_fisheye(&self) -> bool {
        matches!(self.shape, Shape::Fisheye(_))
    }

    /// The unit direction at `px` pixels from the left edge and `v` pixels from the top edge
    /// ([`BLIND`] outside a fisheye's circle).
    pub(crate) fn dir(&self, px: f64, v: f64) -> DVec3 {
        let (u, v) = (px / self.w, v / self.h);
        match self.shape {
            Shape::Equirectangular => {
                let lon = (u - 0.5) * std::f64::consts::TAU;
                let lat = (0.5 - v) * std::f64::consts::PI;
                let (sl, cl) = (libm::sin(lon), libm::cos(lon));
                let (sb, cb) = (libm::sin(lat), libm::cos(lat));
                (cb * (cl * self.forward + sl * self.right) + sb * self.up).unit()
            }
            Shape::Fisheye(fov) => {
                let radius = 0.5 * self.w.min(self.h);
                let (dx, dy) = ((u - 0.5) * self.w, (0.5 - v) * self.h);
                let r = libm::hypot(dx, dy);
                if r > radius {
                    return BLIND;
                }
                if r == 0.0 {
                    return self.forward;
                }
                let theta = (r / radius) * 0.5 * fov;
                let side = (dx / r) * self.right + (dy / r) * self.up;
                (libm::cos(theta) * self.forward + libm::sin(theta) * side).unit()
            }
            Shape::Cylindrical(fov) => {
                let a = (u - 0.5) * fov;
                let height = (0.5 - v) * self.h * fov / self.w;
                (libm::sin(a) * self.right + libm::cos(a) * self.forward + height * self.up).unit()
            }
        }
    }
}
