//! The Magdeburg classroom raytracer's `.in` format (COURSE.md §1): records named by their first
//! letter (`Eye`, `Light`, `Material`, `Sphere`, any case), numbers read like C++ `>>`, optional
//! `( )`, `[ ]`, `< >` around triples, `#` comments, records free to span lines. `Material` is
//! state that later spheres use. rt2 extension: `Material r g b ka kd ks n [reflect [refract [eta]]]`.

use std::path::Path;

use glam::DVec3;

use crate::compat::course::{self, CourseMaterial, Draft};
use crate::diag::{Diagnostic, Diagnostics};
use crate::ir::{Light, LightKind};
use crate::source::{FileId, Span};

/// How the three numbers of a point are named in "record ends before ..." messages.
const XYZ_FIELDS: [&str; 3] = ["the x coordinate", "the y coordinate", "the z coordinate"];
/// How the three numbers of a colour are named in messages.
const RGB_FIELDS: [&str; 3] = [
    "the red component",
    "the green component",
    "the blue component",
];

/// The record kinds, with their field lists for messages.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Eye,
    Light,
    Material,
    Sphere,
}

impl Kind {
    fn name(self) -> &'static str {
        match self {
            Kind::Eye => "Eye",
            Kind::Light => "Light",
            Kind::Material => "Material",
            Kind::Sphere => "Sphere",
        }
    }

    fn layout(self) -> &'static str {
        match self {
            Kind::Eye => "`Eye x y z`",
            Kind::Light => "`Light x y z r g b`",
            Kind::Material => {
                "`Material r g b ka kd ks n`, optionally followed by `reflect refract eta`"
            }
            Kind::Sphere => "`Sphere x y z radius`",
        }
    }
}

/// Reads `.in` text into `draft`, reporting every problem found (it recovers at the next record).
pub(crate) fn parse(
    text: &str,
    file: FileId,
    _path: &Path,
    draft: &mut Draft,
    diags: &mut Diagnostics,
) {
    let mut p = Reader {
        text,
        pos: 0,
        file,
        diags,
        material: None,
        last: None,
    };
    p.run(draft);
}

struct Reader<'t, 'd> {
    text: &'t str,
    pos: usize,
    file: FileId,
    diags: &'d mut Diagnostics,
    /// The current material and where its record was.
    material: Option<CourseMaterial>,
    /// The last record read (for the help on a stray number).
    last: Option<Kind>,
}

/// Why a record could not be completed; the diagnostic is already reported.
struct Failed;

fn is_delim(c: u8) -> bool {
    matches!(c, b'(' | b')' | b'[' | b']' | b'<' | b'>')
}

impl<'t> Reader<'t, '_> {
    fn span(&self, start: usize, end: usize) -> Span {
        Span::new(self.file, start, end)
    }

    /// Skips whitespace (including CR) and `#` comments.
    fn skip_blank(&mut self) {
        let bytes = self.text.as_bytes();
        while let Some(&c) = bytes.get(self.pos) {
            if c.is_ascii_whitespace() {
                self.pos += 1;
            } else if c == b'#' {
                while let Some(&c) = bytes.get(self.pos) {
                    if c == b'\n' {
                        break;
                    }
                    self.pos += 1;
                }
            } else {
                break;
            }
        }
    }

    /// The next token (after blanks) without consuming it: a single delimiter, or a run of
    /// characters up to whitespace, `#` or a delimiter.
    fn peek_token(&mut self) -> Option<(usize, usize)> {
        self.skip_blank();
        let bytes = self.text.as_bytes();
        let start = self.pos;
        let first = *bytes.get(start)?;
        if is_delim(first) {
            return Some((start, start + 1));
        }
        let mut end = start;
        while let Some(&c) = bytes.get(end) {
            if c.is_ascii_whitespace() || c == b'#' || is_delim(c) {
                break;
            }
            end += 1;
        }
        // Tokens end only at ASCII bytes, so `end` is a char boundary.
        Some((start, end))
    }

    fn run(&mut self, draft: &mut Draft) {
        while let Some((start, end)) = self.peek_token() {
            let first = self.text.as_bytes()[start];
            if !first.is_ascii_alphabetic() {
                self.stray(start, end);
                self.pos = end;
                continue;
            }
            // The keyword is its first letter; further letters are skipped (so `Eye200` works).
            let mut kw_end = start;
            while self
                .text
                .as_bytes()
                .get(kw_end)
                .is_some_and(|c| c.is_ascii_alphabetic())
            {
                kw_end += 1;
            }
            let kw = self.span(start, kw_end);
            let kind = match first.to_ascii_uppercase() {
                b'E' => Kind::Eye,
                b'L' => Kind::Light,
                b'M' => Kind::Material,
                b'S' => Kind::Sphere,
                _ => {
                    self.unknown_record(kw);
                    self.pos = end;
                    self.skip_to_keyword();
                    continue;
                }
            };
            self.pos = kw_end;
            self.last = Some(kind);
            if self.record(kind, kw, draft).is_err() {
                self.skip_to_keyword();
            }
        }
    }

    fn unknown_record(&mut self, kw: Span) {
        let word = &self.text[kw.start as usize..kw.end as usize];
        let guess = crate::diag::did_you_mean(word, ["Eye", "Light", "Material", "Sphere"]);
        let mut d = Diagnostic::error(
            "rtc::in::unknown_record",
            kw,
            format!("unknown record `{word}`"),
        )
        .with_label("a record starts with E, L, M or S");
        d = match guess {
            Some(g) => d.with_help(format!("did you mean `{g}`?")),
            None => d.with_help("records are `Eye`, `Light`, `Material` and `Sphere`"),
        };
        self.diags.push(d);
    }

    fn stray(&mut self, start: usize, end: usize) {
        let word = &self.text[start..end];
        let span = self.span(start, end);
        let d = match self.last {
            Some(kind) if !is_delim(self.text.as_bytes()[start]) => Diagnostic::error(
                "rtc::in::extra_number",
                span,
                format!("unexpected `{word}` after a {} record", kind.name()),
            )
            .with_label("this is not part of any record")
            .with_help(format!("a {} record is {}", kind.name(), kind.layout())),
            _ => Diagnostic::error(
                "rtc::in::expected_record",
                span,
                format!("expected a record, found `{word}`"),
            )
            .with_label("a record starts with a keyword")
            .with_help("records are `Eye`, `Light`, `Material` and `Sphere`"),
        };
        self.diags.push(d);
    }

    /// After an error, skips to the next token that starts with a letter (the next record).
    fn skip_to_keyword(&mut self) {
        while let Some((start, end)) = self.peek_token() {
            let c = self.text.as_bytes()[start];
            if c.is_ascii_alphabetic() && self.text[start..end].parse::<f64>().is_err() {
                break;
            }
            self.pos = end;
        }
    }

    fn record(&mut self, kind: Kind, kw: Span, draft: &mut Draft) -> Result<(), Failed> {
        match kind {
            Kind::Eye => {
                draft.camera_written = true;
                let (eye, _) = self.triple(kind, kw, XYZ_FIELDS)?;
                let span = kw.join(self.span(self.pos, self.pos));
                if let Some((_, old)) = draft.eye {
                    self.diags.push(
                        Diagnostic::warning(
                            "rtc::in::duplicate_eye",
                            span,
                            "a second `Eye` record",
                        )
                        .with_label("this eye replaces the earlier one")
                        .with_secondary(old, "first eye"),
                    );
                }
                draft.eye = Some((eye, span));
            }
            Kind::Light => {
                let (position, _) = self.triple(kind, kw, XYZ_FIELDS)?;
                let (color, c_span) = self.triple(kind, kw, RGB_FIELDS)?;
                self.non_negative_color(color, c_span, "light colour");
                draft.lights.push(Light::new(
                    LightKind::Point { position },
                    color,
                    kw.join(self.span(self.pos, self.pos)),
                ));
            }
            Kind::Material => {
                let (color, c_span) = self.triple(kind, kw, RGB_FIELDS)?;
                self.non_negative_color(color, c_span, "material colour");
                let ka = self.coefficient(kind, kw, "ka")?;
                let kd = self.coefficient(kind, kw, "kd")?;
                let ks = self.coefficient(kind, kw, "ks")?;
                let n = self.coefficient(kind, kw, "the Phong exponent n")?;
                // rt2: up to three more numbers before the next keyword.
                let mut extra = [None; 3];
                for (i, name) in ["reflect", "refract", "eta"].into_iter().enumerate() {
                    match self.peek_token() {
                        Some((s, _)) if starts_number(self.text.as_bytes()[s]) => {
                            extra[i] = Some(self.coefficient(kind, kw, name)?);
                        }
                        _ => break,
                    }
                }
                let span = kw.join(self.span(self.pos, self.pos));
                let refract = extra[1].unwrap_or(0.0);
                let eta = extra[2].unwrap_or(1.0);
                if refract > 0.0 && eta <= 0.0 {
                    self.diags.push(course::out_of_range(
                        span,
                        &eta.to_string(),
                        "eta",
                        "positive for a refracting material",
                    ));
                }
                self.material = Some(CourseMaterial {
                    color,
                    texture: None,
                    ka,
                    kd,
                    ks,
                    n,
                    reflect: extra[0],
                    refract,
                    eta: if eta > 0.0 { eta } else { 1.0 },
                    span,
                });
            }
            Kind::Sphere => {
                let (center, _) = self.triple(kind, kw, XYZ_FIELDS)?;
                let (text, r, r_span) = self.number(kind, kw, "the radius")?;
                let span = kw.join(self.span(self.pos, self.pos));
                if r <= 0.0 {
                    self.diags
                        .push(course::out_of_range(r_span, text, "radius", "positive"));
                    return Ok(());
                }
                let Some(material) = &self.material else {
                    self.diags.push(
                        Diagnostic::error("rtc::in::no_material", kw, "sphere without a material")
                            .with_label("no `Material` record comes before this sphere")
                            .with_help("put a record such as `Material 1 1 1 .2 .8 0 1` before it"),
                    );
                    return Ok(());
                };
                let id = draft.scene.add_material(material.to_ir());
                let sphere = course::sphere_object(center, r, None, Some(id), span);
                draft.scene.objects.push(sphere);
            }
        }
        Ok(())
    }

    fn non_negative_color(&mut self, c: DVec3, span: Span, what: &str) {
        if c.min_element() < 0.0 {
            self.diags.push(
                Diagnostic::error(
                    "rtc::compat::out_of_range",
                    span,
                    format!("negative {what} {} {} {}", c.x, c.y, c.z),
                )
                .with_label("colour components must be 0 or more"),
            );
        }
    }

    fn coefficient(&mut self, kind: Kind, kw: Span, what: &str) -> Result<f64, Failed> {
        let (text, v, span) = self.number(kind, kw, what)?;
        if v < 0.0 {
            self.diags
                .push(course::out_of_range(span, text, what, "0 or more"));
        }
        Ok(v)
    }

    /// Three numbers, optionally inside `( )`, `[ ]` or `< >`.
    fn triple(&mut self, kind: Kind, kw: Span, what: [&str; 3]) -> Result<(DVec3, Span), Failed> {
        let begin = self.peek_token().map_or(self.pos, |(s, _)| s);
        let open = match self.peek_token() {
            Some((s, _)) if matches!(self.text.as_bytes()[s], b'(' | b'[' | b'<') => {
                self.pos = s + 1;
                Some(s)
            }
            _ => None,
        };
        let x = self.number(kind, kw, what[0])?.1;
        let y = self.number(kind, kw, what[1])?.1;
        let z = self.number(kind, kw, what[2])?.1;
        if let Some(o) = open {
            let want = match self.text.as_bytes()[o] {
                b'(' => b')',
                b'[' => b']',
                _ => b'>',
            };
            match self.peek_token() {
                Some((s, _)) if self.text.as_bytes()[s] == want => self.pos = s + 1,
                found => {
                    let at = found.map_or(self.span(self.pos, self.pos), |(s, e)| self.span(s, e));
                    let closer = want as char;
                    self.diags.push(
                        Diagnostic::error(
                            "rtc::in::unclosed",
                            at,
                            format!("expected `{closer}` after three numbers"),
                        )
                        .with_label(format!("expected `{closer}` here"))
                        .with_secondary(self.span(o, o + 1), "opened here")
                        .with_help(format!("close the triple with `{closer}`")),
                    );
                    return Err(Failed);
                }
            }
        }
        Ok((DVec3::new(x, y, z), self.span(begin, self.pos)))
    }

    /// One number; a missing one (end of file, or the next keyword) is a truncated record.
    fn number(&mut self, kind: Kind, kw: Span, what: &str) -> Result<(&'t str, f64, Span), Failed> {
        let text = self.text;
        let before = self.pos;
        let Some((start, end)) = self.peek_token() else {
            // Point just after the last number rather than past trailing blank lines.
            let at = self.span(before, before);
            self.truncated(kind, kw, at, what, "the file ends after this");
            return Err(Failed);
        };
        let word = &text[start..end];
        let span = self.span(start, end);
        let parsed = word.parse::<f64>();
        let first = text.as_bytes()[start];
        // A word starting with a record letter is the next record (this one is cut short); any
        // other word is a bad number in this record.
        if matches!(first.to_ascii_uppercase(), b'E' | b'L' | b'M' | b'S') && parsed.is_err() {
            let label = format!("`{word}` starts the next record");
            self.truncated(kind, kw, span, what, &label);
            return Err(Failed);
        }
        self.pos = end;
        let Ok(value) = parsed else {
            self.diags.push(
                Diagnostic::error(
                    "rtc::in::expected_number",
                    span,
                    format!("expected {what}, found `{word}`"),
                )
                .with_label("not a number")
                .with_help(format!(
                    "a {} record is {}",
                    kind.name(),
                    kind.layout()
                )),
            );
            return Err(Failed);
        };
        match course::check_number(word, value, span, what, self.diags) {
            Some(v) => Ok((word, v, span)),
            None => Err(Failed),
        }
    }

    fn truncated(&mut self, kind: Kind, kw: Span, at: Span, what: &str, label: &str) {
        self.diags.push(
            Diagnostic::error(
                "rtc::in::truncated",
                at,
                format!("`{}` record ends before {what}", kind.name()),
            )
            .with_label(label.to_string())
            .with_secondary(kw, "the record starts here")
            .with_help(format!("a {} record is {}", kind.name(), kind.layout())),
        );
    }
}

fn starts_number(c: u8) -> bool {
    c.is_ascii_digit() || matches!(c, b'.' | b'+' | b'-')
}
