//! Colours and the basic textures (a material is built in `material.rs`).

use std::rc::Rc;

use glam::DVec3;

use crate::eval::args::{ArgVal, CallSite};
use crate::eval::args::{Params, check};
use crate::eval::error::R;
use crate::eval::host::BuiltinFn;
use crate::eval::host::Host;
use crate::eval::schema::{Group, Lit, Param, Range, Sig, Ty, Unit};
use crate::eval::types;
use crate::eval::value::{Tex, Value};
use crate::ir;
use crate::syntax::srgb_to_linear;

/// Colour, material and texture constructors with their schemas.
pub(crate) static FNS: &[(&Sig, BuiltinFn)] = &[
    (&RGB, rgb),
    (&SRGB, srgb),
    (&HSV, hsv),
    (&CHECKER, checker),
    (&STRIPES, stripes),
    (&IMAGE, image),
    (&NORMAL_MAP, normal_map),
];

/// The channels of `rgb` and `srgb`.
const CHANNELS: &[Param] = &[
    Param::new("r", Ty::Float, "red").range(Range::NonNegative),
    Param::new("g", Ty::Float, "green").range(Range::NonNegative),
    Param::new("b", Ty::Float, "blue").range(Range::NonNegative),
];

/// The three channels, or one grey value for all three (`rgb(0.5)`, checked here: the
/// schema lists the three-channel form).
fn channels(it: &dyn Host, s: CallSite, a: Vec<ArgVal>, sig: &'static Sig) -> R<[f64; 3]> {
    if let [one] = a.as_slice()
        && let Some(g) = one.value.as_f64()
    {
        check(g >= 0.0, "value", ">= 0", g, one.span)?;
        return Ok([g; 3]);
    }
    let mut p = Params::new(s, sig, a)?;
    Ok([
        p.float(it, "r")?.0,
        p.float(it, "g")?.0,
        p.float(it, "b")?.0,
    ])
}

/// `rgb(r, g, b)`.
static RGB: Sig = Sig::new(
    "rgb",
    Group::Colour,
    "A linear colour (`rgb(value)` is a grey).",
    CHANNELS,
    "Color",
)
.examples(&["rgb(r: 0.8, g: 0.1, b: 0.1)", "rgb(0.5)"]);
fn rgb(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    Ok(Value::Color(channels(it, s, a, &RGB)?.into()))
}

/// `srgb(r, g, b)`.
static SRGB: Sig = Sig::new(
    "srgb",
    Group::Colour,
    "An sRGB-encoded colour, converted to linear (`srgb(value)` is a grey).",
    CHANNELS,
    "Color",
)
.examples(&["srgb(0.55, 0.35, 0.2)"]);
fn srgb(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let c = channels(it, s, a, &SRGB)?;
    Ok(Value::Color(c.map(srgb_to_linear).into()))
}

/// `hsv(hue: Angle, s, v)`: hue is an angle (0deg red, 120deg green), s and v in [0, 1]; the
/// result is the sRGB-encoded colour converted to linear.
static HSV: Sig = Sig::new(
    "hsv",
    Group::Colour,
    "A colour by hue, saturation and value (sRGB-encoded, converted to linear).",
    &[
        Param::new(
            "hue",
            Ty::Angle,
            "the hue: 0deg red, 120deg green, 240deg blue",
        )
        .unit(Unit::Angle),
        Param::new("s", Ty::Float, "the saturation").range(Range::UnitInterval),
        Param::new("v", Ty::Float, "the value (brightness)").range(Range::UnitInterval),
    ],
    "Color",
)
.examples(&["hsv(hue: 120deg, s: 0.5, v: 0.8)"]);
fn hsv(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &HSV, a)?;
    let (hv, hs) = p.req("hue")?;
    if let Some(x) = hv.as_f64() {
        // A bare hue is most often a fraction of the colour wheel (0.5) or degrees (120).
        let (deg, turn) = if (0.0..=1.0).contains(&x) {
            (x * 360.0, x)
        } else {
            (x, x / 360.0)
        };
        let fmt = crate::eval::value::fmt_f;
        return Err(types::mismatch(it, "Angle", &hv, hs)
            .with_label("a hue is an angle on the colour wheel")
            .with_help(format!(
                "write `{}deg` (the same as `{}turn`); 0deg is red, 120deg green, 240deg blue",
                fmt(deg),
                fmt(turn)
            ))
            .into());
    }
    let h = p.angle_in(it, "hue", &hv, hs)?;
    let (sat, _) = p.float(it, "s")?;
    let (val, _) = p.float(it, "v")?;
    let h = h.to_degrees().rem_euclid(360.0) / 60.0;
    let c = val * sat;
    let x = c * (1.0 - (h % 2.0 - 1.0).abs());
    let (r, g, b) = match h as u32 {
        0 => (c, x, 0.0),
        1 => (x, c, 0.0),
        2 => (0.0, c, x),
        3 => (0.0, x, c),
        4 => (x, 0.0, c),
        _ => (c, 0.0, x),
    };
    let m = val - c;
    Ok(Value::Color(
        [r + m, g + m, b + m].map(srgb_to_linear).into(),
    ))
}

/// The parameters of `checker` and `stripes`.
const PATTERN: &[Param] = &[
    Param::new("size", Ty::Float, "the edge of a cell")
        .unit(Unit::Length)
        .range(Range::Positive)
        .or(Lit::Float(1.0)),
    Param::new("a", Ty::Color, "the first colour").or(Lit::Color([1.0, 1.0, 1.0])),
    Param::new("b", Ty::Color, "the second colour").or(Lit::Color([0.0, 0.0, 0.0])),
];

fn pattern(
    it: &dyn Host,
    s: CallSite,
    a: Vec<ArgVal>,
    sig: &'static Sig,
) -> R<(DVec3, DVec3, f64)> {
    let mut p = Params::new(s, sig, a)?;
    let (size, _) = p.float(it, "size")?;
    let (ca, _) = p.color(it, "a")?;
    let (cb, _) = p.color(it, "b")?;
    Ok((ca, cb, size))
}

/// `checker(size, a, b)`.
static CHECKER: Sig = Sig::new(
    "checker",
    Group::Look,
    "A 3-D checkerboard of cubes of edge `size` in object space.",
    PATTERN,
    "Texture",
)
.examples(&["checker(size: 0.5, a: rgb(0.9, 0.9, 0.9), b: rgb(0.1, 0.1, 0.1))"]);
fn checker(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (a, b, size) = pattern(it, s, a, &CHECKER)?;
    Ok(Value::Texture(Rc::new(Tex {
        t: ir::Texture::Checker { a, b, size },
        made: it.next_made(),
    })))
}

/// `stripes(size, a, b)`.
static STRIPES: Sig = Sig::new(
    "stripes",
    Group::Look,
    "Stripes of width `size` along object-space x.",
    PATTERN,
    "Texture",
)
.examples(&["stripes(size: 0.2)"]);
fn stripes(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let (a, b, size) = pattern(it, s, a, &STRIPES)?;
    Ok(Value::Texture(Rc::new(Tex {
        t: ir::Texture::Stripes { a, b, size },
        made: it.next_made(),
    })))
}

/// `image(path, mapping)`.
static IMAGE: Sig = Sig::new(
    "image",
    Group::Look,
    "An image file (PNG, JPEG, HDR, EXR), read nearest-texel, bilinearly or mip-mapped.",
    &[
        Param::new(
            "path",
            Ty::String,
            "the file, relative to the calling file (it must exist)",
        ),
        Param::new("mapping", Ty::Mapping, "how surface points find pixels").or(Lit::Name("uv")),
        Param::new(
            "filter",
            Ty::String,
            "\"nearest\" (the course's texel lookup), \"bilinear\" (smooth up close) or \"mipmap\" (trilinear over the pixel's footprint: smooth up close, no moiré far away)",
        )
        .checked_by_builtin()
        .or(Lit::Name("\"nearest\"")),
    ],
    "Texture",
)
.examples(&["image(path: \"images/flare-halo.png\", mapping: planar, filter: \"bilinear\")"]);
fn image(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &IMAGE, a)?;
    let (rel, ps) = p.string(it, "path")?;
    let path = crate::eval::assets::existing(it, &rel, ps, "image")?;
    let mapping = image_mapping(it, &mut p)?;
    let filter = match p.get("filter") {
        None => ir::ImageFilter::Nearest,
        Some((Value::Str(f), sp)) => match &*f {
            "nearest" => ir::ImageFilter::Nearest,
            "bilinear" => ir::ImageFilter::Bilinear,
            "mipmap" => ir::ImageFilter::Mipmap,
            other => {
                let choices = ["nearest", "bilinear", "mipmap"];
                let e = crate::eval::texture_methods::bad_choice("filter", other, &choices, sp);
                return Err(e.into());
            }
        },
        Some((other, sp)) => return Err(types::mismatch(it, "String", &other, sp).into()),
    };
    Ok(Value::Texture(Rc::new(Tex {
        t: ir::Texture::Image {
            path,
            mapping,
            filter,
            span: ps,
        },
        made: it.next_made(),
    })))
}

/// `normal_map(path, mapping)`.
static NORMAL_MAP: Sig = Sig::new(
    "normal_map",
    Group::Look,
    "A tangent-space normal map image (OpenGL convention: x along u, y up the picture), for `bump:`.",
    &[
        Param::new(
            "path",
            Ty::String,
            "the file, relative to the calling file (it must exist)",
        ),
        Param::new("mapping", Ty::Mapping, "how surface points find pixels").or(Lit::Name("uv")),
    ],
    "Texture",
)
.examples(&["normal_map(path: \"images/flare-halo.png\", mapping: planar)"]);
fn normal_map(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &NORMAL_MAP, a)?;
    let (rel, ps) = p.string(it, "path")?;
    let path = crate::eval::assets::existing(it, &rel, ps, "image")?;
    let mapping = image_mapping(it, &mut p)?;
    Ok(Value::Texture(Rc::new(Tex {
        t: ir::Texture::NormalMap {
            path,
            mapping,
            span: ps,
        },
        made: it.next_made(),
    })))
}

/// An image's `mapping:` argument (uv when absent).
fn image_mapping(it: &mut dyn Host, p: &mut Params) -> R<ir::Mapping> {
    Ok(match p.get("mapping") {
        None => ir::Mapping::Uv,
        Some((Value::Mapping(m), _)) => m,
        Some((other, sp)) => return Err(types::mismatch(it, "Mapping", &other, sp).into()),
    })
}
