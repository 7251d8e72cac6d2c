//! The methods of `Texture` values: a colour map (`.colors`), the modifiers of POV-Ray's
//! patterns (`.turbulence`, `.frequency`, `.phase`, `.wave`, `.repeat`, `.warp`), uv space
//! (`.uv()`), and transforms relative to the object (`.translate`, `.rotate`, `.scale`, ...).
//! A checker or stripes texture given one of them becomes the pattern it is.

use std::rc::Rc;

use glam::{DAffine3, DVec3};

use super::args::{ArgVal, CallSite, Params};
use super::error::{R, error, suggest};
use super::host::Host;
use super::schema::{Group, Lit, Param, Range, Sig, Ty};
use super::types;
use super::value::{Tex, Value};
use crate::diag::Diagnostic;
use crate::ir::{self, PatternSpace, PatternTexture};
use crate::pattern::{
    ColorMap, Field, Fractal, Pattern, Repeat, Rgbft, Stop, Turbulence, Warp, WaveShape,
};
use crate::source::Span;

/// The methods of textures other than the transforms, in the order messages list them.
pub(crate) static METHODS: &[&Sig] = &[
    &COLORS,
    &TURBULENCE,
    &FREQUENCY,
    &PHASE,
    &WAVE,
    &REPEAT,
    &WARP,
    &UV,
];

/// Whether `name` is one of [`METHODS`].
pub(crate) fn is_method(name: &str) -> bool {
    METHODS.iter().any(|m| m.name == name)
}

/// `tex.name(args)` for a method of [`METHODS`].
pub(crate) fn call(it: &mut dyn Host, tex: Rc<Tex>, site: CallSite, args: Vec<ArgVal>) -> R<Value> {
    let mut pt = pattern_of(&tex.t, site)?;
    match site.name {
        "colors" => colors(it, &mut pt, site, args)?,
        "turbulence" => turbulence(it, &mut pt, site, args)?,
        "frequency" | "phase" => {
            let sig = if site.name == "frequency" {
                &FREQUENCY
            } else {
                &PHASE
            };
            let mut p = Params::new(site, sig, args)?;
            let (v, _) = p.float(it, site.name)?;
            set_wave_number(&mut pt.field, site.name == "frequency", v);
        }
        "wave" => wave(it, &mut pt, site, args)?,
        "repeat" => repeat(it, &mut pt, site, args)?,
        "warp" => warp(it, &mut pt, site, args)?,
        _ => {
            Params::new(site, &UV, args)?;
            pt.space = PatternSpace::Uv;
        }
    }
    Ok(made(it, pt))
}

/// `tex` moved by transform `t` (from a transform method): the pattern moves with it.
pub(crate) fn transformed(it: &mut dyn Host, tex: &Tex, t: DAffine3, span: Span) -> R<Value> {
    let t = super::transform::nonsingular(t, span)?;
    let site = CallSite {
        span,
        name: "transform",
    };
    let mut pt = pattern_of(&tex.t, site)?;
    pt.placement = t * pt.placement;
    Ok(made(it, pt))
}

/// A new texture value holding `pt`.
fn made(it: &mut dyn Host, pt: PatternTexture) -> Value {
    Value::Texture(Rc::new(Tex {
        t: ir::Texture::Pattern(Box::new(pt)),
        made: it.next_made(),
    }))
}

/// The pattern a texture is: itself, or what a checker or stripes texture means as one. An
/// image is none (`rtc::texture::image`): its pixels are not a field of the point.
fn pattern_of(t: &ir::Texture, site: CallSite) -> R<PatternTexture> {
    let placed = |pattern: Pattern, size: f64, map: Option<ColorMap>| PatternTexture {
        field: Field::new(pattern),
        placement: DAffine3::from_scale(DVec3::splat(size)),
        space: PatternSpace::Object,
        map: map.unwrap_or_else(ColorMap::grey),
    };
    Ok(match t {
        ir::Texture::Pattern(p) => (**p).clone(),
        ir::Texture::Checker { a, b, size } => {
            placed(Pattern::Checker, *size, ColorMap::entries(&[*a, *b]))
        }
        // Stripes of width `size` alternate every `size`: a gradient along x over two widths,
        // `a` on its first half and `b` on its second.
        ir::Texture::Stripes { a, b, size } => {
            let at = |at: f64, c: DVec3| Stop {
                at,
                color: Rgbft::opaque(c),
            };
            let map = ColorMap::new(vec![at(0.0, *a), at(0.5, *a), at(0.5, *b), at(1.0, *b)]);
            placed(Pattern::Gradient { axis: DVec3::X }, 2.0 * size, map)
        }
        ir::Texture::Image { .. } | ir::Texture::NormalMap { .. } => {
            return Err(error(
                "rtc::texture::image",
                site.span,
                format!("an image texture has no `.{}(..)`", site.name),
            )
            .with_label("called on an image")
            .with_help(
                "place an image with its `mapping:` and the object's transform; \
                 the pattern methods (§16.2) work on patterns, checker and stripes",
            )
            .into());
        }
    })
}

/// An error for a string parameter that is none of its choices.
pub(crate) fn bad_choice(param: &str, got: &str, choices: &[&str], span: Span) -> Diagnostic {
    let list = choices
        .iter()
        .map(|c| format!("\"{c}\""))
        .collect::<Vec<_>>()
        .join(", ");
    let help = suggest(got, choices.iter().copied())
        .map(|s| format!("{s}; the choices are {list}"))
        .unwrap_or_else(|| format!("the choices are {list}"));
    error(
        "rtc::texture::choice",
        span,
        format!("`{param}` cannot be \"{got}\""),
    )
    .with_label(format!("one of {list}"))
    .with_help(help)
}

/// `.colors(stops)`.
static COLORS: Sig = Sig::new(
    "colors",
    Group::Method,
    "The pattern read through a colour map: a list of colours spread evenly over [0, 1] (one per \
     tile of a discrete pattern), or of stops `[at, colour]` or `{ at, color, filter, transmit }`, \
     interpolated linearly in linear RGB.",
    &[Param::new("stops", Ty::List, "colours, or stops sorted or not").checked_by_builtin()],
    "Texture",
)
.examples(&["marble().colors([[0, rgb(0.9, 0.9, 0.85)], [0.8, rgb(0.5, 0.5, 0.55)], [1, rgb(0.2, 0.2, 0.25)]])"]);
fn colors(it: &mut dyn Host, pt: &mut PatternTexture, site: CallSite, args: Vec<ArgVal>) -> R<()> {
    let mut p = Params::new(site, &COLORS, args)?;
    let (v, span) = p.req("stops")?;
    let Value::List(items) = v else {
        return Err(types::mismatch(it, "List", &v, span).into());
    };
    let discrete = pt.field.pattern.entries().is_some();
    pt.map = color_map(it, &items, discrete, span)?;
    Ok(())
}

/// The colour map a `.colors(..)` list describes.
fn color_map(it: &dyn Host, items: &[Value], discrete: bool, span: Span) -> R<ColorMap> {
    let bad = |i: usize, what: String| -> super::error::EvalError {
        error(
            "rtc::texture::stop",
            span,
            format!("entry {} of the colour map {what}", i + 1),
        )
        .with_label("in this list")
        .with_help(
            "write colours (`[rgb(1, 1, 1), rgb(0, 0, 0)]`), stops `[at, colour]` \
             (`[[0, rgb(1, 1, 1)], [1, rgb(0, 0, 0)]]`) or records \
             `{ at: 0.5, color: rgb(1, 1, 1), transmit: 0.5 }`",
        )
        .into()
    };
    if items.is_empty() {
        return Err(error("rtc::texture::stop", span, "the colour map is empty")
            .with_label("no colour here")
            .with_help("give at least one colour, e.g. `[rgb(1, 1, 1), rgb(0, 0, 0)]`")
            .into());
    }
    let n = items.len();
    let mut stops = Vec::with_capacity(n);
    for (i, item) in items.iter().enumerate() {
        let even = if discrete || n == 1 {
            i as f64
        } else {
            i as f64 / (n - 1) as f64
        };
        let stop = match item {
            Value::Color(c) => Stop {
                at: even,
                color: Rgbft::opaque(*c),
            },
            Value::List(pair) => match pair.as_slice() {
                [at, Value::Color(c)] => Stop {
                    at: at
                        .as_f64()
                        .ok_or_else(|| bad(i, "has a position that is no number".into()))?,
                    color: Rgbft::opaque(*c),
                },
                _ => return Err(bad(i, "is not `[at, colour]`".into())),
            },
            Value::Record(r) => {
                let field = |name: &str| r.get(crate::syntax::intern::Sym::new(name));
                for f in &r.fields {
                    let name = f.name.as_str();
                    if !["at", "color", "filter", "transmit"].contains(&name) {
                        return Err(bad(
                            i,
                            format!(
                                "has an unknown field `{name}` (it has `at`, `color`, `filter`, `transmit`)"
                            ),
                        ));
                    }
                }
                let at = field("at")
                    .and_then(Value::as_f64)
                    .ok_or_else(|| bad(i, "needs `at: number`".into()))?;
                let Some(Value::Color(c)) = field("color") else {
                    return Err(bad(i, "needs `color: rgb(..)`".into()));
                };
                let share = |name: &str| -> R<f64> {
                    match field(name) {
                        None => Ok(0.0),
                        Some(v) => match v.as_f64() {
                            Some(x) if (0.0..=1.0).contains(&x) => Ok(x),
                            _ => Err(bad(i, format!("has `{name}` outside [0, 1]"))),
                        },
                    }
                };
                Stop {
                    at,
                    color: Rgbft {
                        rgb: *c,
                        filter: share("filter")?,
                        transmit: share("transmit")?,
                    },
                }
            }
            other => {
                let shown = types::mismatch(it, "Color", other, span);
                return Err(bad(
                    i,
                    format!("is a {} ({})", other.type_name(), shown.message),
                ));
            }
        };
        if !stop.at.is_finite() || !stop.color.rgb.is_finite() || stop.color.rgb.min_element() < 0.0
        {
            return Err(bad(
                i,
                "has a position or colour that is not finite and ≥ 0".into(),
            ));
        }
        stops.push(stop);
    }
    ColorMap::new(stops).ok_or_else(|| bad(0, "is not usable".into()))
}

/// `.frequency(f)` and `.phase(p)`: on ripples and waves they change the rings themselves (as
/// POV-Ray does), elsewhere the wave.
fn set_wave_number(field: &mut Field, frequency: bool, v: f64) {
    match &mut field.pattern {
        Pattern::Ripples {
            frequency: f,
            phase: ph,
            ..
        }
        | Pattern::Waves {
            frequency: f,
            phase: ph,
            ..
        } => *(if frequency { f } else { ph }) = v,
        _ if frequency => field.wave.frequency = v,
        _ => field.wave.phase = v,
    }
}

/// `.frequency(f)`.
static FREQUENCY: Sig = Sig::new(
    "frequency",
    Group::Method,
    "Cycles of the colour map per unit of the pattern's value (ripples and waves: rings per unit).",
    &[Param::new("frequency", Ty::Float, "the frequency")],
    "Texture",
)
.examples(&["wood().frequency(4)"]);

/// `.phase(p)`.
static PHASE: Sig = Sig::new(
    "phase",
    Group::Method,
    "Shifts where the colour map starts, as a fraction of a cycle.",
    &[Param::new("phase", Ty::Float, "the shift")],
    "Texture",
)
.examples(&["onion().phase(0.25)"]);

/// `.turbulence(amount, octaves, omega, lambda, seed)`.
static TURBULENCE: Sig = Sig::new(
    "turbulence",
    Group::Method,
    "Stirs the pattern with fractal noise: marble, wood, agate and the spirals add it to their \
     value as POV-Ray does, every other pattern reads a point pushed by it.",
    &[
        Param::new(
            "amount",
            Ty::OneOf(&[Ty::Float, Ty::Vec3]),
            "how far, per axis if a vector",
        )
        .checked_by_builtin(),
        Param::new("octaves", Ty::Int, "how many octaves of noise")
            .range(Range::Ints(1, 16))
            .or(Lit::Int(6)),
        Param::new(
            "omega",
            Ty::Float,
            "each octave's weight relative to the one before",
        )
        .range(Range::NonNegative)
        .or(Lit::Float(0.5)),
        Param::new(
            "lambda",
            Ty::Float,
            "each octave's frequency relative to the one before",
        )
        .range(Range::Positive)
        .or(Lit::Float(2.0)),
        Param::new("seed", Ty::Int, "the noise seed")
            .range(Range::Ints(0, u32::MAX as i64))
            .or(Lit::Int(0)),
    ],
    "Texture",
)
.examples(&[
    "marble().turbulence(0.8, octaves: 4)",
    "bozo().turbulence([0.5, 0, 0.5])",
]);
fn turbulence(
    it: &mut dyn Host,
    pt: &mut PatternTexture,
    site: CallSite,
    args: Vec<ArgVal>,
) -> R<()> {
    let mut p = Params::new(site, &TURBULENCE, args)?;
    let (v, span) = p.req("amount")?;
    let amount = match v {
        Value::Int(_) | Value::Float(_) => DVec3::splat(v.as_f64().unwrap_or(0.0)),
        Value::Vec3(a) => a,
        other => return Err(types::mismatch(it, "Float or Vec3", &other, span).into()),
    };
    super::args::check(amount.is_finite(), "amount", "finite", amount.x, span)?;
    let (octaves, _) = p.int(it, "octaves")?;
    let (omega, _) = p.float(it, "omega")?;
    let (lambda, _) = p.float(it, "lambda")?;
    let (seed, _) = p.int(it, "seed")?;
    let t = Turbulence {
        amount,
        fractal: Fractal {
            octaves: octaves as u32,
            omega,
            lambda,
        },
        seed: seed as u32,
    };
    match &mut pt.field.pattern {
        Pattern::Marble { turbulence }
        | Pattern::Wood { turbulence }
        | Pattern::Spiral1 { turbulence, .. }
        | Pattern::Spiral2 { turbulence, .. } => *turbulence = t,
        Pattern::Agate { turb, fractal, .. } => {
            *turb *= amount.x;
            *fractal = t.fractal;
        }
        // POV-Ray's turbulence is the pattern's own, whatever follows: the innermost step,
        // transformed with the pattern.
        _ => pt.field.warps.push(Warp::Turbulence(t)),
    }
    Ok(())
}

/// `.wave(shape, exponent)`.
static WAVE: Sig = Sig::new(
    "wave",
    Group::Method,
    "The shape the value takes on its way to the colour map: \"ramp\", \"triangle\", \"sine\", \
     \"scallop\", \"cubic\" or \"poly\" (with `exponent`).",
    &[
        Param::new("shape", Ty::String, "the wave shape").checked_by_builtin(),
        Param::new("exponent", Ty::Float, "the power of \"poly\"")
            .range(Range::Positive)
            .or(Lit::Float(1.0)),
    ],
    "Texture",
)
.examples(&[
    "bozo().wave(\"sine\")",
    "gradient(axis: Y).wave(\"poly\", exponent: 3)",
]);
fn wave(it: &mut dyn Host, pt: &mut PatternTexture, site: CallSite, args: Vec<ArgVal>) -> R<()> {
    let mut p = Params::new(site, &WAVE, args)?;
    let (shape, span) = p.string(it, "shape")?;
    let (exponent, _) = p.float(it, "exponent")?;
    pt.field.wave.shape = match &*shape {
        "ramp" => WaveShape::Ramp,
        "triangle" => WaveShape::Triangle,
        "sine" => WaveShape::Sine,
        "scallop" => WaveShape::Scallop,
        "cubic" => WaveShape::Cubic,
        "poly" => WaveShape::Poly(exponent),
        other => {
            let choices = ["ramp", "triangle", "sine", "scallop", "cubic", "poly"];
            return Err(bad_choice("shape", other, &choices, span).into());
        }
    };
    Ok(())
}

/// `.repeat(axis, width, offset, flip)`.
static REPEAT: Sig = Sig::new(
    "repeat",
    Group::Method,
    "Repeats the slab `0 ≤ p·axis < width` along `axis` (X, Y or Z), each copy moved by `offset` \
     more than the one before, every other copy mirrored along the axes where `flip` is not 0.",
    &[
        Param::new("axis", Ty::Vec3, "X, Y or Z").checked_by_builtin(),
        Param::new("width", Ty::Float, "the slab's thickness").range(Range::Positive),
        Param::new("offset", Ty::Vec3, "the move from one copy to the next")
            .or(Lit::Vec3([0.0, 0.0, 0.0])),
        Param::new("flip", Ty::Vec3, "the axes mirrored in every other copy")
            .or(Lit::Vec3([0.0, 0.0, 0.0])),
    ],
    "Texture",
)
.examples(&["brick().repeat(X, width: 2, flip: X)"]);
fn repeat(it: &mut dyn Host, pt: &mut PatternTexture, site: CallSite, args: Vec<ArgVal>) -> R<()> {
    let mut p = Params::new(site, &REPEAT, args)?;
    let (axis, span) = p.vec3(it, "axis")?;
    let Some(axis) = [DVec3::X, DVec3::Y, DVec3::Z]
        .iter()
        .position(|a| *a == axis)
    else {
        return Err(
            error("rtc::texture::axis", span, "a repeat runs along X, Y or Z")
                .with_label("not one of the axes")
                .with_help("write `X`, `Y` or `Z`; rotate the texture for another direction")
                .into(),
        );
    };
    let (width, _) = p.float(it, "width")?;
    let (offset, _) = p.vec3(it, "offset")?;
    let (flip, _) = p.vec3(it, "flip")?;
    let flip = DVec3::select(flip.cmpne(DVec3::ZERO), DVec3::NEG_ONE, DVec3::ONE);
    let r = Repeat {
        axis,
        width,
        offset,
        flip,
    };
    written_after(pt, Warp::Repeat(r));
    Ok(())
}

/// Adds warp `w` as written after everything the texture has: the point meets it first, then
/// the transforms written so far (moved from `placement` into the warp list), then the earlier
/// warps (POV-Ray's order: a modifier acts on the pattern as modified before it).
fn written_after(pt: &mut PatternTexture, w: Warp) {
    if pt.placement != DAffine3::IDENTITY {
        pt.field.warps.insert(0, Warp::Placement(pt.placement));
        pt.placement = DAffine3::IDENTITY;
    }
    pt.field.warps.insert(0, w);
}

/// `.warp(kind, radius)`.
static WARP: Sig = Sig::new(
    "warp",
    Group::Method,
    "Wraps the pattern's x–y plane round a shape: \"spherical\" (x is the longitude, y the \
     latitude), \"cylindrical\" (x round the y axis) or \"toroidal\" (round a torus of `radius`).",
    &[
        Param::new(
            "kind",
            Ty::String,
            "\"spherical\", \"cylindrical\" or \"toroidal\"",
        )
        .checked_by_builtin(),
        Param::new("radius", Ty::Float, "the torus's major radius")
            .range(Range::Positive)
            .or(Lit::Float(1.0)),
    ],
    "Texture",
)
.examples(&["checker().scale([0.25, 0.5, 1]).warp(\"spherical\")"]);
fn warp(it: &mut dyn Host, pt: &mut PatternTexture, site: CallSite, args: Vec<ArgVal>) -> R<()> {
    let mut p = Params::new(site, &WARP, args)?;
    let (kind, span) = p.string(it, "kind")?;
    let (radius, _) = p.float(it, "radius")?;
    let w = match &*kind {
        "spherical" => Warp::Spherical,
        "cylindrical" => Warp::Cylindrical,
        "toroidal" => Warp::Toroidal(radius),
        other => {
            let choices = ["spherical", "cylindrical", "toroidal"];
            return Err(bad_choice("kind", other, &choices, span).into());
        }
    };
    written_after(pt, w);
    Ok(())
}

/// `.uv()`.
static UV: Sig = Sig::new(
    "uv",
    Group::Method,
    "The pattern reads the surface's (u, v, 0) instead of the object-space point.",
    &[],
    "Texture",
)
.examples(&["checker().scale(0.125).uv()"]);
