//! Reading an OBJ file and its material libraries through tobj. rtc reads the libraries itself
//! and checks them first, because tobj 4.0.5 panics on a colour line with fewer than three
//! numbers (`Kd 1 0`: its `parse_float3` unwraps); such a line is reported with its number.

use std::cell::RefCell;
use std::fs::File;
use std::io::BufReader;
use std::path::Path;

use tobj::{LoadError, LoadOptions, Model};

/// The materials of an OBJ file, or why its material library could not be used.
pub type Materials = Result<Vec<tobj::Material>, String>;

/// The models in the OBJ file at `path` and its materials (`mtllib` paths are relative to it).
pub fn read(path: &Path, opts: &LoadOptions) -> Result<(Vec<Model>, Materials), LoadError> {
    let file = File::open(path).map_err(|_| LoadError::OpenFileFailed)?;
    let problem: RefCell<Option<String>> = RefCell::new(None);
    let (models, materials) = tobj::load_obj_buf(&mut BufReader::new(file), opts, |lib| {
        let full = path
            .parent()
            .map_or_else(|| lib.to_path_buf(), |dir| dir.join(lib));
        let text = std::fs::read(&full).map_err(|_| LoadError::OpenFileFailed)?;
        if let Some(what) = short_colour_line(&text) {
            problem
                .borrow_mut()
                .get_or_insert_with(|| format!("`{}` {what}", lib.display()));
            return Err(LoadError::MaterialParseError);
        }
        tobj::load_mtl_buf(&mut text.as_slice())
    })?;
    let materials = materials.map_err(|e| match problem.take() {
        Some(p) => p,
        None => e.to_string(),
    });
    Ok((models, materials))
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
    use super::short_colour_line;

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
