//! Lights: where a light is, its shape (a point or a parallelogram) and its colour.

use glam::DVec3;

use crate::source::Span;

/// A light source with an RGB intensity.
#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    /// Where and what shape.
    pub kind: LightKind,
    /// RGB intensity; may exceed 1.
    pub color: DVec3,
    /// Where it was defined.
    pub span: Span,
}

/// The geometry of a light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightKind {
    /// A point light.
    Point {
        /// Position.
        position: DVec3,
    },
    /// A parallelogram light `corner + s·u + t·v`, sampled on a `samples[0]×samples[1]` grid.
    Area {
        /// One corner.
        corner: DVec3,
        /// First edge.
        u: DVec3,
        /// Second edge.
        v: DVec3,
        /// Stratified sample counts along `u` and `v` (each ≥ 1).
        samples: [u32; 2],
    },
}

impl LightKind {
    /// The light's centre (its position for a point light).
    pub(crate) fn center(&self) -> DVec3 {
        match *self {
            LightKind::Point { position } => position,
            LightKind::Area { corner, u, v, .. } => corner + 0.5 * (u + v),
        }
    }
}
