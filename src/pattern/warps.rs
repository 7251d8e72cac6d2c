//! Warps: functions of position applied before a pattern reads the point (POV-Ray's `warp { }`
//! and `turbulence`). Transforms are not here: the caller brings the point into the pattern's
//! space first.

use glam::DVec3;

use super::fbm::{self, Fractal};

/// Turbulence: the point displaced by vector fBm times `amount` per axis (POV-Ray's
/// `turbulence <x, y, z>` with `octaves`, `omega`, `lambda`). Marble, wood, agate and the
/// spirals read it in their own way instead (POV-Ray's "classic" turbulence, handled by the
/// pattern): give it to them, not as a warp.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Turbulence {
    /// How far each axis is pushed per unit of the noise sum (0: no turbulence).
    pub amount: DVec3,
    /// Octaves, omega and lambda of the sum.
    pub fractal: Fractal,
    /// The noise seed.
    pub seed: u32,
}

impl Turbulence {
    /// No turbulence, with POV-Ray's default octaves, omega and lambda.
    pub const NONE: Turbulence = Turbulence {
        amount: DVec3::ZERO,
        fractal: Fractal {
            octaves: 6,
            omega: 0.5,
            lambda: 2.0,
        },
        seed: 0,
    };

    /// `amount` on every axis, POV-Ray's default octaves, omega and lambda, seed 0.
    pub fn uniform(amount: f64) -> Turbulence {
        Turbulence {
            amount: DVec3::splat(amount),
            ..Turbulence::NONE
        }
    }

    /// Whether the amount is zero on every axis (the warp is the identity).
    pub fn is_none(&self) -> bool {
        self.amount == DVec3::ZERO
    }

    /// The warped point: `p + amount ⊙ vector_fbm(p)`.
    #[inline]
    pub fn warp(&self, p: DVec3) -> DVec3 {
        if self.is_none() {
            return p;
        }
        p + self.amount * fbm::vector(p, &self.fractal, self.seed)
    }

    /// The scalar turbulence classic patterns add: `amount.x · classic(p)` (0 without any).
    #[inline]
    pub fn scalar(&self, p: DVec3) -> f64 {
        if self.is_none() {
            return 0.0;
        }
        self.amount.x * fbm::classic(p, &self.fractal, self.seed)
    }
}

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

/// A warp of either kind.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Warp {
    /// A turbulence warp.
    Turbulence(Turbulence),
    /// A repeat warp.
    Repeat(Repeat),
}

impl Warp {
    /// The warped point.
    #[inline]
    pub fn apply(&self, p: DVec3) -> DVec3 {
        match self {
            Warp::Turbulence(t) => t.warp(p),
            Warp::Repeat(r) => r.warp(p),
        }
    }
}
