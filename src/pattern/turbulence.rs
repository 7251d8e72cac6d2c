//! Turbulence: a point pushed by vector fBm (POV-Ray's `turbulence`), the warp most patterns
//! read and the parameter marble, wood, agate and the spirals take as their classic turbulence.

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
