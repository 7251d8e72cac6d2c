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
