//! Source files and spans: every IR node and diagnostic points back into a file through a `Span`.

use std::path::{Path, PathBuf};
use std::sync::{Arc, OnceLock};

/// Index of a file in a [`SourceMap`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct FileId(pub u32);

/// A byte range in one source file: 12 bytes, `Copy`, carried by every AST node and IR item.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Span {
    /// The file the range belongs to.
    pub file: FileId,
    /// Byte offset of the first byte.
    pub start: u32,
    /// Byte offset one past the last byte.
    pub end: u32,
}

impl Span {
    /// A span over `start..end` in `file`.
    pub fn new(file: FileId, start: usize, end: usize) -> Span {
        Span {
            file,
            start: start as u32,
            end: end.max(start) as u32,
        }
    }

    /// The smallest span covering both `self` and `other` (same file assumed).
    pub(crate) fn join(self, other: Span) -> Span {
        Span {
            file: self.file,
            start: self.start.min(other.start),
            end: self.end.max(other.end),
        }
    }

    /// Length in bytes.
    pub fn len(self) -> usize {
        (self.end - self.start) as usize
    }

    /// True for an empty range (the pair of `len`, as clippy asks of a public `len`).
    pub fn is_empty(self) -> bool {
        self.end == self.start
    }
}

/// One loaded source text with its path (as given, for messages) and line starts.
#[derive(Clone, Debug)]
pub struct SourceFile {
    /// The path as the user wrote it or as it was resolved (shown in messages).
    pub path: PathBuf,
    /// The whole text, shared: the evaluator parses from it while the map takes more files,
    /// and a generated scene's megabytes are not copied for that.
    pub text: Arc<String>,
    /// Where each line starts, found when a position is first asked for (only diagnostics
    /// ask: a file that evaluates cleanly is never indexed).
    line_starts: OnceLock<Vec<usize>>,
}

impl SourceFile {
    /// Wraps a text.
    fn new(path: PathBuf, text: String) -> SourceFile {
        SourceFile {
            path,
            text: Arc::new(text),
            line_starts: OnceLock::new(),
        }
    }

    fn line_starts(&self) -> &[usize] {
        self.line_starts.get_or_init(|| {
            let mut starts = vec![0];
            starts.extend(memchr::memchr_iter(b'\n', self.text.as_bytes()).map(|i| i + 1));
            starts
        })
    }

    /// 1-based (line, column) of a byte offset; the column counts characters, not bytes.
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let offset = offset.min(self.text.len());
        let starts = self.line_starts();
        let line = starts.partition_point(|&s| s <= offset) - 1;
        let start = starts[line];
        let col = self
            .text
            .get(start..offset)
            .map_or(offset - start, |s| s.chars().count());
        (line + 1, col + 1)
    }

    /// Byte offset of a 1-based (line, column) position, clamped to the text (the tests').
    #[cfg(test)]
    fn offset_of(&self, line: usize, col: usize) -> usize {
        let Some(&start) = self.line_starts().get(line.saturating_sub(1)) else {
            return self.text.len();
        };
        let rest = &self.text[start..];
        rest.char_indices()
            .nth(col.saturating_sub(1))
            .map_or(self.text.len(), |(i, _)| start + i)
    }
}

/// All files read during one run; spans index into it.
#[derive(Clone, Debug, Default)]
pub struct SourceMap {
    files: Vec<SourceFile>,
}

impl SourceMap {
    /// An empty map.
    pub fn new() -> SourceMap {
        SourceMap::default()
    }

    /// Adds a file and returns its id.
    pub fn add(&mut self, path: impl Into<PathBuf>, text: impl Into<String>) -> FileId {
        self.files.push(SourceFile::new(path.into(), text.into()));
        FileId((self.files.len() - 1) as u32)
    }

    /// The file behind an id.
    pub fn get(&self, id: FileId) -> &SourceFile {
        &self.files[id.0 as usize]
    }

    /// The id of an already loaded path, if any.
    pub(crate) fn find(&self, path: &Path) -> Option<FileId> {
        self.files
            .iter()
            .position(|f| f.path == path)
            .map(|i| FileId(i as u32))
    }

    /// The text a span covers.
    pub fn snippet(&self, span: Span) -> &str {
        let text = &self.get(span.file).text;
        text.get(span.start as usize..span.end as usize)
            .unwrap_or("")
    }

    /// A copy of the map as it was when it held its first `count` files (the texts are shared).
    pub(crate) fn prefix(&self, count: usize) -> SourceMap {
        SourceMap {
            files: self.files[..count.min(self.files.len())].to_vec(),
        }
    }

    /// Every file, in the order it was added.
    pub fn files(&self) -> &[SourceFile] {
        &self.files
    }
}

/// Files from this size on are read in two halves at once.
const PARALLEL_READ_BYTES: u64 = 1 << 20;

/// Bytes of one source file (a scene, an imported module, a course `.in` or `.yaml` file),
/// checked before reading (docs/language.md §24). The literal million-sphere scene is 85 MB.
pub const MAX_SOURCE_BYTES: u64 = 1 << 30;

/// Opens `path` for reading if it is a regular file of at most `max` bytes. A device
/// (`/dev/zero`), a FIFO (which would block until a writer came), a socket or a folder is
/// refused from its metadata before it is opened, and a file above `max` from its size; the
/// errors say which (`ErrorKind::InvalidInput`, `ErrorKind::FileTooLarge`).
pub(crate) fn open_regular(path: &Path, max: u64) -> std::io::Result<(std::fs::File, u64)> {
    let kind = |meta: &std::fs::Metadata| -> std::io::Result<u64> {
        if !meta.is_file() {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidInput,
                format!("{} is not a regular file", file_kind(meta)),
            ));
        }
        if meta.len() > max {
            return Err(std::io::Error::new(
                std::io::ErrorKind::FileTooLarge,
                format!(
                    "the file has {} bytes, more than the {max} a file may have",
                    meta.len()
                ),
            ));
        }
        Ok(meta.len())
    };
    kind(&std::fs::metadata(path)?)?;
    let file = std::fs::File::open(path)?;
    // What was opened, in case the name was replaced between the two looks.
    let len = kind(&file.metadata()?)?;
    Ok((file, len))
}

/// What a file that is not a regular one is, for messages.
fn file_kind(meta: &std::fs::Metadata) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        let t = meta.file_type();
        if t.is_fifo() {
            return "a FIFO (named pipe)";
        }
        if t.is_char_device() || t.is_block_device() {
            return "a device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if meta.is_dir() {
        "a folder"
    } else {
        "a special file"
    }
}

/// Reads a whole regular file of at most `max` bytes ([`open_regular`]); a file that grows while
/// it is read stops at `max + 1` bytes and is refused.
pub fn read_regular(path: &Path, max: u64) -> std::io::Result<Vec<u8>> {
    use std::io::Read;
    let (file, len) = open_regular(path, max)?;
    let mut buf = Vec::with_capacity(usize::try_from(len).unwrap_or(0));
    file.take(max.saturating_add(1)).read_to_end(&mut buf)?;
    if buf.len() as u64 > max {
        return Err(std::io::Error::new(
            std::io::ErrorKind::FileTooLarge,
            format!("the file grew above the {max} bytes a file may have"),
        ));
    }
    Ok(buf)
}

/// Reads a whole source file, like `std::fs::read`, if it is a regular file of at most
/// [`MAX_SOURCE_BYTES`] ([`open_regular`]). A large one (a generated scene of megabytes) is
/// read in two halves at once, so the kernel's copy into the new buffer, and the page faults it
/// takes, run on two cores.
pub fn read_file(path: &Path) -> std::io::Result<Vec<u8>> {
    #[cfg(unix)]
    {
        use std::io::{Read, Seek, SeekFrom};
        use std::os::unix::fs::FileExt;
        let (mut file, len) = open_regular(path, MAX_SOURCE_BYTES)?;
        if len >= PARALLEL_READ_BYTES
            && let Ok(size) = usize::try_from(len)
        {
            // Zeroed by the allocator's fresh pages, not by a pass over the buffer.
            let mut buf = vec![0u8; size];
            let (front, back) = buf.split_at_mut(size / 2);
            let (a, b) = rayon::join(
                || file.read_exact_at(front, 0),
                || file.read_exact_at(back, (size / 2) as u64),
            );
            // A file that shrank meanwhile is read again as a whole; one that grew gets its
            // tail read too, as `std::fs::read` would have read it.
            if a.is_ok() && b.is_ok() {
                file.seek(SeekFrom::Start(len))?;
                file.take(MAX_SOURCE_BYTES - len + 1)
                    .read_to_end(&mut buf)?;
                if buf.len() as u64 <= MAX_SOURCE_BYTES {
                    return Ok(buf);
                }
            }
        }
    }
    read_regular(path, MAX_SOURCE_BYTES)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_col_counts_from_one_and_by_chars() {
        let f = SourceFile::new("a".into(), "ab\nc°d\n".into());
        assert_eq!(f.line_col(0), (1, 1));
        assert_eq!(f.line_col(3), (2, 1));
        // "°" is two bytes; the byte after it is column 3.
        assert_eq!(f.line_col(6), (2, 3));
        assert_eq!(f.offset_of(2, 3), 6);
    }

    /// A large file (read in two halves at once) and a small one read as `std::fs::read` reads
    /// them.
    #[test]
    fn files_read_in_halves_are_read_whole() {
        let dir = std::env::temp_dir().join(format!("rtc-read-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        for len in [0, 10, (3 << 20) + 7] {
            let bytes: Vec<u8> = (0..len).map(|i: usize| (i * 31 % 251) as u8).collect();
            let path = dir.join(format!("f{len}"));
            std::fs::write(&path, &bytes).unwrap();
            assert_eq!(super::read_file(&path).unwrap(), bytes, "{len} bytes");
        }
        assert!(super::read_file(&dir.join("absent")).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn only_regular_files_within_the_budget_are_read() {
        let dir = std::env::temp_dir().join(format!("rtc-regular-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("ten");
        std::fs::write(&file, b"0123456789").unwrap();
        assert_eq!(super::read_regular(&file, 10).unwrap(), b"0123456789");
        let big = super::read_regular(&file, 9).unwrap_err();
        assert_eq!(big.kind(), std::io::ErrorKind::FileTooLarge, "{big}");
        let folder = super::read_regular(&dir, 1 << 20).unwrap_err();
        assert!(folder.to_string().contains("a folder"), "{folder}");
        #[cfg(unix)]
        {
            let device = super::read_file(Path::new("/dev/zero")).unwrap_err();
            assert_eq!(device.kind(), std::io::ErrorKind::InvalidInput, "{device}");
            assert!(device.to_string().contains("a device"), "{device}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
