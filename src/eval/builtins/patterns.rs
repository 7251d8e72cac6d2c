//! Pattern constructors: POV-Ray's pattern set ([`crate::pattern`]) as `Texture` values, each
//! read through a grey colour map until `.colors(..)` gives it one (docs/textures.md).

use std::rc::Rc;
use std::sync::Arc;

use glam::{DAffine3, DVec3};

use crate::eval::args::{ArgVal, CallSite, Params};
use crate::eval::error::R;
use crate::eval::host::{BuiltinFn, Host};
use crate::eval::schema::{Group, Lit, Param, Range, Sig, Ty, Unit};
use crate::eval::value::{Tex, Value};
use crate::ir::{self, PatternSpace, PatternTexture};
use crate::pattern::{ColorMap, Crackle, Field, Fractal, Pattern, Turbulence};

/// The pattern constructors with their schemas.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[
    (&GRADIENT, gradient),
    (&HEXAGON, hexagon),
    (&BRICK, brick),
    (&RADIAL, radial),
    (&ONION, onion),
    (&SPHERICAL, spherical),
    (&CYLINDRICAL, cylindrical),
    (&BOXED, boxed),
    (&PLANAR, planar),
    (&SQUARE, square),
    (&TRIANGULAR, triangular),
    (&SPIRAL1, spiral1),
    (&SPIRAL2, spiral2),
    (&AGATE, agate),
    (&BOZO, bozo),
    (&SPOTTED, spotted),
    (&BUMPS, bumps),
    (&GRANITE, granite),
    (&MARBLE, marble),
    (&WOOD, wood),
    (&LEOPARD, leopard),
    (&RIPPLES, ripples),
    (&WAVES, waves),
    (&WRINKLES, wrinkles),
    (&DENTS, dents),
    (&CRACKLE, crackle),
    (&CELLS, cells),
    (&PATTERN, pattern),
];

/// A pattern texture value: `pattern` with no warp, its default wave, in object space, read
/// through the grey map (one grey per tile for a discrete pattern).
pub(crate) fn texture(it: &mut dyn Host, pattern: Pattern) -> Value {
    let map = match pattern.entries() {
        Some(n) => {
            let greys: Vec<DVec3> = (0..n)
                .map(|i| DVec3::splat(f64::from(i) / f64::from(n - 1)))
                .collect();
            ColorMap::entries(&greys)
        }
        None => None,
    };
    Value::Texture(Rc::new(Tex {
        t: ir::Texture::Pattern(Box::new(PatternTexture {
            field: Field::new(pattern),
            placement: DAffine3::IDENTITY,
            space: PatternSpace::Object,
            map: map.unwrap_or_else(ColorMap::grey),
        })),
        made: it.next_made(),
    }))
}

/// The seed parameter of the random patterns.
const SEED: Param = Param::new(
    "seed",
    Ty::Int,
    "another seed gives another pattern of the same look",
)
.range(Range::Ints(0, u32::MAX as i64))
.or(Lit::Int(0));

/// The seed, checked by its range.
fn seed(it: &dyn Host, p: &mut Params) -> R<u32> {
    let (s, _) = p.int(it, "seed")?;
    Ok(s as u32)
}

/// Defines a constructor without parameters: its schema and function.
macro_rules! plain {
    ($sig:ident, $f:ident, $name:literal, $doc:literal, $pattern:expr) => {
        static $sig: Sig =
            Sig::new($name, Group::Look, $doc, &[], "Texture").examples(&[concat!($name, "()")]);
        fn $f(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
            Params::new(s, &$sig, a)?;
            Ok(texture(it, $pattern))
        }
    };
}

/// Defines a constructor whose only parameter is the seed.
macro_rules! seeded {
    ($sig:ident, $f:ident, $name:literal, $doc:literal, $variant:ident) => {
        static $sig: Sig = Sig::new($name, Group::Look, $doc, &[SEED], "Texture")
            .examples(&[concat!($name, "(seed: 7)")]);
        fn $f(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
            let mut p = Params::new(s, &$sig, a)?;
            let seed = seed(it, &mut p)?;
            Ok(texture(it, Pattern::$variant { seed }))
        }
    };
}

plain!(
    HEXAGON,
    hexagon,
    "hexagon",
    "Hexagons of side 1 in the x–z plane, three tiles (0, 1, 2).",
    Pattern::Hexagon
);
plain!(
    RADIAL,
    radial,
    "radial",
    "The angle about y as a fraction of a turn, from +x towards −z; in [0, 1].",
    Pattern::Radial
);
plain!(
    ONION,
    onion,
    "onion",
    "Concentric shells: the fractional part of the distance from the origin; in [0, 1).",
    Pattern::Onion
);
plain!(
    SPHERICAL,
    spherical,
    "spherical_falloff",
    "POV-Ray's `spherical`: 1 at the origin falling to 0 at distance 1 (0 beyond).",
    Pattern::Spherical
);
plain!(
    CYLINDRICAL,
    cylindrical,
    "cylindrical_falloff",
    "POV-Ray's `cylindrical`: 1 on the y axis falling to 0 at distance 1 (0 beyond).",
    Pattern::Cylindrical
);
plain!(
    BOXED,
    boxed,
    "boxed",
    "1 at the origin falling to 0 on the cube of half-size 1 (0 beyond).",
    Pattern::Boxed
);
plain!(
    PLANAR,
    planar,
    "planar_falloff",
    "POV-Ray's `planar`: 1 on the plane y = 0 falling to 0 at |y| = 1 (0 beyond).",
    Pattern::Planar
);
plain!(
    SQUARE,
    square,
    "square",
    "Unit squares in the x–z plane, four tiles (0 to 3) in a two-by-two block.",
    Pattern::Square
);
plain!(
    TRIANGULAR,
    triangular,
    "triangular",
    "Triangles of side 1 in the x–z plane, six tiles (0 to 5) round each vertex.",
    Pattern::Triangular
);
plain!(
    MARBLE,
    marble,
    "marble",
    "Bands along x, triangle-waved; `.turbulence(..)` gives the veins.",
    Pattern::Marble {
        turbulence: Turbulence::NONE
    }
);
plain!(
    WOOD,
    wood,
    "wood",
    "Rings about the z axis, triangle-waved; `.turbulence(..)` makes them wobble.",
    Pattern::Wood {
        turbulence: Turbulence::NONE
    }
);
plain!(
    LEOPARD,
    leopard,
    "leopard",
    "Regular round spots on a cubic lattice; in [0, 1].",
    Pattern::Leopard
);
seeded!(
    BOZO,
    bozo,
    "bozo",
    "Smooth noise (Perlin's improved noise, mean 0.5); in [0, 1].",
    Bozo
);
seeded!(
    SPOTTED,
    spotted,
    "spotted",
    "POV-Ray's other name for `bozo`: smooth noise in [0, 1].",
    Bozo
);
seeded!(
    BUMPS,
    bumps,
    "bumps",
    "POV-Ray's name for `bozo` as a bump pattern: smooth noise in [0, 1].",
    Bozo
);
seeded!(
    GRANITE,
    granite,
    "granite",
    "Six octaves of creased noise, the look of granite; in [0, 0.984].",
    Granite
);
seeded!(
    WRINKLES,
    wrinkles,
    "wrinkles",
    "Ten octaves of noise, contrast raised: wrinkled skin as a bump; in [0, 1).",
    Wrinkles
);
seeded!(
    DENTS,
    dents,
    "dents",
    "Noise cubed: scattered dents as a bump; in [0, 1].",
    Dents
);
seeded!(
    CELLS,
    cells,
    "cells",
    "A random value per unit cube; in [0, 1).",
    Cells
);

/// `gradient(axis)`.
static GRADIENT: Sig = Sig::new(
    "gradient",
    Group::Look,
    "The fractional coordinate along the direction `axis` (its length does not matter, as in POV-Ray); in [0, 1].",
    &[
        Param::new("axis", Ty::Vec3, "the direction the value grows along")
            .range(Range::NonZero)
            .or(Lit::Vec3([1.0, 0.0, 0.0])),
    ],
    "Texture",
)
.examples(&["gradient(axis: Y)"]);
fn gradient(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &GRADIENT, a)?;
    let (axis, _) = p.vec3(it, "axis")?;
    Ok(texture(it, Pattern::gradient(axis)))
}

/// `brick(size, mortar)`.
static BRICK: Sig = Sig::new(
    "brick",
    Group::Look,
    "Bricks in a running bond: 0 in the mortar, 1 in a brick.",
    &[
        Param::new(
            "size",
            Ty::Vec3,
            "a brick's length (x), height (y) and depth (z)",
        )
        .unit(Unit::Length)
        .or(Lit::Vec3([8.0, 3.0, 4.5])),
        Param::new("mortar", Ty::Float, "the joints' thickness")
            .unit(Unit::Length)
            .range(Range::NonNegative)
            .or(Lit::Float(0.5)),
    ],
    "Texture",
)
.examples(&["brick(size: [0.25, 0.08, 0.12], mortar: 0.01)"]);
fn brick(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &BRICK, a)?;
    let (size, ss) = p.vec3(it, "size")?;
    crate::eval::args::check(
        size.min_element() > 0.0,
        "size",
        "every side > 0",
        size.min_element(),
        ss,
    )?;
    let (mortar, _) = p.float(it, "mortar")?;
    Ok(texture(it, Pattern::Brick { size, mortar }))
}

/// The parameter of the spirals.
const ARMS: &[Param] = &[Param::new("arms", Ty::Float, "how many arms wind round")
    .range(Range::Positive)
    .or(Lit::Float(1.0))];

/// `spiral1(arms)`.
static SPIRAL1: Sig = Sig::new(
    "spiral1",
    Group::Look,
    "Arms winding round the z axis, triangle-waved.",
    ARMS,
    "Texture",
)
.examples(&["spiral1(arms: 3)"]);
fn spiral1(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &SPIRAL1, a)?;
    let (arms, _) = p.float(it, "arms")?;
    let turbulence = Turbulence::NONE;
    Ok(texture(it, Pattern::Spiral1 { arms, turbulence }))
}

/// `spiral2(arms)`.
static SPIRAL2: Sig = Sig::new(
    "spiral2",
    Group::Look,
    "Two spirals winding opposite ways round the z axis, crossed; triangle-waved.",
    ARMS,
    "Texture",
)
.examples(&["spiral2(arms: 2)"]);
fn spiral2(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &SPIRAL2, a)?;
    let (arms, _) = p.float(it, "arms")?;
    let turbulence = Turbulence::NONE;
    Ok(texture(it, Pattern::Spiral2 { arms, turbulence }))
}

/// `agate(turb, seed)`.
static AGATE: Sig = Sig::new(
    "agate",
    Group::Look,
    "Turbulent bands along z, the look of agate; in [0, 1].",
    &[
        Param::new(
            "turb",
            Ty::Float,
            "how far the bands wander (POV-Ray's `agate_turb`)",
        )
        .range(Range::NonNegative)
        .or(Lit::Float(1.0)),
        SEED,
    ],
    "Texture",
)
.examples(&["agate(turb: 0.5)"]);
fn agate(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &AGATE, a)?;
    let (turb, _) = p.float(it, "turb")?;
    let seed = seed(it, &mut p)?;
    let fractal = Fractal::default();
    Ok(texture(
        it,
        Pattern::Agate {
            turb,
            fractal,
            seed,
        },
    ))
}

/// The parameters of `ripples` and `waves`.
const RINGS: &[Param] = &[
    Param::new("frequency", Ty::Float, "rings per unit of distance").or(Lit::Float(1.0)),
    Param::new(
        "phase",
        Ty::Float,
        "added to every ring's phase (a fraction of a ring)",
    )
    .or(Lit::Float(0.0)),
    Param::new(
        "count",
        Ty::Int,
        "how many sources (POV-Ray's `number_of_waves`)",
    )
    .range(Range::Ints(1, 64))
    .or(Lit::Int(10)),
];

/// The frequency, phase and count of `ripples` or `waves`.
fn rings(it: &dyn Host, s: CallSite, a: Vec<ArgVal>, sig: &'static Sig) -> R<(f64, f64, u32)> {
    let mut p = Params::new(s, sig, a)?;
    let (frequency, _) = p.float(it, "frequency")?;
    let (phase, _) = p.float(it, "phase")?;
    let (count, _) = p.int(it, "count")?;
    Ok((frequency, phase, count as u32))
}

/// `ripples(frequency, phase, count)`.
static RIPPLES: Sig = Sig::new(
    "ripples",
    Group::Look,
    "Rings spreading from `count` sources in the unit cube, as on water; in [0, 1].",
    RINGS,
    "Texture",
)
.examples(&["ripples(frequency: 8)"]);
fn ripples(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (frequency, phase, count) = rings(it, s, a, &RIPPLES)?;
    let pattern = Pattern::Ripples {
        frequency,
        phase,
        count,
    };
    Ok(texture(it, pattern))
}

/// `waves(frequency, phase, count)`.
static WAVES: Sig = Sig::new(
    "waves",
    Group::Look,
    "Waves of unequal lengths from `count` sources, as on a swell; about 0.5 ± 0.5.",
    RINGS,
    "Texture",
)
.examples(&["waves(frequency: 2)"]);
fn waves(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (frequency, phase, count) = rings(it, s, a, &WAVES)?;
    let pattern = Pattern::Waves {
        frequency,
        phase,
        count,
    };
    Ok(texture(it, pattern))
}

/// `crackle(form, seed)`.
static CRACKLE: Sig = Sig::new(
    "crackle",
    Group::Look,
    "Worley's cellular noise: `\"edges\"` (F2 − F1, 0 on the cracks), `\"f1\"` or `\"f2\"`.",
    &[
        Param::new(
            "form",
            Ty::String,
            "which distance: \"edges\", \"f1\" or \"f2\"",
        )
        .checked_by_builtin()
        .or(Lit::Name("\"edges\"")),
        SEED,
    ],
    "Texture",
)
.examples(&["crackle(form: \"f1\", seed: 3)"]);
fn crackle(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &CRACKLE, a)?;
    let form = match p.get("form") {
        None => Crackle::Edges,
        Some((Value::Str(f), sp)) => match &*f {
            "edges" => Crackle::Edges,
            "f1" => Crackle::F1,
            "f2" => Crackle::F2,
            other => {
                return Err(super::super::texture_methods::bad_choice(
                    "form",
                    other,
                    &["edges", "f1", "f2"],
                    sp,
                )
                .into());
            }
        },
        Some((other, sp)) => {
            return Err(crate::eval::types::mismatch(it, "String", &other, sp).into());
        }
    };
    let seed = seed(it, &mut p)?;
    Ok(texture(it, Pattern::Crackle { form, seed }))
}

/// `pattern(f)`.
static PATTERN: Sig = Sig::new(
    "pattern",
    Group::Look,
    "A pattern from a function of the point: `f(p)` is the value at `p` (pattern space), compiled once when the pattern is made (language.md §16.4 lists what compiles); any range, waves wrap it as other patterns.",
    &[Param::new(
        "f",
        Ty::Fn,
        "a `fn(p)` of the point giving a number",
    )],
    "Texture",
)
.examples(&["pattern(fn(p) { p.x - floor(p.x) })"]);
fn pattern(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &PATTERN, a)?;
    let (f, sp) = p.req("f")?;
    let program = it.compile_pattern(f, sp)?;
    Ok(texture(it, Pattern::Function(Arc::new(program))))
}
