//! The header of a PLY file: `ply`, `format`, then `element NAME COUNT` lines each followed by
//! its `property TYPE NAME` / `property list COUNT_TYPE ITEM_TYPE NAME` lines (and `comment` or
//! `obj_info` lines anywhere), up to `end_header`. Counts are checked here against the triangle
//! budget and the file's length, so the body's reader never sizes anything from an untrusted
//! number.

use super::mesh_data::too_many_triangles;
use super::obj_error::MeshError;

/// Lines a header may have: a real one has a few dozen.
const MAX_HEADER_LINES: usize = 10_000;

/// A PLY scalar type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    /// The type of a header word (both spellings of PLY's types).
    fn of(word: &str) -> Option<Scalar> {
        Some(match word {
            "char" | "int8" => Scalar::I8,
            "uchar" | "uint8" => Scalar::U8,
            "short" | "int16" => Scalar::I16,
            "ushort" | "uint16" => Scalar::U16,
            "int" | "int32" => Scalar::I32,
            "uint" | "uint32" => Scalar::U32,
            "float" | "float32" => Scalar::F32,
            "double" | "float64" => Scalar::F64,
            _ => return None,
        })
    }

    /// Bytes of a binary value.
    pub(super) fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }

    /// The type's name in a header.
    pub(super) fn name(self) -> &'static str {
        match self {
            Scalar::I8 => "char",
            Scalar::U8 => "uchar",
            Scalar::I16 => "short",
            Scalar::U16 => "ushort",
            Scalar::I32 => "int",
            Scalar::U32 => "uint",
            Scalar::F32 => "float",
            Scalar::F64 => "double",
        }
    }
}

/// A property's type: one value, or a list of values after its length.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    Scalar(Scalar),
    /// The length's type and the items' type.
    List(Scalar, Scalar),
}

/// One property of an element.
#[derive(Debug)]
pub(super) struct Property {
    pub(super) name: String,
    pub(super) kind: Kind,
}

/// One element: its name, how many the body holds, and each one's properties in order.
#[derive(Debug)]
pub(super) struct Element {
    pub(super) name: String,
    pub(super) count: u64,
    pub(super) properties: Vec<Property>,
    /// The header line declaring it.
    pub(super) line: usize,
}

/// How the body is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Encoding {
    Ascii,
    Binary { big: bool },
}

/// A checked header.
#[derive(Debug)]
pub(super) struct Header {
    pub(super) encoding: Encoding,
    pub(super) elements: Vec<Element>,
    /// Byte where the body starts.
    pub(super) body_start: usize,
    /// The body's first line.
    pub(super) body_line: usize,
}

/// The error at header line `line`.
fn bad(line: usize, message: impl Into<String>, fix: &str) -> MeshError {
    MeshError::at_line(message, line, fix)
}

/// The header of the PLY file `bytes`.
pub(super) fn header(bytes: &[u8], max_triangles: usize) -> Result<Header, MeshError> {
    let mut at = 0;
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    for line in 1..=MAX_HEADER_LINES {
        let Some(end) = memchr::memchr(b'\n', &bytes[at..]) else {
            return Err(bad(
                line,
                "the PLY header has no `end_header` line",
                "the file is truncated or not PLY: export it again",
            ));
        };
        let raw = &bytes[at..at + end];
        at += end + 1;
        let text = String::from_utf8_lossy(raw.strip_suffix(b"\r").unwrap_or(raw));
        let words: Vec<&str> = text.split_ascii_whitespace().collect();
        if line == 1 {
            if words != ["ply"] {
                return Err(bad(
                    1,
                    "a PLY file must start with the line `ply`",
                    "check that the file is PLY (the extension picks the reader)",
                ));
            }
            continue;
        }
        match words.as_slice() {
            ["format", kind, "1.0"] => {
                encoding = Some(match *kind {
                    "ascii" => Encoding::Ascii,
                    "binary_little_endian" => Encoding::Binary { big: false },
                    "binary_big_endian" => Encoding::Binary { big: true },
                    _ => {
                        return Err(bad(
                            line,
                            format!("unknown PLY format `{kind}`"),
                            "the format is `ascii`, `binary_little_endian` or `binary_big_endian`, version 1.0",
                        ));
                    }
                })
            }
            ["comment", ..] | ["obj_info", ..] | [] => {}
            ["element", name, count] => {
                let Ok(count) = count.parse::<u64>() else {
                    return Err(bad(
                        line,
                        format!("the PLY element `{name}` has count `{count}`, not a whole number"),
                        "write `element NAME COUNT` with COUNT a whole number",
                    ));
                };
                elements.push(Element {
                    name: (*name).to_owned(),
                    count,
                    properties: Vec::new(),
                    line,
                });
            }
            ["property", rest @ ..] => {
                let Some(e) = elements.last_mut() else {
                    return Err(bad(
                        line,
                        "a PLY property before any element",
                        "declare `element NAME COUNT` before its properties",
                    ));
                };
                e.properties.push(property(rest, line)?);
            }
            ["end_header"] => {
                let Some(encoding) = encoding else {
                    return Err(bad(
                        line,
                        "the PLY header has no `format` line",
                        "add `format binary_little_endian 1.0` (or `ascii 1.0`) after `ply`",
                    ));
                };
                let h = Header {
                    encoding,
                    elements,
                    body_start: at,
                    body_line: line + 1,
                };
                check_counts(&h, bytes.len(), max_triangles)?;
                return Ok(h);
            }
            _ => {
                let shown: String = text.chars().take(60).collect();
                return Err(bad(
                    line,
                    format!("a PLY header line rtc does not know: `{shown}`"),
                    "the header has `format`, `element`, `property`, `comment`, `obj_info` and `end_header` lines",
                ));
            }
        }
    }
    Err(bad(
        MAX_HEADER_LINES,
        format!("the PLY header has more than {MAX_HEADER_LINES} lines"),
        "the file is not PLY, or its `end_header` line is missing",
    ))
}

/// The words after `property`.
fn property(words: &[&str], line: usize) -> Result<Property, MeshError> {
    let ty = |w: &str| {
        Scalar::of(w).ok_or_else(|| {
            bad(
                line,
                format!("unknown PLY type `{w}`"),
                "the types are char, uchar, short, ushort, int, uint, float and double",
            )
        })
    };
    let (kind, name) = match words {
        ["list", count, item, name] => {
            let (count, item) = (ty(count)?, ty(item)?);
            if matches!(count, Scalar::F32 | Scalar::F64) {
                return Err(bad(
                    line,
                    format!("the PLY list `{name}` has a `{}` length", count.name()),
                    "a list's length is an integer type: `property list uchar int vertex_indices`",
                ));
            }
            (Kind::List(count, item), name)
        }
        [ty_word, name] => (Kind::Scalar(ty(ty_word)?), name),
        _ => {
            return Err(bad(
                line,
                "a PLY property line is `property TYPE NAME` or `property list COUNT_TYPE ITEM_TYPE NAME`",
                "fix the header line",
            ));
        }
    };
    Ok(Property {
        name: (*name).to_owned(),
        kind,
    })
}

/// Counts within the budget and the file: each element with properties takes at least a byte
/// of the body (so a count above the body's length is a lie); each face at least a triangle.
fn check_counts(h: &Header, len: usize, max_triangles: usize) -> Result<(), MeshError> {
    let body = (len - h.body_start) as u64;
    for e in &h.elements {
        if e.name == "face" && e.count > max_triangles as u64 {
            return Err(too_many_triangles(e.count, max_triangles));
        }
        if !e.properties.is_empty() && e.count > body {
            return Err(bad(
                e.line,
                format!(
                    "the PLY element `{}` counts {} but the body has only {body} bytes",
                    e.name, e.count
                ),
                "the file is truncated or its header is wrong: export it again",
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_header_is_read_and_checked() {
        let text = b"ply\r\nformat binary_big_endian 1.0\ncomment x\nelement vertex 1\nproperty float x\nproperty list uchar int vertex_indices\nend_header\n0123";
        let h = header(text, 10).unwrap();
        assert_eq!(h.encoding, Encoding::Binary { big: true });
        assert_eq!(
            h.elements[0].properties[1].kind,
            Kind::List(Scalar::U8, Scalar::I32)
        );
        assert_eq!(h.body_line, 8);
        assert_eq!(&text[h.body_start..], b"0123");
        let lie =
            b"ply\nformat ascii 1.0\nelement vertex 99\nproperty float x\nend_header\n1 2 3\n";
        let e = header(lie, 10).unwrap_err();
        assert_eq!(e.line, Some(3), "{e:?}");
        let faces = b"ply\nformat ascii 1.0\nelement face 11\nproperty float x\nend_header\n";
        assert!(header(faces, 10).unwrap_err().too_large);
        let e = header(b"ply\nformat ascii 1.0\nproperty list float int x\n", 10).unwrap_err();
        assert_eq!(e.line, Some(3));
        assert_eq!(header(b"plyx\n", 10).unwrap_err().line, Some(1));
    }
}
