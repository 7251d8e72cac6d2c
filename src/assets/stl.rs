//! STL files, binary and ASCII. Written here rather than through the `stl_io` crate: its
//! binary reader sizes its result from the 32-bit triangle count of the header before reading
//! a triangle (a 100-byte file claiming 4·10⁹ triangles asks for 200 GB and aborts the
//! process), and it reports no byte offsets or lines. Here the count is checked against the
//! file's length and the triangle budget first, and every error names where it is.
//!
//! STL repeats each corner in every triangle that uses it; identical positions (bit for bit)
//! are welded into one vertex, so smooth normals and the closedness CSG needs work as for OBJ.

use std::collections::HashMap;

use glam::Vec3;

use super::mesh_data::{Indexed, too_many_triangles};
use super::obj_error::MeshError;

/// Bytes of a binary STL header (80 free bytes, then the little-endian triangle count).
const HEADER: usize = 84;

/// Bytes of one binary STL triangle: normal, three corners (twelve f32) and a u16 attribute.
const RECORD: usize = 50;

/// The mesh in an STL file's bytes, at most `max_triangles` triangles. A file whose length is
/// what its header's count needs is binary (whatever its first word); one that starts with
/// `solid` is ASCII; anything else is a binary file of the wrong length.
pub(super) fn parse(bytes: &[u8], max_triangles: usize) -> Result<Indexed, MeshError> {
    let binary_count = bytes
        .get(80..HEADER)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]) as u64);
    let fits = |n: u64| {
        n.checked_mul(RECORD as u64).map(|b| b + HEADER as u64) == Some(bytes.len() as u64)
    };
    if let Some(n) = binary_count.filter(|&n| fits(n)) {
        return binary(bytes, n, max_triangles);
    }
    if bytes.trim_ascii_start().starts_with(b"solid") {
        return ascii(bytes, max_triangles);
    }
    match binary_count {
        Some(n) => Err(MeshError::at_byte(
            format!(
                "a binary STL file's header says {n} triangles ({} bytes), but the file has {} bytes",
                (n as u128) * RECORD as u128 + HEADER as u128,
                bytes.len()
            ),
            80,
            "the file is truncated or not STL: export it again (binary STL is 84 bytes of header and 50 per triangle)",
        )),
        None => Err(MeshError::at_byte(
            format!(
                "an STL file of {} bytes is too short for a header",
                bytes.len()
            ),
            0,
            "an ASCII STL file starts with `solid`; a binary one has an 84-byte header: export it again",
        )),
    }
}

/// Welds corners into shared vertices, in order of first use.
struct Welder {
    ids: HashMap<[u32; 3], u32>,
    mesh: Indexed,
}

impl Welder {
    fn new(triangles: usize) -> Welder {
        Welder {
            ids: HashMap::with_capacity(triangles),
            mesh: Indexed {
                triangles: Vec::with_capacity(triangles),
                ..Indexed::default()
            },
        }
    }

    fn vertex(&mut self, p: Vec3) -> u32 {
        let next = self.mesh.vertices.len() as u32;
        let id = *self
            .ids
            .entry(p.to_array().map(f32::to_bits))
            .or_insert(next);
        if id == next {
            self.mesh.vertices.push(p);
        }
        id
    }

    fn triangle(&mut self, corners: [Vec3; 3]) {
        let t = corners.map(|p| self.vertex(p));
        self.mesh.triangles.push(t);
    }
}

/// A binary file of `count` triangles (its length already checked).
fn binary(bytes: &[u8], count: u64, max_triangles: usize) -> Result<Indexed, MeshError> {
    if count > max_triangles as u64 {
        return Err(too_many_triangles(count, max_triangles));
    }
    let mut weld = Welder::new(count as usize);
    for record in bytes[HEADER..].chunks_exact(RECORD) {
        let f = |k: usize| {
            let b = &record[4 * k..4 * k + 4];
            f32::from_le_bytes([b[0], b[1], b[2], b[3]])
        };
        // Floats 0–2 are the facet normal, which rtc computes from the winding instead.
        let corner = |c: usize| Vec3::new(f(3 + 3 * c), f(4 + 3 * c), f(5 + 3 * c));
        weld.triangle([corner(0), corner(1), corner(2)]);
    }
    Ok(weld.mesh)
}

/// An ASCII file: `solid`, then `facet normal x y z`, `outer loop`, three `vertex x y z`,
/// `endloop`, `endfacet` per triangle, and `endsolid`. Keywords may be split over lines any
/// way; words are read in order and each error names its line.
fn ascii(bytes: &[u8], max_triangles: usize) -> Result<Indexed, MeshError> {
    let mut words = Words::new(bytes);
    let mut weld = Welder::new(0);
    // `solid` and its optional name: the rest of its line.
    words.expect(b"solid")?;
    words.skip_line();
    loop {
        let (word, line) = words.next_word().ok_or_else(|| {
            MeshError::at_line(
                "an ASCII STL file ends without `endsolid`",
                words.line,
                "the file is truncated: export it again",
            )
        })?;
        match word {
            b"endsolid" => return Ok(weld.mesh),
            b"facet" => {}
            other => return Err(unexpected(other, "`facet` or `endsolid`", line)),
        }
        words.expect(b"normal")?;
        for _ in 0..3 {
            words.number()?;
        }
        words.expect(b"outer")?;
        words.expect(b"loop")?;
        let mut corners = [Vec3::ZERO; 3];
        for c in &mut corners {
            words.expect(b"vertex")?;
            *c = Vec3::new(words.number()?, words.number()?, words.number()?);
        }
        words.expect(b"endloop")?;
        words.expect(b"endfacet")?;
        if weld.mesh.triangles.len() >= max_triangles {
            return Err(too_many_triangles(max_triangles as u64 + 1, max_triangles));
        }
        weld.triangle(corners);
    }
}

/// "expected ..., found ..." at `line`.
fn unexpected(found: &[u8], expected: &str, line: usize) -> MeshError {
    MeshError::at_line(
        format!(
            "expected {expected} in an ASCII STL file, found `{}`",
            String::from_utf8_lossy(&found[..found.len().min(40)])
        ),
        line,
        "each facet is `facet normal nx ny nz`, `outer loop`, three `vertex x y z`, `endloop`, `endfacet`; export the file again",
    )
}

/// Whitespace-separated words with their 1-based line numbers (ASCII STL and PLY).
pub(super) struct Words<'a> {
    bytes: &'a [u8],
    pub(super) at: usize,
    pub(super) line: usize,
}

impl<'a> Words<'a> {
    /// The words of `bytes` from its start.
    pub(super) fn new(bytes: &'a [u8]) -> Words<'a> {
        Words {
            bytes,
            at: 0,
            line: 1,
        }
    }

    /// The next word and its line, if any.
    pub(super) fn next_word(&mut self) -> Option<(&'a [u8], usize)> {
        while let Some(&b) = self.bytes.get(self.at) {
            if !b.is_ascii_whitespace() {
                break;
            }
            self.line += usize::from(b == b'\n');
            self.at += 1;
        }
        let start = self.at;
        while self
            .bytes
            .get(self.at)
            .is_some_and(|b| !b.is_ascii_whitespace())
        {
            self.at += 1;
        }
        (self.at > start).then(|| (&self.bytes[start..self.at], self.line))
    }

    /// Bytes not read yet.
    pub(super) fn bytes_left(&self) -> usize {
        self.bytes.len() - self.at
    }

    /// Skips to the start of the next line (a `solid` line's name).
    fn skip_line(&mut self) {
        match memchr::memchr(b'\n', &self.bytes[self.at..]) {
            Some(i) => {
                self.at += i + 1;
                self.line += 1;
            }
            None => self.at = self.bytes.len(),
        }
    }

    /// The keyword `want` (any case), or an error.
    fn expect(&mut self, want: &[u8]) -> Result<(), MeshError> {
        let what = format!("`{}`", String::from_utf8_lossy(want));
        match self.next_word() {
            Some((w, _)) if w.eq_ignore_ascii_case(want) => Ok(()),
            Some((w, line)) => Err(unexpected(w, &what, line)),
            None => Err(MeshError::at_line(
                format!("an ASCII STL file ends where {what} was expected"),
                self.line,
                "the file is truncated: export it again",
            )),
        }
    }

    /// A number, or an error.
    fn number(&mut self) -> Result<f32, MeshError> {
        match self.next_word() {
            Some((w, line)) => std::str::from_utf8(w)
                .ok()
                .and_then(|s| s.parse::<f32>().ok())
                .ok_or_else(|| unexpected(w, "a number", line)),
            None => Err(MeshError::at_line(
                "an ASCII STL file ends where a number was expected",
                self.line,
                "the file is truncated: export it again",
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TRI: &str = "solid t\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\n";

    #[test]
    fn ascii_triangles_weld_their_corners() {
        let two = format!(
            "{TRI}facet normal 0 0 1 outer loop vertex 1 0 0 vertex 1 1 0 vertex 0 1 0 endloop endfacet\nendsolid t\n"
        );
        let m = parse(two.as_bytes(), 10).unwrap();
        assert_eq!(m.vertices.len(), 4);
        assert_eq!(m.triangles, vec![[0, 1, 2], [1, 3, 2]]);
    }

    #[test]
    fn ascii_errors_name_their_line() {
        let e = parse(
            format!("{TRI}facet normal 0 0 1\nouter loop\nvertex 1 x 0\n").as_bytes(),
            10,
        )
        .unwrap_err();
        assert_eq!(e.line, Some(11), "{e:?}");
        assert!(e.message.contains("found `x`"), "{e:?}");
        let e = parse(TRI.as_bytes(), 10).unwrap_err();
        assert!(e.message.contains("without `endsolid`"), "{e:?}");
        let e = parse(format!("{TRI}{TRI}").as_bytes(), 10).unwrap_err();
        assert_eq!(e.line, Some(9), "a second `solid` is not a facet: {e:?}");
    }

    #[test]
    fn a_binary_count_must_match_the_length_and_the_budget() {
        let mut b = vec![0u8; HEADER + RECORD];
        b[80] = 1;
        assert_eq!(parse(&b, 10).unwrap().triangles.len(), 1);
        assert!(parse(&b, 0).unwrap_err().too_large);
        // A header claiming 4·10⁹ triangles is refused by its length, before any allocation.
        b[80..84].copy_from_slice(&u32::MAX.to_le_bytes());
        let e = parse(&b, 10).unwrap_err();
        assert_eq!(e.byte, Some(80));
        assert!(e.message.contains("4294967295 triangles"), "{e:?}");
        assert_eq!(parse(b"so", 10).unwrap_err().byte, Some(0));
    }
}
