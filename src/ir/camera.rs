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
            Projection::Perspective { .. } => self.up,
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
}
