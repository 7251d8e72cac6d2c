//! The camera of a scene: where it looks from and to, the image size, the projection, the
//! lens and how it moves while the shutter is open.

use glam::DVec3;

use crate::source::Span;

use super::motion::{CameraMotion, Shutter};

/// How pixels map to rays.
#[derive(Clone, Debug, PartialEq)]
pub struct Camera {
    /// Eye point (ray origin).
    pub eye: DVec3,
    /// The point looked at; the course image plane passes through it.
    pub center: DVec3,
    /// Up direction (re-orthogonalised against the view direction by the renderer).
    pub up: DVec3,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// How the view is sized.
    pub projection: Projection,
    /// Thin-lens aperture radius in world units; 0 is a pinhole.
    pub aperture: f64,
    /// Distance from the eye to the plane in focus (used when `aperture > 0`).
    pub focus_distance: f64,
    /// When the film is exposed (`None`: an instant, no motion blur).
    pub shutter: Option<Shutter>,
    /// How the camera moves while the shutter is open (`None`: it stands still).
    pub motion: Option<CameraMotion>,
    /// Where it was defined.
    pub span: Span,
}

impl Camera {
    /// The same view with pixels `factor` times larger (a coarse preview): the image shrinks to
    /// ⌈width/factor⌉ × ⌈height/factor⌉, and the course camera's pixel size `|up|` grows by
    /// `factor` so the view keeps its extent (within one coarse pixel).
    pub fn coarser(&self, factor: u32) -> Camera {
        let factor = factor.max(1);
        let up = match self.projection {
            Projection::Course => self.up * f64::from(factor),
            _ => self.up,
        };
        Camera {
            width: self.width.div_ceil(factor),
            height: self.height.div_ceil(factor),
            up,
            ..self.clone()
        }
    }
}

/// View sizing of a [`Camera`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// The course camera (COURSE.md §2.4): `|up|` is the size of one pixel at the plane through
    /// `center`; pixel (x, y) with offset (sx, sy) looks through
    /// `center + (x+sx−w/2)·right + ((h−1−y)+sy−h/2)·up'`.
    Course,
    /// A pinhole (or thin lens) with this vertical field of view, in radians.
    Perspective {
        /// Vertical field of view in radians, in (0, π).
        fov_y: f64,
    },
    /// Parallel rays along the view direction (POV-Ray's `orthographic`): pixel (x, y) with
    /// offset (sx, sy) starts at `eye + (x+sx−w/2)·p·right + ((h−1−y)+sy−h/2)·p·up'`, where
    /// `p = height / h` is the pixel size in world units.
    Orthographic {
        /// The view's height in world units, > 0 (its width is `height · w / h`).
        height: f64,
    },
    /// A 360° × 180° panorama (POV-Ray's `spherical` camera, `angle 360 180`): the pixel at
    /// (u, v) = ((x+sx)/w, (y+1−sy)/h) looks at longitude `(u − ½)·2π` (positive to the right)
    /// and latitude `(½ − v)·π` (positive up) from the view direction.
    Equirectangular,
    /// An equidistant fisheye (POV-Ray's `fisheye`): in the circle inscribed in the image
    /// (radius `R = min(w, h) / 2` pixels), a pixel `r` pixels from the image centre looks
    /// `(r / R) · fov / 2` away from the view direction; pixels outside the circle are black.
    Fisheye {
        /// The angle across the circle, in radians, in (0, 2π].
        fov: f64,
    },
    /// A vertical cylindrical panorama (POV-Ray's `cylinder 1`): column `u = (x+sx)/w` looks at
    /// the horizontal angle `(u − ½)·fov` from the view direction, row `v` at the height
    /// `(½ − v) · h · fov / w` on the cylinder of radius 1 around the eye (square pixels on the
    /// horizon).
    Cylindrical {
        /// The horizontal angle across the image, in radians, in (0, 2π].
        fov: f64,
    },
}

impl Projection {
    /// Whether every ray starts at the eye and passes through a plane image (the perspective
    /// and course cameras): what the packet tracer's pinhole rays and `project` assume.
    pub fn is_planar(&self) -> bool {
        matches!(self, Projection::Course | Projection::Perspective { .. })
    }
}
