//! TrueType/OpenType fonts for `text` (read by `ttf-parser`): a font file checked and kept once
//! per process, and a string laid out in it as POV-Ray 3.7 lays out `text`
//! (`source/core/shape/truetype.cpp`): 1 unit = 1 em, the baseline on `y = 0`, the first
//! glyph's left edge at `x = 0`, each next glyph one advance width further plus the font's
//! `kern` table pair value and the extra `spacing`; a character the font lacks drawn as its
//! `.notdef` glyph (glyph 0). The default font, DejaVu Sans, is built in.

use std::path::Path;

use glam::DVec2;
use ttf_parser::{Face, GlyphId, OutlineBuilder};

use crate::ir::{GlyphCurve, TextAlign, TextGlyphs};

/// The built-in font (DejaVu Sans; licence in `stdlib/fonts/LICENSE-DejaVu.txt`).
pub(crate) static DEFAULT_FONT: &[u8] = include_bytes!("../../stdlib/fonts/DejaVuSans.ttf");

/// The largest font file read (checked before reading).
pub(crate) const MAX_FONT_BYTES: u64 = 64 << 20;

/// The most characters a text may have.
pub(crate) const MAX_TEXT_CHARS: usize = 100_000;

/// A font file's bytes, checked to parse.
#[derive(Debug)]
pub struct FontAsset {
    bytes: Vec<u8>,
}

/// Why a font cannot be used.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum FontError {
    /// The file cannot be opened or read.
    Unreadable(String),
    /// The file is larger than [`MAX_FONT_BYTES`].
    TooLarge(u64),
    /// Not a TrueType/OpenType font ttf-parser can read.
    Malformed(String),
}

impl FontAsset {
    /// Reads and checks the font at `path`.
    pub(crate) fn load(path: &Path) -> Result<FontAsset, FontError> {
        let size = std::fs::metadata(path)
            .map_err(|e| FontError::Unreadable(e.to_string()))?
            .len();
        if size > MAX_FONT_BYTES {
            return Err(FontError::TooLarge(size));
        }
        let bytes = std::fs::read(path).map_err(|e| FontError::Unreadable(e.to_string()))?;
        Face::parse(&bytes, 0).map_err(|e| FontError::Malformed(e.to_string()))?;
        Ok(FontAsset { bytes })
    }

    /// The built-in font.
    pub(crate) fn builtin() -> FontAsset {
        FontAsset {
            bytes: DEFAULT_FONT.to_vec(),
        }
    }

    /// `string` laid out with `spacing` after each character and aligned by `align`, and the
    /// characters the font has no glyph for (drawn as its `.notdef`).
    pub(crate) fn layout(
        &self,
        string: &str,
        spacing: DVec2,
        align: TextAlign,
    ) -> (TextGlyphs, Vec<char>) {
        let Ok(face) = Face::parse(&self.bytes, 0) else {
            // `load` parsed it: unreachable in practice, and an empty text says so.
            return (TextGlyphs::default(), Vec::new());
        };
        let em = 1.0 / f64::from(face.units_per_em().max(1));
        let kern: Vec<_> = face
            .tables()
            .kern
            .map(|k| {
                k.subtables
                    .into_iter()
                    .filter(|s| s.horizontal && !s.variable && !s.has_cross_stream)
                    .collect()
            })
            .unwrap_or_default();
        let mut missing = Vec::new();
        let mut placed: Vec<Vec<GlyphCurve>> = Vec::new();
        let mut pen = DVec2::ZERO;
        let mut prev: Option<GlyphId> = None;
        let mut first_edge = 0.0;
        for (i, ch) in string.chars().enumerate() {
            let id = face.glyph_index(ch).unwrap_or_else(|| {
                if !missing.contains(&ch) {
                    missing.push(ch);
                }
                GlyphId(0)
            });
            if let Some(p) = prev {
                let k: i32 = kern
                    .iter()
                    .filter_map(|s| s.glyphs_kerning(p, id))
                    .map(i32::from)
                    .sum();
                pen.x += f64::from(k) * em;
            }
            let lsb = f64::from(face.glyph_hor_side_bearing(id).unwrap_or(0)) * em;
            if i == 0 {
                // POV-Ray puts the first glyph's left edge at the origin.
                first_edge = lsb;
            }
            let mut b = Curves {
                em,
                at: pen - DVec2::new(first_edge, 0.0),
                start: DVec2::ZERO,
                last: DVec2::ZERO,
                out: Vec::new(),
            };
            face.outline_glyph(id, &mut b);
            b.close();
            if !b.out.is_empty() {
                placed.push(b.out);
            }
            pen.x += f64::from(face.glyph_hor_advance(id).unwrap_or(0)) * em;
            pen += spacing;
            prev = Some(id);
        }
        let width = pen.x - spacing.x - first_edge;
        let shift = match align {
            TextAlign::Left => 0.0,
            TextAlign::Center => -0.5 * width,
            TextAlign::Right => -width,
        };
        if shift != 0.0 {
            let d = DVec2::new(shift, 0.0);
            for g in &mut placed {
                for c in g.iter_mut() {
                    match c {
                        GlyphCurve::Line(p) => p.iter_mut().for_each(|q| *q += d),
                        GlyphCurve::Quad(p) => p.iter_mut().for_each(|q| *q += d),
                        GlyphCurve::Cubic(p) => p.iter_mut().for_each(|q| *q += d),
                    }
                }
            }
        }
        (TextGlyphs { glyphs: placed }, missing)
    }

    /// Whether the font has a `kern` table with horizontal pairs.
    #[cfg(test)]
    fn has_kerning(&self) -> bool {
        Face::parse(&self.bytes, 0)
            .ok()
            .and_then(|f| f.tables().kern)
            .is_some_and(|k| k.subtables.into_iter().any(|s| s.horizontal))
    }
}

/// Collects a glyph's outline as curves in em units, moved to `at`.
struct Curves {
    em: f64,
    at: DVec2,
    start: DVec2,
    last: DVec2,
    out: Vec<GlyphCurve>,
}

impl Curves {
    fn p(&self, x: f32, y: f32) -> DVec2 {
        DVec2::new(f64::from(x), f64::from(y)) * self.em + self.at
    }
}

impl OutlineBuilder for Curves {
    fn move_to(&mut self, x: f32, y: f32) {
        self.close();
        self.start = self.p(x, y);
        self.last = self.start;
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let q = self.p(x, y);
        if q != self.last {
            self.out.push(GlyphCurve::Line([self.last, q]));
        }
        self.last = q;
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let (c, q) = (self.p(x1, y1), self.p(x, y));
        self.out.push(GlyphCurve::Quad([self.last, c, q]));
        self.last = q;
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let (c1, c2, q) = (self.p(x1, y1), self.p(x2, y2), self.p(x, y));
        self.out.push(GlyphCurve::Cubic([self.last, c1, c2, q]));
        self.last = q;
    }

    /// Closes the contour with a straight segment back to its start where it is open.
    fn close(&mut self) {
        if self.last != self.start {
            self.out.push(GlyphCurve::Line([self.last, self.start]));
        }
        self.last = self.start;
    }
}

impl FontError {
    /// The diagnostic for this error on the font `path` named at `span`:
    /// `rtc::font::{not_found, too_large, malformed}`.
    pub(crate) fn diagnostic(
        &self,
        span: crate::source::Span,
        path: &Path,
    ) -> crate::diag::Diagnostic {
        use crate::diag::Diagnostic;
        let shown = path.display();
        match self {
            FontError::Unreadable(why) => Diagnostic::error(
                "rtc::font::not_found",
                span,
                format!("cannot read the font file `{shown}`"),
            )
            .with_label(why.clone())
            .with_help("check the path and the file's permissions"),
            FontError::TooLarge(size) => Diagnostic::error(
                "rtc::font::too_large",
                span,
                format!("the font file `{shown}` is too large: {size} bytes"),
            )
            .with_label(format!("more than {MAX_FONT_BYTES} bytes"))
            .with_help("use a font file of at most 64 MiB (a subset of the font)"),
            FontError::Malformed(why) => Diagnostic::error(
                "rtc::font::malformed",
                span,
                format!("`{shown}` is not a TrueType or OpenType font"),
            )
            .with_label(why.clone())
            .with_help(
                "give a `.ttf` or `.otf` file (a collection `.ttc` is read at its first font)",
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn x_extent(g: &[GlyphCurve]) -> (f64, f64) {
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for c in g {
            let pts: &[DVec2] = match c {
                GlyphCurve::Line(p) => p,
                GlyphCurve::Quad(p) => p,
                GlyphCurve::Cubic(p) => p,
            };
            for p in pts {
                lo = lo.min(p.x);
                hi = hi.max(p.x);
            }
        }
        (lo, hi)
    }

    #[test]
    fn the_first_glyph_starts_at_the_origin_and_holes_are_contours() {
        let f = FontAsset::builtin();
        let (t, missing) = f.layout("Bg%o", DVec2::ZERO, TextAlign::Left);
        assert!(missing.is_empty());
        assert_eq!(t.glyphs.len(), 4);
        let (lo, _) = x_extent(&t.glyphs[0]);
        assert!(lo.abs() < 1e-12, "{lo}");
        // Every contour closes: each curve starts where the previous one ended, or a new
        // contour begins, and the ends of each glyph's curves pair up.
        for g in &t.glyphs {
            let ends = |c: &GlyphCurve| match *c {
                GlyphCurve::Line([a, b]) => (a, b),
                GlyphCurve::Quad([a, _, b]) => (a, b),
                GlyphCurve::Cubic([a, _, _, b]) => (a, b),
            };
            let starts: Vec<_> = g.iter().map(|c| ends(c).0).collect();
            for c in g {
                assert!(starts.contains(&ends(c).1));
            }
        }
    }

    #[test]
    fn a_missing_character_is_reported_and_drawn_as_notdef() {
        let f = FontAsset::builtin();
        let (t, missing) = f.layout("A\u{10FFFD}", DVec2::ZERO, TextAlign::Left);
        assert_eq!(missing, vec!['\u{10FFFD}']);
        assert_eq!(t.glyphs.len(), 2, ".notdef has an outline");
    }

    #[test]
    fn kerning_pairs_and_alignment_move_glyphs() {
        let f = FontAsset::builtin();
        let (av, _) = f.layout("AV", DVec2::ZERO, TextAlign::Left);
        let (a, _) = f.layout("A", DVec2::ZERO, TextAlign::Left);
        let (v, _) = f.layout("V", DVec2::ZERO, TextAlign::Left);
        let face = Face::parse(DEFAULT_FONT, 0).unwrap();
        let em = 1.0 / f64::from(face.units_per_em());
        let adv = f64::from(
            face.glyph_hor_advance(face.glyph_index('A').unwrap())
                .unwrap(),
        ) * em;
        let lsb_a = f64::from(
            face.glyph_hor_side_bearing(face.glyph_index('A').unwrap())
                .unwrap(),
        ) * em;
        let lsb_v = f64::from(
            face.glyph_hor_side_bearing(face.glyph_index('V').unwrap())
                .unwrap(),
        ) * em;
        let v_at = x_extent(&av.glyphs[1]).0;
        let unkerned = adv - lsb_a + lsb_v;
        if f.has_kerning() {
            assert!(v_at < unkerned - 1e-6, "V at {v_at}, unkerned {unkerned}");
        } else {
            assert!((v_at - unkerned).abs() < 1e-9);
        }
        assert_eq!(x_extent(&a.glyphs[0]).0, 0.0);
        assert!(x_extent(&v.glyphs[0]).0.abs() < 1e-12);
        let (r, _) = f.layout("AV", DVec2::ZERO, TextAlign::Right);
        let (c, _) = f.layout("AV", DVec2::ZERO, TextAlign::Center);
        let shift_r = x_extent(&r.glyphs[0]).0;
        let shift_c = x_extent(&c.glyphs[0]).0;
        assert!(shift_r < 0.0 && (shift_c - 0.5 * shift_r).abs() < 1e-12);
    }
}
