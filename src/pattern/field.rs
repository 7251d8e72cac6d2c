//! [`Pattern`], the closed set of scalar fields of position a texture can hold, and [`Field`],
//! a pattern with its warps and wave: the number a colour map will read at a point.

use std::sync::Arc;

use glam::DVec3;

use crate::num::Norm;

use super::fbm::Fractal;
use super::noisy::{self, Crackle};
use super::program::Program;
use super::ripples::{self, DEFAULT_WAVES};
use super::warps::{Turbulence, Warp};
use super::waves::{Wave, WaveShape};
use super::{geometric, tilings};

/// A scalar field of position, in the pattern's own space (the caller applies the object's and
/// the pattern's transforms first). Each variant's range is on its function and in
/// [`Pattern::range`]; discrete patterns give tile indices ([`Pattern::entries`]).
#[derive(Clone, Debug, PartialEq)]
pub enum Pattern {
    /// [`geometric::gradient`]: the coordinate along `axis`, its remainder modulo 1 above 1;
    /// (−∞, 1] (the wave wraps it).
    Gradient {
        /// The direction, a unit vector ([`Pattern::gradient`] makes it one: POV-Ray
        /// normalises the direction it is given, so its length does not matter).
        axis: DVec3,
    },
    /// [`tilings::checker`]: 0 or 1 by unit cube.
    Checker,
    /// [`tilings::hexagon`]: 0, 1 or 2 by hexagon of side 1 in x–z.
    Hexagon,
    /// [`tilings::brick`]: 0 in mortar, 1 in a brick.
    Brick {
        /// Brick length (x), height (y) and depth (z); POV-Ray's default ⟨8, 3, 4.5⟩.
        size: DVec3,
        /// Joint thickness; POV-Ray's default 0.5.
        mortar: f64,
    },
    /// [`geometric::radial`]: the angle about y as a fraction of a turn; [0.25, 1.25] (the
    /// wave wraps it).
    Radial,
    /// [`geometric::onion`]: the fractional distance from the origin; [0, 1).
    Onion,
    /// [`geometric::spherical`]: `1 − |p|`, 0 beyond; [0, 1].
    Spherical,
    /// [`geometric::cylindrical`]: `1 −` distance from the y axis, 0 beyond; [0, 1].
    Cylindrical,
    /// [`geometric::boxed`]: `1 −` the largest |coordinate|, 0 beyond; [0, 1].
    Boxed,
    /// [`geometric::planar`]: `1 − |y|`, 0 beyond; [0, 1].
    Planar,
    /// [`tilings::square`]: 0 to 3 by unit square in x–z.
    Square,
    /// [`tilings::triangular`]: 0 to 5 by triangle of side 1 in x–z.
    Triangular,
    /// [`geometric::spiral1`]: arms winding along z; unbounded (triangle wave by default).
    Spiral1 {
        /// The number of arms.
        arms: f64,
        /// Classic turbulence (POV-Ray adds `turbulence.x` times its scalar turbulence).
        turbulence: Turbulence,
    },
    /// [`geometric::spiral2`]: two crossed spirals; [0, 2] (triangle wave by default).
    Spiral2 {
        /// The number of arms.
        arms: f64,
        /// Classic turbulence, as for `Spiral1`.
        turbulence: Turbulence,
    },
    /// [`noisy::agate`]: turbulent bands along z; [0, 1].
    Agate {
        /// POV-Ray's `agate_turb` (default 1).
        turb: f64,
        /// The octaves, omega and lambda of its turbulence.
        fractal: Fractal,
        /// The noise seed.
        seed: u32,
    },
    /// [`noisy::bozo`], also POV-Ray's `spotted` and `bumps`: the noise; [0, 1].
    Bozo {
        /// The noise seed.
        seed: u32,
    },
    /// [`noisy::granite`]: six creased octaves; [0, 0.984375].
    Granite {
        /// The noise seed.
        seed: u32,
    },
    /// [`noisy::marble`]: `x` plus turbulence; unbounded (triangle wave by default).
    Marble {
        /// Classic turbulence.
        turbulence: Turbulence,
    },
    /// [`noisy::wood`]: wobbling rings about z; at least 0 (triangle wave by default).
    Wood {
        /// Classic turbulence.
        turbulence: Turbulence,
    },
    /// [`noisy::leopard`]: regular spots; [0, 1].
    Leopard,
    /// [`ripples::ripples`]: rings from the sources; [0, 1].
    Ripples {
        /// Rings per unit of distance.
        frequency: f64,
        /// Added to every ring's phase.
        phase: f64,
        /// How many sources (POV-Ray's `number_of_waves`, default 10).
        count: u32,
    },
    /// [`ripples::waves`]: waves of unequal lengths from the sources; `0.5 ± waves_reach`.
    Waves {
        /// Waves per unit of distance (times each source's own).
        frequency: f64,
        /// Added to every wave's phase.
        phase: f64,
        /// How many sources.
        count: u32,
    },
    /// [`noisy::wrinkles`]: ten contrast-raised octaves; [0, 1).
    Wrinkles {
        /// The noise seed.
        seed: u32,
    },
    /// [`noisy::dents`]: the noise cubed; [0, 1].
    Dents {
        /// The noise seed.
        seed: u32,
    },
    /// [`noisy::crackle`]: a Worley distance, clamped; [0, 1].
    Crackle {
        /// F1, F2 or F2 − F1.
        form: Crackle,
        /// The feature points' seed.
        seed: u32,
    },
    /// [`tilings::cells`]: a random value per unit cube; [0, 1).
    Cells {
        /// The seed.
        seed: u32,
    },
    /// A user function of position compiled to a [`Program`] (the language's `pattern(f)`):
    /// whatever it returns, a value that is not finite read as 0; unbounded.
    Function(Arc<Program>),
}

/// Every POV-Ray pattern name [`Pattern::named`] knows.
pub const NAMES: &[&str] = &[
    "gradient",
    "checker",
    "hexagon",
    "brick",
    "radial",
    "onion",
    "spherical",
    "cylindrical",
    "boxed",
    "planar",
    "square",
    "triangular",
    "spiral1",
    "spiral2",
    "agate",
    "bozo",
    "spotted",
    "bumps",
    "granite",
    "marble",
    "wood",
    "leopard",
    "ripples",
    "waves",
    "wrinkles",
    "dents",
    "crackle",
    "cells",
];

impl Pattern {
    /// `gradient direction` as POV-Ray reads it: along the unit vector of `direction` (whose
    /// length does not matter); along x when `direction` has no direction.
    pub fn gradient(direction: DVec3) -> Pattern {
        Pattern::Gradient {
            axis: direction.unit_or(DVec3::X),
        }
    }

    /// The pattern POV-Ray's name gives with its defaults, seed 0 and no turbulence (`gradient`
    /// along x and the spirals' one arm are rtc's choices: POV-Ray requires them).
    pub fn named(name: &str) -> Option<Pattern> {
        let none = Turbulence::NONE;
        Some(match name {
            "gradient" => Pattern::Gradient { axis: DVec3::X },
            "checker" => Pattern::Checker,
            "hexagon" => Pattern::Hexagon,
            "brick" => Pattern::Brick {
                size: DVec3::new(8.0, 3.0, 4.5),
                mortar: 0.5,
            },
            "radial" => Pattern::Radial,
            "onion" => Pattern::Onion,
            "spherical" => Pattern::Spherical,
            "cylindrical" => Pattern::Cylindrical,
            "boxed" => Pattern::Boxed,
            "planar" => Pattern::Planar,
            "square" => Pattern::Square,
            "triangular" => Pattern::Triangular,
            "spiral1" => Pattern::Spiral1 {
                arms: 1.0,
                turbulence: none,
            },
            "spiral2" => Pattern::Spiral2 {
                arms: 1.0,
                turbulence: none,
            },
            "agate" => Pattern::Agate {
                turb: 1.0,
                fractal: Fractal::default(),
                seed: 0,
            },
            "bozo" | "spotted" | "bumps" => Pattern::Bozo { seed: 0 },
            "granite" => Pattern::Granite { seed: 0 },
            "marble" => Pattern::Marble { turbulence: none },
            "wood" => Pattern::Wood { turbulence: none },
            "leopard" => Pattern::Leopard,
            "ripples" => Pattern::Ripples {
                frequency: 1.0,
                phase: 0.0,
                count: DEFAULT_WAVES,
            },
            "waves" => Pattern::Waves {
                frequency: 1.0,
                phase: 0.0,
                count: DEFAULT_WAVES,
            },
            "wrinkles" => Pattern::Wrinkles { seed: 0 },
            "dents" => Pattern::Dents { seed: 0 },
            "crackle" => Pattern::Crackle {
                form: Crackle::Edges,
                seed: 0,
            },
            "cells" => Pattern::Cells { seed: 0 },
            _ => return None,
        })
    }

    /// The pattern's value at `p` (its own space).
    #[inline]
    pub fn eval(&self, p: DVec3) -> f64 {
        match self {
            Pattern::Gradient { axis } => geometric::gradient(p, *axis),
            Pattern::Checker => tilings::checker(p),
            Pattern::Hexagon => tilings::hexagon(p),
            Pattern::Brick { size, mortar } => tilings::brick(p, *size, *mortar),
            Pattern::Radial => geometric::radial(p),
            Pattern::Onion => geometric::onion(p),
            Pattern::Spherical => geometric::spherical(p),
            Pattern::Cylindrical => geometric::cylindrical(p),
            Pattern::Boxed => geometric::boxed(p),
            Pattern::Planar => geometric::planar(p),
            Pattern::Square => tilings::square(p),
            Pattern::Triangular => tilings::triangular(p),
            Pattern::Spiral1 { arms, turbulence } => geometric::spiral1(p, *arms, turbulence),
            Pattern::Spiral2 { arms, turbulence } => geometric::spiral2(p, *arms, turbulence),
            Pattern::Agate {
                turb,
                fractal,
                seed,
            } => noisy::agate(p, *turb, fractal, *seed),
            Pattern::Bozo { seed } => noisy::bozo(p, *seed),
            Pattern::Granite { seed } => noisy::granite(p, *seed),
            Pattern::Marble { turbulence } => noisy::marble(p, turbulence),
            Pattern::Wood { turbulence } => noisy::wood(p, turbulence),
            Pattern::Leopard => noisy::leopard(p),
            Pattern::Ripples {
                frequency,
                phase,
                count,
            } => ripples::ripples(p, *frequency, *phase, *count),
            Pattern::Waves {
                frequency,
                phase,
                count,
            } => ripples::waves(p, *frequency, *phase, *count),
            Pattern::Wrinkles { seed } => noisy::wrinkles(p, *seed),
            Pattern::Dents { seed } => noisy::dents(p, *seed),
            Pattern::Crackle { form, seed } => noisy::crackle(p, *form, *seed),
            Pattern::Cells { seed } => tilings::cells(p, *seed),
            Pattern::Function(program) => program.eval(p),
        }
    }

    /// For a discrete pattern, how many tile indices it gives (0 to n − 1); `None` for a
    /// continuous one.
    pub fn entries(&self) -> Option<u32> {
        match self {
            Pattern::Checker | Pattern::Brick { .. } => Some(2),
            Pattern::Hexagon => Some(3),
            Pattern::Square => Some(4),
            Pattern::Triangular => Some(6),
            _ => None,
        }
    }

    /// The wave shape POV-Ray gives the pattern by default: the triangle for marble, wood and
    /// the spirals, the ramp for the rest.
    pub fn default_wave(&self) -> WaveShape {
        match self {
            Pattern::Marble { .. }
            | Pattern::Wood { .. }
            | Pattern::Spiral1 { .. }
            | Pattern::Spiral2 { .. } => WaveShape::Triangle,
            _ => WaveShape::Ramp,
        }
    }

    /// The closed interval every value lies in (infinite ends for unbounded patterns).
    pub fn range(&self) -> (f64, f64) {
        match self {
            Pattern::Brick { .. } | Pattern::Checker => (0.0, 1.0),
            Pattern::Hexagon => (0.0, 2.0),
            Pattern::Square => (0.0, 3.0),
            Pattern::Triangular => (0.0, 5.0),
            Pattern::Spiral1 { .. } | Pattern::Marble { .. } | Pattern::Function(_) => {
                (f64::NEG_INFINITY, f64::INFINITY)
            }
            Pattern::Gradient { .. } => (f64::NEG_INFINITY, 1.0),
            Pattern::Radial => (0.25, 1.25),
            Pattern::Wood { .. } => (0.0, f64::INFINITY),
            Pattern::Spiral2 { .. } => (0.0, 2.0),
            Pattern::Granite { .. } => (0.0, 0.984_375),
            Pattern::Waves { count, .. } => {
                let reach = ripples::waves_reach(*count);
                (0.5 - reach, 0.5 + reach)
            }
            _ => (0.0, 1.0),
        }
    }
}

/// A pattern with what POV-Ray applies around it: warps on the point first (in order), the
/// wave on the value after (continuous patterns only; a discrete pattern's index passes as is).
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    /// The pattern.
    pub pattern: Pattern,
    /// Applied to the point in order before the pattern reads it.
    pub warps: Vec<Warp>,
    /// Frequency, phase and shape of the value.
    pub wave: Wave,
}

impl Field {
    /// The pattern with no warp and its default wave at frequency 1, phase 0.
    pub fn new(pattern: Pattern) -> Field {
        Field {
            wave: Wave::new(pattern.default_wave()),
            pattern,
            warps: Vec::new(),
        }
    }

    /// The value at `p`: `wave(pattern(warps(p)))`.
    #[inline]
    pub fn eval(&self, p: DVec3) -> f64 {
        let q = self.warps.iter().fold(p, |q, w| w.apply(q));
        let v = self.pattern.eval(q);
        if self.pattern.entries().is_some() {
            v
        } else {
            self.wave.apply(v)
        }
    }
}
