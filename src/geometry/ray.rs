//! Rays and object-space hit records.

use glam::{DVec2, DVec3};

/// A ray `origin + t·dir`. `dir` is unit length in world space; in object space it may not be.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Start point.
    pub origin: DVec3,
    /// Direction.
    pub dir: DVec3,
}

impl Ray {
    /// A ray from `origin` along `dir`.
    pub fn new(origin: DVec3, dir: DVec3) -> Ray {
        Ray { origin, dir }
    }

    /// The point at parameter `t`.
    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + t * self.dir
    }
}

/// A hit in the space the ray was given in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Ray parameter of the hit.
    pub t: f64,
    /// Unit outward normal at the hit (not flipped towards the ray).
    pub normal: DVec3,
    /// Surface coordinates in [0, 1]².
    pub uv: DVec2,
}

/// A place where a ray crosses the boundary of a closed solid (for CSG classification).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// The surface hit.
    pub hit: Hit,
    /// True when the ray goes from outside to inside here.
    pub entering: bool,
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
