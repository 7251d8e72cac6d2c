//! Reading an OBJ file and its material libraries through tobj. rtc checks both before tobj
//! parses them, for input on which tobj 4.0.5 panics (both found by fuzzing, `fuzz/`):
//! - a material colour line with fewer than three numbers (`Kd 1 0`: `parse_float3` unwraps);
//! - a face's texture or normal index beyond the file's size, or relative to before the first
//!   element (`f 1//6148914691236517207 ...`, `f 1/-4 ...` after three `vt`): tobj's index
//!   arithmetic overflows (a panic with overflow checks, silently wrong normals without).

use std::cell::RefCell;
use std::collections::HashMap;
use std::path::{Path, PathBuf};

use tobj::{LoadError, LoadOptions, Model};

/// Bytes of one MTL material library, checked before reading (docs/language.md §24).
const MAX_MTL_BYTES: u64 = 64 << 20;

/// The materials of an OBJ file, or why its material library could not be used.
pub(crate) type Materials = Result<Vec<tobj::Material>, String>;

/// The models in the OBJ file's bytes `text` and its materials (`mtllib` paths are relative to
/// the file), its libraries loaded through `libs` (made for the same file), which lists them
/// afterwards.
pub(crate) fn read_text(
    libs: &Libraries,
    text: &[u8],
    opts: &LoadOptions,
) -> Result<(Vec<Model>, Materials), LoadError> {
    if let Some(e) = bad_face_index(text) {
        return Err(e);
    }
    let (models, materials) = tobj::load_obj_buf(&mut &text[..], opts, |lib| libs.load(lib))?;
    Ok((models, libs.finish(materials)))
}

/// Where the library an `mtllib` line names is read from: relative to the OBJ file's folder.
fn library_path(obj: &Path, lib: &Path) -> PathBuf {
    obj.parent()
        .map_or_else(|| lib.to_path_buf(), |dir| dir.join(lib))
}

/// The material libraries the OBJ file `obj` (its bytes `text`) names, by tobj's reading of an
/// `mtllib` line (the line's first word; the name is the rest after the first space, trimmed,
/// so it may hold spaces), without parsing anything else: what a loaded mesh reads besides
/// its own file (the fingerprint of shards, `rtc watch`).
pub(crate) fn library_paths(obj: &Path, text: &[u8]) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = Vec::new();
    for line in text.split(|&b| b == b'\n') {
        let line = line.strip_suffix(b"\r").unwrap_or(line);
        // Cheap test first: most lines of a large file are vertices and faces.
        if !line.trim_ascii_start().starts_with(b"mtllib") {
            continue;
        }
        let Ok(line) = std::str::from_utf8(line) else {
            continue;
        };
        if line.split_whitespace().next() != Some("mtllib") {
            continue;
        }
        let name = line.split_once(' ').unwrap_or_default().1.trim();
        let path = library_path(obj, Path::new(name));
        if !out.contains(&path) {
            out.push(path);
        }
    }
    out
}

/// The material libraries of one OBJ file, loaded as tobj loads them (its loader callback and
/// its merging, for the parallel reader of `obj_fast`, which meets the same lines in order).
pub(crate) struct Libraries<'a> {
    obj: &'a Path,
    /// The first library with a colour line tobj would panic on.
    problem: RefCell<Option<String>>,
    /// Every library asked for (read or not), once each, in order.
    files: RefCell<Vec<PathBuf>>,
    /// Materials merged so far, their names, and the last library's error (tobj's rules).
    merged: Vec<tobj::Material>,
    names: HashMap<String, usize>,
    error: Option<LoadError>,
}

impl<'a> Libraries<'a> {
    /// No libraries yet, for the OBJ file `obj`.
    pub(crate) fn new(obj: &'a Path) -> Libraries<'a> {
        Libraries {
            obj,
            problem: RefCell::new(None),
            files: RefCell::new(Vec::new()),
            merged: Vec::new(),
            names: HashMap::new(),
            error: None,
        }
    }

    /// Reads the library `lib` (relative to the OBJ file) as tobj's material loader.
    fn load(&self, lib: &Path) -> tobj::MTLLoadResult {
        let full = library_path(self.obj, lib);
        {
            let mut files = self.files.borrow_mut();
            if !files.contains(&full) {
                files.push(full.clone());
            }
        }
        // Only a regular file within the budget of §24: `mtllib /dev/zero` would read for ever.
        let text = crate::source::read_regular(&full, MAX_MTL_BYTES)
            .map_err(|_| LoadError::OpenFileFailed)?;
        if let Some(what) = short_colour_line(&text) {
            self.problem
                .borrow_mut()
                .get_or_insert_with(|| format!("`{}` {what}", lib.display()));
            return Err(LoadError::MaterialParseError);
        }
        tobj::load_mtl_buf(&mut text.as_slice())
    }

    /// Loads and merges the library an `mtllib` line names (tobj's `TmpMaterials::merge`).
    pub(crate) fn add(&mut self, lib: &str) {
        match self.load(Path::new(lib)) {
            Ok((mut mats, map)) => {
                let offset = self.merged.len();
                self.merged.append(&mut mats);
                for (name, i) in map {
                    self.names.insert(name, i + offset);
                }
            }
            Err(e) => self.error = Some(e),
        }
    }

    /// The libraries asked for so far (read or not: one that appears later changes the mesh).
    pub(crate) fn files(&self) -> Vec<PathBuf> {
        self.files.borrow().clone()
    }

    /// The index a `usemtl` line's name selects, among the libraries merged so far.
    pub(crate) fn find(&self, name: &str) -> Option<usize> {
        self.names.get(name).copied()
    }

    /// The merged materials as tobj returns them (any material, else the last error).
    pub(crate) fn merged(&mut self) -> Materials {
        let merged = std::mem::take(&mut self.merged);
        let result = match self.error.take() {
            Some(e) if merged.is_empty() => Err(e),
            _ => Ok(merged),
        };
        self.finish(result)
    }

    /// tobj's materials result, its error told as the problem found, if any.
    fn finish(&self, materials: Result<Vec<tobj::Material>, LoadError>) -> Materials {
        materials.map_err(|e| match self.problem.take() {
            Some(p) => p,
            None => e.to_string(),
        })
    }
}

/// The error tobj should give for the first face or line element whose index its arithmetic
/// cannot hold: larger than the file has bytes (so larger than any element count), or relative
/// (negative) to before the first element defined so far. (tobj reads 0 as "no index".) Like tobj it reads the lines
/// before the first byte that is not UTF-8, and splits words as `str::split_whitespace`.
/// (`obj_error::locate` then finds the line.) Bytes, not `str`: this scan costs ~2% of a load.
fn bad_face_index(text: &[u8]) -> Option<LoadError> {
    let text = match std::str::from_utf8(text) {
        Ok(_) => text,
        Err(e) => {
            let head = &text[..e.valid_up_to()];
            &head[..head.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1)]
        }
    };
    let mut scan = FaceScan {
        limit: text.len() as u64,
        counts: [0; 3],
    };
    for line in text.split(|&b| b == b'\n') {
        let bad = if line.is_ascii() {
            let is_space = |b: &u8| matches!(b, b' ' | b'\t' | b'\r' | 0x0b | 0x0c);
            scan.line(line.split(is_space).filter(|w| !w.is_empty()))
        } else {
            let line = std::str::from_utf8(line).ok()?;
            scan.line(line.split_whitespace().map(str::as_bytes))
        };
        if bad.is_some() {
            return bad;
        }
    }
    None
}

/// Element counts so far, for [`bad_face_index`].
struct FaceScan {
    limit: u64,
    /// `v`, `vt` and `vn` lines so far.
    counts: [u64; 3],
}

impl FaceScan {
    fn line<'a>(&mut self, mut words: impl Iterator<Item = &'a [u8]>) -> Option<LoadError> {
        match words.next()? {
            b"v" => self.counts[0] += 1,
            b"vt" => self.counts[1] += 1,
            b"vn" => self.counts[2] += 1,
            b"f" | b"l" => {
                for corner in words {
                    for (k, part) in corner.split(|&b| b == b'/').take(3).enumerate() {
                        let Some(i) = integer(part) else { continue };
                        let size = i.unsigned_abs();
                        if size > self.limit || (i < 0 && size > self.counts[k]) {
                            return Some(match k {
                                0 => LoadError::FaceVertexOutOfBounds,
                                1 => LoadError::FaceTexCoordOutOfBounds,
                                _ => LoadError::FaceNormalOutOfBounds,
                            });
                        }
                    }
                }
            }
            _ => {}
        }
        None
    }
}

/// `s` as tobj reads an index (`isize::from_str`: an optional sign and digits), if it is one.
pub(super) fn integer(s: &[u8]) -> Option<i64> {
    let (negative, digits) = match s {
        [b'-', d @ ..] => (true, d),
        [b'+', d @ ..] => (false, d),
        d => (false, d),
    };
    if digits.is_empty() {
        return None;
    }
    let mut v: i64 = 0;
    for &c in digits {
        if !c.is_ascii_digit() {
            return None;
        }
        v = v.checked_mul(10)?.checked_add(i64::from(c - b'0'))?;
    }
    Some(if negative { -v } else { v })
}

/// "line N: `Kd` needs three numbers (r g b)" for the first colour line that has fewer, among
/// the lines tobj reads: it stops at the first line that is not UTF-8.
fn short_colour_line(text: &[u8]) -> Option<String> {
    for (i, line) in text.split(|&b| b == b'\n').enumerate() {
        let line = std::str::from_utf8(line).ok()?;
        let mut words = line.split_whitespace();
        let Some(key) = words.next() else { continue };
        if matches!(key, "Ka" | "Kd" | "Ks" | "Ke") && words.count() < 3 {
            return Some(format!(
                "line {}: `{key}` needs three numbers (r g b)",
                i + 1
            ));
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use tobj::LoadError;

    /// The libraries a file names are the ones its loader reads: the rest of the `mtllib`
    /// line, spaces and all (`rtc watch` cut such a name at the space and watched neither part).
    #[test]
    fn library_paths_are_read_as_the_loader_reads_them() {
        let obj = Path::new("models/m.obj");
        let text = b"# mtllib not.mtl\nmtllib my colours.mtl\r\nmtllibx no.mtl\n  mtllib b.mtl \nv 0 0 0\nmtllib b.mtl\n";
        assert_eq!(
            library_paths(obj, text),
            vec![
                PathBuf::from("models/my colours.mtl"),
                // tobj names an indented line's library by all after its first space, keyword
                // and all: that (missing) file is what the loader asks for, so it is watched.
                PathBuf::from("models/mtllib b.mtl"),
                PathBuf::from("models/b.mtl")
            ]
        );
        // What the loader asked for, through tobj, is the same list.
        let libs = Libraries::new(obj);
        let _ = read_text(&libs, text, &LoadOptions::default());
        assert_eq!(libs.files(), library_paths(obj, text));
    }

    #[test]
    fn face_indices_tobj_cannot_hold_are_found() {
        let tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n";
        let bad = |faces: &str| bad_face_index(format!("{tri}{faces}").as_bytes());
        assert_eq!(bad("f 1 2 3\nf -1 -2 -3\nf 1//1 2 3\nf 0 1//0 2\n"), None);
        assert_eq!(bad("f -4 -2 -1\n"), Some(LoadError::FaceVertexOutOfBounds));
        assert_eq!(
            bad("f 1 2 6148914691236517206\n"),
            Some(LoadError::FaceVertexOutOfBounds)
        );
        assert_eq!(
            bad("f 1/-1 2 3\n"),
            Some(LoadError::FaceTexCoordOutOfBounds)
        );
        assert_eq!(bad("l 1//-2 2\n"), Some(LoadError::FaceNormalOutOfBounds));
        // Words split as tobj splits them (vertical tab and Unicode spaces included), and
        // nothing after a line that is not UTF-8, where tobj stops.
        assert_eq!(bad("f\x0b-9 1 2\n"), Some(LoadError::FaceVertexOutOfBounds));
        assert_eq!(
            bad("f 1\u{3000}-9 2\n"),
            Some(LoadError::FaceVertexOutOfBounds)
        );
        assert_eq!(bad_face_index(b"v 0 0 0\n\xff\nf -9 1 1\n"), None);
        assert_eq!(integer(b"+12"), Some(12));
        assert_eq!(integer(b"99999999999999999999"), None);
    }

    #[test]
    fn short_colour_lines_are_found_with_their_number() {
        let text = b"newmtl a\nKd 1 0 0\n  Ks 0.5\nKa\n";
        assert_eq!(
            short_colour_line(text).as_deref(),
            Some("line 3: `Ks` needs three numbers (r g b)")
        );
        assert_eq!(short_colour_line(b"newmtl a\nKd 1 0 0 # red\nNs 8\n"), None);
        // tobj parses the lines before one that is not UTF-8 (found by the obj_mtl fuzzer).
        assert_eq!(
            short_colour_line(b"Ks 0.5\r\nK\xff\n").as_deref(),
            Some("line 1: `Ks` needs three numbers (r g b)")
        );
        assert_eq!(short_colour_line(b"K\xff\nKs 0.5\n"), None);
    }
}
