//! A parallel reader for the common subset of OBJ: `v` (three numbers), `vt`, `vn`, `f` (three
//! or more corners, every index already defined: positive or relative), `o`, `g`, `s`,
//! `usemtl`, `mtllib`, comments and any line tobj ignores, in UTF-8 with LF or CRLF line ends.
//!
//! It gives the mesh tobj gives for such a file (the same corners, normals, texture
//! coordinates and materials per triangle; `assets::obj` builds the asset from either), and
//! `None` for anything else, which then goes through tobj with its diagnostics. tobj hashes
//! every corner on one thread (60% of the time to the first ray of a million triangles); here
//! chunks of lines are read on every core. The chunks depend only on the file's bytes and are
//! joined in file order, so the result is the same for any number of threads.
//!
//! The subset is what makes the two agree: tobj resolves a corner without a texture or normal
//! index to the previous corner's, checks indices only when a group ends, and divides by `w`;
//! files that would meet those rules are left to it.

use glam::{Vec2, Vec3};
use rayon::prelude::*;

/// A file read by [`read`]: every element in file order and the fan-triangulated faces.
#[derive(Debug, Default, PartialEq)]
pub struct ObjData {
    /// Every `v` line.
    pub(crate) positions: Vec<Vec3>,
    /// Every `vt` line (its first two numbers).
    pub(crate) texcoords: Vec<Vec2>,
    /// Every `vn` line.
    pub(crate) normals: Vec<Vec3>,
    /// Position indices of each triangle, faces in file order, each fanned from its first corner.
    pub(crate) triangles: Vec<[u32; 3]>,
    /// Texture coordinate indices per triangle (empty when the file has no `vt`).
    pub(crate) tex_of: Vec<[u32; 3]>,
    /// Normal indices per triangle (empty when the file has no `vn`).
    pub(crate) normal_of: Vec<[u32; 3]>,
    /// Material index per triangle (`None`: none or unknown); empty when the file has no `usemtl`.
    pub(crate) material_of: Vec<Option<usize>>,
    /// The material current at the end of the file (tobj's last, possibly empty, group has it).
    pub(crate) last_material: Option<usize>,
}

/// A material library line or a material choice, after `triangles` triangles of its chunk.
#[derive(Debug)]
enum Event<'a> {
    Library(&'a str),
    Use(&'a str),
}

/// Bytes per chunk of lines: large enough that a small file is one chunk, small enough that a
/// large one spreads over every core.
const CHUNK_BYTES: usize = 1 << 19;

/// Reads `text` if it lies in the subset; `library` loads an `mtllib` (as tobj's material
/// loader: called for every such line in order) and `use_material` maps a `usemtl` name to a
/// material index with the libraries loaded so far. `None`: leave the file to tobj.
pub(crate) fn read(
    text: &[u8],
    library: &mut dyn FnMut(&str),
    use_material: &mut dyn FnMut(&str) -> Option<usize>,
) -> Option<ObjData> {
    read_in_chunks(text, CHUNK_BYTES, library, use_material)
}

/// [`read`] with chunks of about `chunk` bytes (tests vary it: the result must not change).
pub fn read_in_chunks(
    text: &[u8],
    chunk: usize,
    library: &mut dyn FnMut(&str),
    use_material: &mut dyn FnMut(&str) -> Option<usize>,
) -> Option<ObjData> {
    let chunks = split_lines(text, chunk.max(1));
    // Pass 1: element counts per chunk, so every chunk knows how many of each come before it
    // (relative indices, the "already defined" rule) and where its elements go.
    let counts: Vec<[usize; 3]> = chunks
        .par_iter()
        .map(|c| count_elements(c))
        .collect::<Option<_>>()?;
    let mut base = vec![[0usize; 3]; chunks.len()];
    let mut total = [0usize; 3];
    for (b, c) in base.iter_mut().zip(&counts) {
        *b = total;
        for k in 0..3 {
            total[k] += c[k];
        }
    }
    if total[0] > u32::MAX as usize || total[1] > u32::MAX as usize || total[2] > u32::MAX as usize
    {
        return None;
    }
    let mut data = ObjData {
        positions: vec![Vec3::ZERO; total[0]],
        texcoords: vec![Vec2::ZERO; total[1]],
        normals: vec![Vec3::ZERO; total[2]],
        ..ObjData::default()
    };
    // Pass 2: each chunk writes its elements into its own slices and returns its faces.
    let mut work = Vec::with_capacity(chunks.len());
    let (mut p, mut t, mut n) = (
        &mut data.positions[..],
        &mut data.texcoords[..],
        &mut data.normals[..],
    );
    for (c, (b, k)) in chunks.iter().zip(base.iter().zip(&counts)) {
        let (p0, p1) = std::mem::take(&mut p).split_at_mut(k[0]);
        let (t0, t1) = std::mem::take(&mut t).split_at_mut(k[1]);
        let (n0, n1) = std::mem::take(&mut n).split_at_mut(k[2]);
        (p, t, n) = (p1, t1, n1);
        work.push((*c, *b, p0, t0, n0));
    }
    let parts: Vec<Faces<'_>> = work
        .into_par_iter()
        .map(|(c, b, p, t, n)| read_chunk(c, b, p, t, n))
        .collect::<Option<_>>()?;
    // A corner without a texture (normal) index is tobj's "previous corner's" rule unless the
    // file has none at all; a corner with one refers to a defined element (checked per line).
    let all =
        |f: fn(&Faces<'_>) -> Presence| parts.iter().map(f).fold(Presence::Unknown, Presence::join);
    let tex = all(|f| f.tex);
    let nrm = all(|f| f.nrm);
    if tex == Presence::Mixed || (tex != Presence::All && total[1] > 0) {
        return None;
    }
    if nrm == Presence::Mixed || (nrm != Presence::All && total[2] > 0) {
        return None;
    }
    let count: usize = parts.iter().map(|f| f.v.len()).sum();
    if count == 0 || count > u32::MAX as usize {
        return None;
    }
    // Materials in file order: libraries load and names resolve as tobj meets the lines.
    let mut material = None;
    let mut runs: Vec<(usize, Option<usize>)> = Vec::new();
    let mut before = 0;
    for f in &parts {
        for (at, e) in &f.events {
            match e {
                Event::Library(lib) => library(lib),
                Event::Use(name) => {
                    if name.is_empty() {
                        return None;
                    }
                    material = use_material(name);
                    runs.push((before + at, material));
                }
            }
        }
        before += f.v.len();
    }
    data.last_material = material;
    if !runs.is_empty() {
        data.material_of = vec![None; count];
        for (i, &(start, m)) in runs.iter().enumerate() {
            let end = runs.get(i + 1).map_or(count, |n| n.0);
            data.material_of[start..end].fill(m);
        }
    }
    data.triangles = join(&parts, |f| &f.v);
    if tex == Presence::All {
        data.tex_of = join(&parts, |f| &f.vt);
    }
    if nrm == Presence::All {
        data.normal_of = join(&parts, |f| &f.vn);
    }
    Some(data)
}

/// The chunks' `field`s end to end.
fn join<'p>(
    parts: &'p [Faces<'_>],
    field: impl Fn(&'p Faces<'_>) -> &'p [[u32; 3]],
) -> Vec<[u32; 3]> {
    let mut out = Vec::with_capacity(parts.iter().map(|f| field(f).len()).sum());
    for f in parts {
        out.extend_from_slice(field(f));
    }
    out
}

/// `text` cut after a line end about every `size` bytes (at least one chunk).
fn split_lines(text: &[u8], size: usize) -> Vec<&[u8]> {
    let mut out = Vec::with_capacity(text.len() / size + 1);
    let mut rest = text;
    while rest.len() > size {
        match memchr::memchr(b'\n', &rest[size..]) {
            Some(i) => {
                let (a, b) = rest.split_at(size + i + 1);
                out.push(a);
                rest = b;
            }
            None => break,
        }
    }
    out.push(rest);
    out
}

/// Whether the corners of some faces have a texture (normal) index.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Presence {
    /// No corner seen yet.
    Unknown,
    /// Every corner seen has one.
    All,
    /// No corner seen has one.
    None,
    /// Some have one and some not.
    Mixed,
}

impl Presence {
    fn join(self, other: Presence) -> Presence {
        match (self, other) {
            (Presence::Unknown, x) | (x, Presence::Unknown) => x,
            (a, b) if a == b => a,
            _ => Presence::Mixed,
        }
    }

    fn saw(&mut self, has: bool) {
        *self = self.join(if has { Presence::All } else { Presence::None });
    }
}

/// One chunk's faces and events.
struct Faces<'a> {
    v: Vec<[u32; 3]>,
    vt: Vec<[u32; 3]>,
    vn: Vec<[u32; 3]>,
    tex: Presence,
    nrm: Presence,
    events: Vec<(usize, Event<'a>)>,
}

/// The lines of a chunk as tobj reads them (`BufRead::lines`: split at LF; a CR before it
/// is whitespace to every use below). `None` when the chunk is not UTF-8 (tobj fails there).
fn lines(chunk: &[u8]) -> Option<impl Iterator<Item = &[u8]>> {
    std::str::from_utf8(chunk).ok()?;
    let mut rest = chunk;
    Some(std::iter::from_fn(move || {
        if rest.is_empty() {
            return None;
        }
        let (line, next) = match memchr::memchr(b'\n', rest) {
            Some(i) => (&rest[..i], &rest[i + 1..]),
            None => (rest, &rest[rest.len()..]),
        };
        rest = next;
        Some(line)
    }))
}

/// Whitespace as `str::split_whitespace` sees it, for ASCII bytes.
fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | b'\r' | 0x0b | 0x0c)
}

/// The words of an ASCII line, split as `str::split_whitespace` splits them.
struct Words<'a>(&'a [u8]);

impl<'a> Iterator for Words<'a> {
    type Item = &'a [u8];
    fn next(&mut self) -> Option<&'a [u8]> {
        let start = self.0.iter().position(|&b| !is_space(b))?;
        let rest = &self.0[start..];
        let end = rest.iter().position(|&b| is_space(b)).unwrap_or(rest.len());
        self.0 = &rest[end..];
        Some(&rest[..end])
    }
}

/// Calls `f` with the words of `line` (UTF-8; ASCII lines take the byte path).
fn with_words<R>(line: &[u8], f: impl FnOnce(&mut dyn Iterator<Item = &[u8]>) -> R) -> R {
    if line.is_ascii() {
        f(&mut Words(line))
    } else {
        // The chunk is UTF-8, so its lines are.
        let s = std::str::from_utf8(line).unwrap_or_default();
        f(&mut s.split_whitespace().map(str::as_bytes))
    }
}

/// The `v`, `vt` and `vn` lines of a chunk.
fn count_elements(chunk: &[u8]) -> Option<[usize; 3]> {
    let mut n = [0usize; 3];
    for line in lines(chunk)? {
        match with_words(line, |w| w.next().and_then(element_kind)) {
            Some(k) => n[k] += 1,
            None => continue,
        }
    }
    Some(n)
}

/// 0, 1, 2 for `v`, `vt`, `vn`.
fn element_kind(word: &[u8]) -> Option<usize> {
    match word {
        b"v" => Some(0),
        b"vt" => Some(1),
        b"vn" => Some(2),
        _ => None,
    }
}

/// Parses a chunk whose elements start at `base` and fill `pos`, `tex`, `nrm`.
fn read_chunk<'a>(
    chunk: &'a [u8],
    base: [usize; 3],
    pos: &mut [Vec3],
    tex: &mut [Vec2],
    nrm: &mut [Vec3],
) -> Option<Faces<'a>> {
    let mut faces = Faces {
        v: Vec::with_capacity(chunk.len() / 40),
        vt: Vec::new(),
        vn: Vec::new(),
        tex: Presence::Unknown,
        nrm: Presence::Unknown,
        events: Vec::new(),
    };
    let mut seen = [0usize; 3];
    let mut corners: Vec<[u32; 3]> = Vec::new();
    for line in lines(chunk)? {
        let ok = with_words(line, |words| {
            let Some(key) = words.next() else {
                return Some(());
            };
            match key {
                b"v" => {
                    let [x, y, z] = floats::<3>(words)?;
                    // `w` or vertex colours: tobj's rules, left to it.
                    if words.next().is_some() {
                        return None;
                    }
                    *pos.get_mut(seen[0])? = Vec3::new(x, y, z);
                    seen[0] += 1;
                }
                b"vt" => {
                    let [u, v] = floats::<2>(words)?;
                    *tex.get_mut(seen[1])? = Vec2::new(u, v);
                    seen[1] += 1;
                }
                b"vn" => {
                    let [x, y, z] = floats::<3>(words)?;
                    *nrm.get_mut(seen[2])? = Vec3::new(x, y, z);
                    seen[2] += 1;
                }
                b"f" => {
                    let defined = [0, 1, 2].map(|k| base[k] + seen[k]);
                    corners.clear();
                    for w in words {
                        corners.push(corner(w, defined)?);
                    }
                    if corners.len() < 3 {
                        return None;
                    }
                    let has = |k: usize| corners[0][k] != u32::MAX;
                    for k in [1, 2] {
                        if corners.iter().any(|c| (c[k] != u32::MAX) != has(k)) {
                            return None;
                        }
                    }
                    faces.tex.saw(has(1));
                    faces.nrm.saw(has(2));
                    for i in 1..corners.len() - 1 {
                        let tri = [corners[0], corners[i], corners[i + 1]];
                        faces.v.push(tri.map(|c| c[0]));
                        if has(1) {
                            faces.vt.push(tri.map(|c| c[1]));
                        }
                        if has(2) {
                            faces.vn.push(tri.map(|c| c[2]));
                        }
                    }
                }
                // Lines (and points) become degenerate triangles with tobj's index rules.
                b"l" => return None,
                b"mtllib" | b"usemtl" => {
                    // tobj's own reading of the name: after the first space, trimmed.
                    let s = std::str::from_utf8(line).ok()?;
                    let name = s.split_once(' ').unwrap_or_default().1.trim();
                    let e = if key == b"mtllib" {
                        Event::Library(name)
                    } else {
                        Event::Use(name)
                    };
                    faces.events.push((faces.v.len(), e));
                }
                _ => {}
            }
            Some(())
        });
        ok?;
    }
    Some(faces)
}

/// The first `N` words as f32 (tobj's `parse_floatn`: Rust's own parsing, extra words unread).
fn floats<const N: usize>(words: &mut dyn Iterator<Item = &[u8]>) -> Option<[f32; N]> {
    let mut out = [0f32; N];
    for x in &mut out {
        *x = std::str::from_utf8(words.next()?).ok()?.parse().ok()?;
    }
    Some(out)
}

/// A face corner `v`, `v/t`, `v//n` or `v/t/n` as 0-based indices (`u32::MAX`: absent), each
/// below `defined` (the elements so far); `None` for anything else (tobj's errors, index 0).
fn corner(word: &[u8], defined: [usize; 3]) -> Option<[u32; 3]> {
    let mut out = [u32::MAX; 3];
    let mut parts = word.split(|&b| b == b'/');
    for (k, slot) in out.iter_mut().enumerate() {
        let Some(part) = parts.next() else { break };
        if part.is_empty() {
            if k == 0 {
                return None;
            }
            continue;
        }
        let i = super::obj_file::integer(part)?;
        let n = defined[k] as i64;
        let at = if i < 0 { n + i } else { i - 1 };
        if i == 0 || at < 0 || at >= n {
            return None;
        }
        *slot = at as u32;
    }
    if parts.next().is_some() {
        return None;
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plain(text: &str) -> Option<ObjData> {
        read_in_chunks(text.as_bytes(), 8, &mut |_| {}, &mut |_| None)
    }

    #[test]
    fn corners_resolve_positive_and_relative_indices() {
        assert_eq!(corner(b"2", [3, 0, 0]), Some([1, u32::MAX, u32::MAX]));
        assert_eq!(corner(b"-1/-2/+1", [3, 2, 1]), Some([2, 0, 0]));
        assert_eq!(corner(b"1//1", [1, 0, 1]), Some([0, u32::MAX, 0]));
        // Not yet defined, zero, too many parts, no position, not a number.
        for bad in ["4", "-4", "0", "1/1/1/1", "/1", "1/x", "1.0", "+", ""] {
            assert_eq!(corner(bad.as_bytes(), [3, 3, 3]), None, "{bad}");
        }
    }

    #[test]
    fn faces_fan_from_their_first_corner_across_chunks() {
        let d = plain("v 0 0 0\r\nv 1 0 0\nv 1 1 0\n# c\nv 0 1 0\nf 1 2 3 4\nf -4 -3 -1\n")
            .expect("in the subset");
        assert_eq!(d.positions.len(), 4);
        assert_eq!(d.positions[2], Vec3::new(1.0, 1.0, 0.0));
        assert_eq!(d.triangles, vec![[0, 1, 2], [0, 2, 3], [0, 1, 3]]);
        assert!(d.tex_of.is_empty() && d.normal_of.is_empty() && d.material_of.is_empty());
    }

    #[test]
    fn files_outside_the_subset_are_left_to_tobj() {
        let tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
        for tail in [
            "f 1 2 4\nv 1 1 1\n",        // a forward reference
            "f 1 2\n",                   // a line as a face
            "l 1 2\n",                   // a line
            "vt 0 0\nf 1 2 3\n",         // texture coordinates but a corner without one
            "vn 0 0 1\nf 1//1 2 3//1\n", // mixed normals
            "v 1 2 3 4\nf 1 2 3\n",      // a w coordinate
            "f 1 2 3\nusemtl\n",         // a material without a name
            "",                          // no faces
        ] {
            assert_eq!(plain(&format!("{tri}{tail}")), None, "{tail:?}");
        }
        let unicode = plain("# \u{e9}\nv 0 0 0\nv\u{3000}1 0 0\nv 0 1 0\nf 1 2 3\n");
        assert_eq!(unicode.map(|d| d.positions[1]), Some(Vec3::X));
        let bad_utf8 = read(
            b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n#\xff\n",
            &mut |_| {},
            &mut |_| None,
        );
        assert_eq!(bad_utf8, None);
    }
}
