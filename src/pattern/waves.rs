//! Wave shapes: what turns a pattern's value into the number a colour map reads. POV-Ray 3.7
//! applies them to every continuous pattern: the value times `frequency` plus `phase`, wrapped
//! into [0, 1], then shaped. Discrete patterns (checker, hexagon, brick, square, triangular)
//! are indices and take no wave.

use std::f64::consts::{PI, TAU};

/// The shape a wrapped value takes (POV-Ray's `ramp_wave`, `triangle_wave`, `sine_wave`,
/// `scallop_wave`, `cubic_wave`, `poly_wave`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WaveShape {
    /// `v`: rises from 0 to 1, then drops back (the default for most patterns).
    Ramp,
    /// `2v` up to 0.5, then `2(1 − v)`: 0 at 0 and 1, 1 at 0.5 (marble's, wood's, spirals').
    Triangle,
    /// `(1 + sin 2πv) / 2`: 0.5 at 0, 1 at 0.25, 0.5 at 0.5, 0 at 0.75.
    Sine,
    /// `|sin πv|`: 0 at 0 and 1, 1 at 0.5, with cusps at the ends.
    Scallop,
    /// `v²(3 − 2v)`: the smoothstep, 0.5 at 0.5, flat at both ends.
    Cubic,
    /// `v^e` with the exponent `e` (`poly_wave e`; POV-Ray's default exponent is 1).
    Poly(f64),
}

impl WaveShape {
    /// The shape at `v` in [0, 1].
    #[inline]
    pub fn at(self, v: f64) -> f64 {
        match self {
            WaveShape::Ramp => v,
            WaveShape::Triangle => {
                if v < 0.5 {
                    2.0 * v
                } else {
                    2.0 * (1.0 - v)
                }
            }
            WaveShape::Sine => 0.5 * (1.0 + libm::sin(TAU * v)),
            WaveShape::Scallop => libm::sin(PI * v).abs(),
            WaveShape::Cubic => v * v * (3.0 - 2.0 * v),
            WaveShape::Poly(e) => libm::pow(v, e),
        }
    }

    /// The shape's slope at `v` in [0, 1] (one side's at a corner); infinite where the shape
    /// is (`poly_wave` below 1 at 0).
    #[inline]
    pub fn slope(self, v: f64) -> f64 {
        match self {
            WaveShape::Ramp => 1.0,
            WaveShape::Triangle => {
                if v < 0.5 {
                    2.0
                } else {
                    -2.0
                }
            }
            WaveShape::Sine => PI * libm::cos(TAU * v),
            WaveShape::Scallop => {
                let s = libm::sin(PI * v);
                PI * libm::cos(PI * v) * if s < 0.0 { -1.0 } else { 1.0 }
            }
            WaveShape::Cubic => 6.0 * v * (1.0 - v),
            WaveShape::Poly(e) => e * libm::pow(v, e - 1.0),
        }
    }
}

/// Wraps a value into [0, 1]: values already in [0, 1] pass unchanged (so a pattern's 1 stays
/// 1, which POV-Ray gets by taking the remainder modulo 1.00001), others lose their integer part.
/// POV-Ray's 1.00001 also drifts the phase of large values (x = 1000.5 reads 0.51); ours does not.
#[inline]
pub fn wrap(v: f64) -> f64 {
    if (0.0..=1.0).contains(&v) {
        v
    } else {
        v - v.floor()
    }
}

/// Frequency, phase and shape together: what a continuous pattern's value goes through.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wave {
    /// The shape.
    pub shape: WaveShape,
    /// Cycles of the shape per unit of the pattern's value (0: the value is only wrapped, as
    /// in POV-Ray, where frequency 0 skips the multiply and the phase).
    pub frequency: f64,
    /// Added to the scaled value before wrapping (a fraction of a cycle).
    pub phase: f64,
}

impl Wave {
    /// `shape` at frequency 1, phase 0.
    pub fn new(shape: WaveShape) -> Wave {
        Wave {
            shape,
            frequency: 1.0,
            phase: 0.0,
        }
    }

    /// The shaped value of pattern value `v`: `shape(wrap(v·frequency + phase))`.
    #[inline]
    pub fn apply(&self, v: f64) -> f64 {
        let scaled = if self.frequency == 0.0 {
            v
        } else {
            v * self.frequency + self.phase
        };
        self.shape.at(wrap(scaled))
    }

    /// The slope of [`Wave::apply`] at pattern value `v` (wrapping has slope 1 between its
    /// jumps).
    #[inline]
    pub fn slope(&self, v: f64) -> f64 {
        if self.frequency == 0.0 {
            self.shape.slope(wrap(v))
        } else {
            self.frequency * self.shape.slope(wrap(v * self.frequency + self.phase))
        }
    }
}

impl Default for Wave {
    /// The ramp at frequency 1, phase 0 (a pattern's value unchanged when in [0, 1]).
    fn default() -> Wave {
        Wave::new(WaveShape::Ramp)
    }
}
