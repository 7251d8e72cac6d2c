//! PLY files (ASCII, binary little- and big-endian). Written here rather than through
//! `ply-rs-bw`: that crate reads every element into a map of property names to values, which
//! for a million faces is many times the cost of the OBJ reader (the benchmark wants PLY at
//! least as fast), and reports neither lines nor byte offsets. The header ([`super::ply_header`])
//! is checked first: counts against the budgets and the file's length, so no allocation is
//! sized from an untrusted number.
//!
//! Read: the `vertex` element's `x y z`, normals `nx ny nz`, texture coordinates (`s t`,
//! `u v`, `texture_u texture_v` or `texture_s texture_t`), colours (`red green blue` or
//! `diffuse_red diffuse_green diffuse_blue`: a `uchar` is byte/255, a `ushort` /65535, a
//! float as written, clamped to [0, 1]; no sRGB curve, as image texels are read), and the
//! `face` element's list `vertex_indices` (or `vertex_index`), each polygon fanned from its
//! first corner. Other properties and elements (alpha, `edge`, `material`, ...) are read past.

use glam::{Vec2, Vec3};

use super::mesh_data::{Indexed, too_many_triangles};
use super::obj_error::MeshError;
use super::ply_header::{Element, Encoding, Header, Kind, Scalar, header};
use super::stl::Words;

/// The mesh in a PLY file's bytes, at most `max_triangles` triangles.
pub(super) fn parse(bytes: &[u8], max_triangles: usize) -> Result<Indexed, MeshError> {
    let h = header(bytes, max_triangles)?;
    let mut body = Body::new(bytes, &h);
    let mut mesh = Indexed::default();
    let vertex_count = h
        .elements
        .iter()
        .find(|e| e.name == "vertex")
        .map_or(0, |e| e.count);
    for e in &h.elements {
        match e.name.as_str() {
            "vertex" => vertices(&mut body, e, &mut mesh)?,
            "face" => faces(&mut body, e, vertex_count, max_triangles, &mut mesh)?,
            _ => {
                for _ in 0..e.count {
                    for p in &e.properties {
                        body.skip(p.kind)?;
                    }
                }
            }
        }
    }
    Ok(mesh)
}

/// Where each property the mesh uses sits in the vertex element.
#[derive(Default)]
struct Roles {
    position: [Option<usize>; 3],
    normal: [Option<usize>; 3],
    uv: [Option<usize>; 2],
    color: [Option<usize>; 3],
}

/// A colour channel stored as type `s`, in [0, 1]: integers scaled from their type's range
/// (a `uchar` 255 is 1), floats as written; NaN is 0.
fn channel(v: f32, s: Scalar) -> f32 {
    let full = match s {
        Scalar::U16 => 65535.0,
        Scalar::F32 | Scalar::F64 => 1.0,
        _ => 255.0,
    };
    let c = v / full;
    if c.is_nan() { 0.0 } else { c.clamp(0.0, 1.0) }
}

fn vertices(body: &mut Body<'_>, e: &Element, mesh: &mut Indexed) -> Result<(), MeshError> {
    let mut roles = Roles::default();
    for (i, p) in e.properties.iter().enumerate() {
        if !matches!(p.kind, Kind::Scalar(_)) {
            continue;
        }
        let slot = match p.name.as_str() {
            "x" => &mut roles.position[0],
            "y" => &mut roles.position[1],
            "z" => &mut roles.position[2],
            "nx" => &mut roles.normal[0],
            "ny" => &mut roles.normal[1],
            "nz" => &mut roles.normal[2],
            "s" | "u" | "texture_u" | "texture_s" => &mut roles.uv[0],
            "t" | "v" | "texture_v" | "texture_t" => &mut roles.uv[1],
            "red" | "diffuse_red" => &mut roles.color[0],
            "green" | "diffuse_green" => &mut roles.color[1],
            "blue" | "diffuse_blue" => &mut roles.color[2],
            _ => continue,
        };
        slot.get_or_insert(i);
    }
    let [Some(x), Some(y), Some(z)] = roles.position else {
        return Err(MeshError::at_line(
            "the PLY `vertex` element has no `x`, `y` and `z` properties",
            e.line,
            "declare the positions as `property float x`, `property float y`, `property float z`",
        ));
    };
    let normals = roles.normal.iter().all(Option::is_some);
    let uvs = roles.uv.iter().all(Option::is_some);
    let colors = roles.color.iter().all(Option::is_some);
    // Each channel's type (checked scalar above), for its scale.
    let types = roles.color.map(|i| match i.map(|i| e.properties[i].kind) {
        Some(Kind::Scalar(s)) => s,
        _ => Scalar::F32,
    });
    // The header's count is checked against the file's length: each vertex takes a byte.
    let cap = e.count as usize;
    mesh.vertices.reserve(cap);
    if normals {
        mesh.normals.reserve(cap);
    }
    if uvs {
        mesh.uvs.reserve(cap);
    }
    if colors {
        mesh.colors.reserve(cap);
    }
    let mut values = vec![0f32; e.properties.len()];
    for _ in 0..e.count {
        for (v, p) in values.iter_mut().zip(&e.properties) {
            *v = match p.kind {
                Kind::Scalar(s) => body.float(s)?,
                list => {
                    body.skip(list)?;
                    0.0
                }
            };
        }
        mesh.vertices
            .push(Vec3::new(values[x], values[y], values[z]));
        if normals {
            let n = roles.normal.map(|i| values[i.unwrap_or(0)]);
            mesh.normals.push(Vec3::from_array(n));
        }
        if uvs {
            let t = roles.uv.map(|i| values[i.unwrap_or(0)]);
            mesh.uvs.push(Vec2::from_array(t));
        }
        if colors {
            let c = std::array::from_fn(|k| channel(values[roles.color[k].unwrap_or(0)], types[k]));
            mesh.colors.push(Vec3::from_array(c));
        }
    }
    Ok(())
}

fn faces(
    body: &mut Body<'_>,
    e: &Element,
    vertex_count: u64,
    max_triangles: usize,
    mesh: &mut Indexed,
) -> Result<(), MeshError> {
    let list = e.properties.iter().position(|p| {
        matches!(p.kind, Kind::List(..))
            && matches!(p.name.as_str(), "vertex_indices" | "vertex_index")
    });
    let Some(list) = list else {
        return Err(MeshError::at_line(
            "the PLY `face` element has no `vertex_indices` list",
            e.line,
            "declare the faces' corners as `property list uchar int vertex_indices`",
        ));
    };
    mesh.triangles.reserve(e.count as usize);
    let mut corners: Vec<u32> = Vec::new();
    for face in 0..e.count {
        for (i, p) in e.properties.iter().enumerate() {
            let Kind::List(count, item) = p.kind else {
                body.skip(p.kind)?;
                continue;
            };
            if i != list {
                body.skip(p.kind)?;
                continue;
            }
            let where_ = body.position();
            let n = body.count(count, item)?;
            corners.clear();
            for _ in 0..n {
                let at = body.position();
                let v = body.integer(item)?;
                if v < 0 || v as u64 >= vertex_count {
                    return Err(body.error(
                        format!(
                            "face {face} names vertex {v}, but the file has {vertex_count} vertices (0 to {})",
                            vertex_count.saturating_sub(1)
                        ),
                        at,
                        "a face's corners index the `vertex` element from 0: fix or re-export the file",
                    ));
                }
                corners.push(v as u32);
            }
            if corners.len() < 3 {
                return Err(body.error(
                    format!(
                        "face {face} has {} corners; a face needs at least 3",
                        corners.len()
                    ),
                    where_,
                    "remove the face or re-export the mesh with polygons of three or more corners",
                ));
            }
            if mesh.triangles.len() + corners.len() - 2 > max_triangles {
                return Err(too_many_triangles(
                    (mesh.triangles.len() + corners.len() - 2) as u64,
                    max_triangles,
                ));
            }
            for k in 1..corners.len() - 1 {
                mesh.triangles
                    .push([corners[0], corners[k], corners[k + 1]]);
            }
        }
    }
    Ok(())
}

/// Where the reader is: a line of an ASCII body, a byte of a binary one.
#[derive(Clone, Copy)]
enum Position {
    Line(usize),
    Byte(u64),
}

/// The body after the header, read value by value.
enum Body<'a> {
    Ascii(Words<'a>),
    Binary {
        bytes: &'a [u8],
        at: usize,
        big: bool,
    },
}

impl<'a> Body<'a> {
    fn new(bytes: &'a [u8], h: &Header) -> Body<'a> {
        match h.encoding {
            Encoding::Ascii => {
                let mut words = Words::new(bytes);
                words.at = h.body_start;
                words.line = h.body_line;
                Body::Ascii(words)
            }
            Encoding::Binary { big } => Body::Binary {
                bytes,
                at: h.body_start,
                big,
            },
        }
    }

    fn position(&self) -> Position {
        match self {
            Body::Ascii(w) => Position::Line(w.line),
            Body::Binary { at, .. } => Position::Byte(*at as u64),
        }
    }

    fn error(&self, message: String, at: Position, fix: &str) -> MeshError {
        match at {
            Position::Line(l) => MeshError::at_line(message, l, fix),
            Position::Byte(b) => MeshError::at_byte(message, b, fix),
        }
    }

    /// The next ASCII word, or the error of a file that ends early.
    fn word(&mut self, what: Scalar) -> Result<&'a str, MeshError> {
        let Body::Ascii(w) = self else {
            unreachable!("words are read from ASCII bodies only")
        };
        let line = w.line;
        match w.next_word() {
            Some((word, line)) => std::str::from_utf8(word).map_err(|_| {
                MeshError::at_line(
                    format!(
                        "expected a PLY `{}` value, found bytes that are not text",
                        what.name()
                    ),
                    line,
                    "an ASCII PLY body holds numbers only: re-export the file",
                )
            }),
            None => Err(MeshError::at_line(
                format!(
                    "the PLY file ends where a `{}` value was expected",
                    what.name()
                ),
                line,
                "the file is truncated, or its header counts more elements than it holds: re-export it",
            )),
        }
    }

    /// The next `n` bytes of a binary body, or the error of a file that ends early.
    fn take<const N: usize>(&mut self, what: Scalar) -> Result<[u8; N], MeshError> {
        let Body::Binary { bytes, at, big } = self else {
            unreachable!("bytes are read from binary bodies only")
        };
        let Some(b) = bytes.get(*at..*at + N) else {
            return Err(MeshError::at_byte(
                format!(
                    "the PLY file ends where a `{}` value was expected",
                    what.name()
                ),
                *at as u64,
                "the file is truncated, or its header counts more elements than it holds: re-export it",
            ));
        };
        *at += N;
        let mut out = [0u8; N];
        out.copy_from_slice(b);
        if *big {
            out.reverse();
        }
        Ok(out)
    }

    /// A value of type `s` as f32 (a `float` exactly as stored; a `double` rounded once).
    fn float(&mut self, s: Scalar) -> Result<f32, MeshError> {
        if let Body::Ascii(_) = self {
            let at = self.position();
            let w = self.word(s)?;
            let v = match s {
                Scalar::F32 => w.parse::<f32>().ok(),
                Scalar::F64 => w.parse::<f64>().ok().map(|v| v as f32),
                _ => w.parse::<i64>().ok().map(|v| v as f32),
            };
            return v.ok_or_else(|| self.bad_word(w, s, at));
        }
        Ok(match s {
            Scalar::F32 => f32::from_le_bytes(self.take(s)?),
            Scalar::F64 => f64::from_le_bytes(self.take(s)?) as f32,
            _ => self.integer(s)? as f32,
        })
    }

    /// A value of integer type `s` (a float type is refused: indices are integers).
    fn integer(&mut self, s: Scalar) -> Result<i64, MeshError> {
        if let Body::Ascii(_) = self {
            let at = self.position();
            let w = self.word(s)?;
            return w.parse::<i64>().map_err(|_| self.bad_word(w, s, at));
        }
        Ok(match s {
            Scalar::I8 => i64::from(i8::from_le_bytes(self.take(s)?)),
            Scalar::U8 => i64::from(u8::from_le_bytes(self.take(s)?)),
            Scalar::I16 => i64::from(i16::from_le_bytes(self.take(s)?)),
            Scalar::U16 => i64::from(u16::from_le_bytes(self.take(s)?)),
            Scalar::I32 => i64::from(i32::from_le_bytes(self.take(s)?)),
            Scalar::U32 => i64::from(u32::from_le_bytes(self.take(s)?)),
            Scalar::F32 | Scalar::F64 => {
                return Err(self.error(
                    format!("a PLY list's length or index is a `{}`, not an integer", s.name()),
                    self.position(),
                    "declare list lengths and indices with integer types: `property list uchar int vertex_indices`",
                ));
            }
        })
    }

    fn bad_word(&self, w: &str, s: Scalar, at: Position) -> MeshError {
        let shown: String = w.chars().take(40).collect();
        self.error(
            format!("expected a PLY `{}` value, found `{shown}`", s.name()),
            at,
            "the body's values must follow the header's properties in order: fix or re-export the file",
        )
    }

    /// A list's length: at least 0, and no more items than the rest of the file can hold.
    fn count(&mut self, count: Scalar, item: Scalar) -> Result<u64, MeshError> {
        let at = self.position();
        let n = self.integer(count)?;
        let left = match self {
            Body::Ascii(w) => (w.bytes_left() / 2) as i64 + 1,
            Body::Binary { bytes, at, .. } => ((bytes.len() - *at) / item.size()) as i64,
        };
        if n < 0 || n > left {
            return Err(self.error(
                format!("a PLY list has length {n}, more than the rest of the file holds"),
                at,
                "the file is truncated or its lists' types in the header are wrong: re-export it",
            ));
        }
        Ok(n as u64)
    }

    /// Reads past one value of `kind`.
    fn skip(&mut self, kind: Kind) -> Result<(), MeshError> {
        match kind {
            Kind::Scalar(s) => self.float(s).map(drop),
            Kind::List(count, item) => {
                for _ in 0..self.count(count, item)? {
                    self.float(item)?;
                }
                Ok(())
            }
        }
    }
}
