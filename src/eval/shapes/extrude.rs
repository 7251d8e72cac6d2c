//! Swept outlines: `prism(points, heights, spline, sweep)` (POV-Ray's `prism`) and
//! `text(string, font, thickness, spacing, align)` (POV-Ray's `text` from a TrueType/OpenType
//! font through the asset service). Their geometry is `geometry::shapes::extrusion`.

use std::sync::Arc;

use glam::DVec2;

use crate::diag::Diagnostic;
use crate::eval::args::Params;
use crate::eval::args::{ArgVal, CallSite};
use crate::eval::error::{R, error};
use crate::eval::host::Host;
use crate::eval::schema::{Lit, Param, Range, Sig, Ty, Unit};
use crate::eval::types;
use crate::eval::value::Value;
use crate::ir::{PrismSweep, Shape, Spline, TextAlign};

use super::common::{checked, choice, pair};
use crate::eval::schema::Group;

/// `prism(points, heights, spline, sweep)`.
pub(super) static PRISM: Sig = Sig::new(
    "prism",
    Group::Shape,
    "POV-Ray's prism: a closed outline in the ground plane swept up `y` (even-odd holes).",
    &[
        Param::new(
            "points",
            Ty::ListOf(&Ty::Pair(&Ty::Float)),
            "`[x, z]` points; each sub-outline ends on its first point (see §10)",
        )
        .unit(Unit::Length),
        Param::new(
            "heights",
            Ty::Pair(&Ty::Float),
            "`[low, high]` in y (low < high; ≥ 0 for a conic sweep)",
        )
        .unit(Unit::Length)
        .checked_by_builtin()
        .or(Lit::Name("[0, 1]")),
        Param::new(
            "spline",
            Ty::String,
            "\"linear\", \"quadratic\", \"cubic\" or \"bezier\"",
        )
        .checked_by_builtin()
        .or(Lit::Name("\"linear\"")),
        Param::new(
            "sweep",
            Ty::String,
            "\"linear\" (straight up) or \"conic\" (scaled by y from the origin)",
        )
        .checked_by_builtin()
        .or(Lit::Name("\"linear\"")),
    ],
    "Object",
)
.examples(&[
    "prism(points: [[0, 0], [1, 0], [0.5, 1], [0, 0]], heights: [0, 0.5])",
    "prism(points: [[0, 1], [1, 0], [0, -1], [-1, 0], [0, 1], [1, 0], [0, -1]], heights: [0.2, 1], spline: \"cubic\", sweep: \"conic\")",
]);
pub(super) fn prism(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &PRISM, a)?;
    let (points, sp) = super::common::pairs(it, &mut p, "points")?;
    let (heights, hs) = match p.get("heights") {
        Some((v, hs)) => (pair(it, &v, hs)?, hs),
        None => (DVec2::new(0.0, 1.0), s.span),
    };
    let spline = match p.get("spline") {
        None => Spline::Linear,
        Some((v, sp)) => {
            let name = types::string(it, &v, sp)?;
            let k = choice(&name, &Spline::NAMES, "spline", sp)?;
            Spline::named(Spline::NAMES[k]).unwrap_or(Spline::Linear)
        }
    };
    let sweep = match p.get("sweep") {
        None => PrismSweep::Linear,
        Some((v, sp)) => {
            let name = types::string(it, &v, sp)?;
            match choice(&name, &["linear", "conic"], "sweep", sp)? {
                0 => PrismSweep::Linear,
                _ => PrismSweep::Conic,
            }
        }
    };
    checked(
        Shape::Prism {
            points,
            heights: [heights.x, heights.y],
            spline,
            sweep,
        },
        s,
        &[("points", sp), ("heights", hs)],
    )
}

/// `text(string, font, thickness, spacing, align)`.
pub(super) static TEXT: Sig = Sig::new(
    "text",
    Group::Shape,
    "A string in a TrueType/OpenType font, 1 unit per em, baseline on y = 0, facing +z, extruded back to z = −thickness.",
    &[
        Param::new("string", Ty::String, "the characters (a missing one draws the font's .notdef box, with a warning)"),
        Param::new(
            "font",
            Ty::String,
            "a `.ttf`/`.otf` file, relative to the calling file",
        )
        .or(Lit::Name("the built-in DejaVu Sans")),
        Param::new("thickness", Ty::Float, "the depth of the extrusion")
            .unit(Unit::Length)
            .range(Range::Positive)
            .or(Lit::Float(0.25)),
        Param::new(
            "spacing",
            Ty::Pair(&Ty::Float),
            "`[x, y]` added after each character (POV-Ray's `offset`)",
        )
        .unit(Unit::Length)
        .checked_by_builtin()
        .or(Lit::Name("[0, 0]")),
        Param::new(
            "align",
            Ty::String,
            "\"left\" (the first glyph's edge on x = 0), \"center\" or \"right\"",
        )
        .checked_by_builtin()
        .or(Lit::Name("\"left\"")),
    ],
    "Object",
)
.examples(&[
    "text(string: \"Bg%\", thickness: 0.2, align: \"center\")",
    "text(string: \"AV\", font: \"../stdlib/fonts/DejaVuSans.ttf\", thickness: 0.1, spacing: [0.05, 0], align: \"right\")",
]);
pub(super) fn text(it: &mut dyn Host, s: CallSite, a: Vec<ArgVal>) -> R<Value> {
    let mut p = Params::new(s, &TEXT, a)?;
    let (string, ss) = p.string(it, "string")?;
    if string.chars().count() > crate::assets::MAX_TEXT_CHARS {
        return Err(error(
            "rtc::font::too_large",
            ss,
            format!(
                "a text of {} characters is longer than the {} a text may have",
                string.chars().count(),
                crate::assets::MAX_TEXT_CHARS
            ),
        )
        .with_label("too many characters")
        .with_help("split the string into several `text` objects")
        .into());
    }
    let (font, fs) = match p.get("font") {
        None => (None, s.span),
        Some((v, fs)) => {
            let rel = types::string(it, &v, fs)?;
            (
                Some(crate::eval::assets::existing(it, &rel, fs, "font")?),
                fs,
            )
        }
    };
    let (thickness, _) = p.float(it, "thickness")?;
    let spacing = match p.get("spacing") {
        Some((v, sp)) => pair(it, &v, sp)?,
        None => DVec2::ZERO,
    };
    let align = match p.get("align") {
        None => TextAlign::Left,
        Some((v, sp)) => {
            let name = types::string(it, &v, sp)?;
            match choice(&name, &TextAlign::NAMES, "align", sp)? {
                0 => TextAlign::Left,
                1 => TextAlign::Center,
                _ => TextAlign::Right,
            }
        }
    };
    let asset = crate::assets::font(font.as_deref())
        .map_err(|e| e.diagnostic(fs, font.as_deref().unwrap_or(std::path::Path::new(""))))?;
    let (glyphs, missing) = asset.layout(&string, spacing, align);
    if !missing.is_empty() {
        let list: Vec<String> = missing
            .iter()
            .map(|c| format!("`{c}` (U+{:04X})", u32::from(*c)))
            .collect();
        it.warn(
            Diagnostic::warning(
                "rtc::font::missing_glyph",
                ss,
                format!("the font has no glyph for {}", list.join(", ")),
            )
            .with_label("drawn as the font's .notdef glyph (a box)")
            .with_help("use a font that has these characters, or remove them from the string"),
        );
    }
    checked(
        Shape::Text {
            font,
            string: string.to_string(),
            thickness,
            spacing,
            align,
            glyphs: Arc::new(glyphs),
        },
        s,
        &[("string", ss)],
    )
}
