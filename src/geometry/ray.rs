//! Rays, object-space hit records and the frame texture mappings read hits in.

use crate::num::Norm;
use glam::{DVec2, DVec3};

use std::f64::consts::PI;

/// A ray `origin + t·dir` at one instant. `dir` is unit length in world space; in object space
/// it may not be.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Start point.
    pub origin: DVec3,
    /// Direction.
    pub dir: DVec3,
    /// When it travels, as a fraction of the open shutter (0 = open, 1 = close): where moving
    /// objects are for it.
    pub(crate) time: f64,
}

impl Ray {
    /// A ray from `origin` along `dir` at shutter open.
    pub fn new(origin: DVec3, dir: DVec3) -> Ray {
        Ray {
            origin,
            dir,
            time: 0.0,
        }
    }

    /// The same ray at shutter fraction `time`.
    pub(crate) fn at_time(self, time: f64) -> Ray {
        Ray { time, ..self }
    }

    /// The point at parameter `t`.
    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + t * self.dir
    }
}

/// A hit in the space the ray was given in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Hit {
    /// Ray parameter of the hit.
    pub(crate) t: f64,
    /// Unit outward normal at the hit (not flipped towards the ray).
    pub(crate) normal: DVec3,
    /// Surface coordinates in [0, 1]².
    pub(crate) uv: DVec2,
}

/// The frame in which texture mappings read a hit's position: a sphere's own centre (and its
/// equirectangular uv), or the object-space origin for every other shape. The world keeps it
/// per surface (`World::frame`), so a sphere inside a CSG node maps about its own centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum MappingFrame {
    /// About the object-space origin.
    Object,
    /// About a sphere's centre, with its radius.
    Sphere {
        /// The sphere's centre (object space).
        center: DVec3,
        /// Its radius.
        radius: f64,
    },
}

impl MappingFrame {
    /// The object-space point `p` as mappings read it: relative to the frame's centre.
    pub(crate) fn point(&self, p: DVec3) -> DVec3 {
        match *self {
            MappingFrame::Object => p - DVec3::ZERO,
            MappingFrame::Sphere { center, .. } => p - center,
        }
    }

    /// Equirectangular (u, v) of the object-space point `p` about the frame's centre (+Y is the
    /// north pole): a sphere's own uv, else the direction from the origin.
    pub(crate) fn spherical_uv(&self, p: DVec3) -> DVec2 {
        match *self {
            MappingFrame::Sphere { center, radius } => {
                equirectangular_uv(((p - center) / radius).unit())
            }
            MappingFrame::Object => equirectangular_uv(p.try_unit().unwrap_or(DVec3::Y)),
        }
    }
}

/// A place where a ray crosses the boundary of a closed solid (for CSG classification).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Crossing {
    /// The surface hit.
    pub(crate) hit: Hit,
    /// True when the ray goes from outside to inside here.
    pub(crate) entering: bool,
}

/// The first of `candidates` with `t` in (t_min, t_max) (candidates need not be sorted).
pub(crate) fn nearest(
    candidates: impl IntoIterator<Item = Hit>,
    t_min: f64,
    t_max: f64,
) -> Option<Hit> {
    let mut best: Option<Hit> = None;
    for h in candidates {
        if h.t > t_min && h.t < t_max && best.is_none_or(|b| h.t < b.t) {
            best = Some(h);
        }
    }
    best
}

/// Equirectangular coordinates of a unit direction from the centre: +Y is the north pole (v = 0),
/// u = φ/2π with φ measured from +X towards −Z (counter-clockwise seen from above).
pub(crate) fn equirectangular_uv(n: DVec3) -> DVec2 {
    let theta = libm::acos(n.y.clamp(-1.0, 1.0));
    let mut phi = libm::atan2(-n.z, n.x);
    if phi < 0.0 {
        phi += 2.0 * PI;
    }
    DVec2::new(phi / (2.0 * PI), theta / PI)
}
