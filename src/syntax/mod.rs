//! Syntax: the pest grammar (`grammar/rtc.pest`), the AST, and a statement-by-statement driver
//! that recovers at top-level line starts so several syntax errors show in one run.

pub(crate) mod ast;
mod build;
mod delims;
mod errors;
mod fast;
pub mod format;
mod grammar;
pub(crate) mod intern;
mod numbers;
mod pratt;
mod stmts;

pub(crate) use build::srgb_to_linear;
pub(crate) use errors::KEYWORDS;

use pest::Parser;

use crate::diag::Diagnostic;
use crate::source::{FileId, Span};

pub(crate) use grammar::{RtcParser, Rule};

/// The language versions this build understands: `rtc 1` and `rtc 1.1` name the same language
/// (1.1 is a compatible extension of 1; docs/language.md §2).
const SUPPORTED_VERSIONS: &[&str] = &["1", "1.0", "1.1"];

/// Deepest bracket nesting accepted; deeper input is rejected before pest or the evaluator
/// could exhaust the stack.
const MAX_NESTING: usize = 200;

/// Parses a whole file. Returns the AST (only when there were no syntax errors) and diagnostics.
pub(crate) fn parse(
    file: FileId,
    text: &str,
) -> (Option<ast::File<'_>>, Vec<crate::diag::Diagnostic>) {
    let parsed = parse_with(file, text, Path::FastFirst);
    (parsed.ast, parsed.diags)
}

/// How statements are read: the fast path first (`parse`), or pest alone (the reference the
/// fast path is tested against).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Path {
    FastFirst,
    #[cfg(test)]
    PestOnly,
}

/// A parse's result, with how many statements the fast path read (for its tests).
struct Parsed<'t> {
    ast: Option<ast::File<'t>>,
    diags: Vec<Diagnostic>,
    #[cfg_attr(not(test), allow(dead_code))]
    fast_statements: usize,
}

fn parse_with(file: FileId, text: &str, path: Path) -> Parsed<'_> {
    let scan = delims::scan(file, text);
    // Only brackets the scan counts (outside strings and comments, before its first error:
    // the statements read end there) reach pest, so the budget's own count runs only when they
    // nest deeply; it counts every bracket, as it did when it ran first.
    if scan.max_depth > MAX_NESTING
        && let Some(d) = too_deep(file, text)
    {
        return Parsed {
            ast: None,
            diags: vec![d],
            fast_statements: 0,
        };
    }
    // A delimiter error cuts the file: statements before the one it is in are still parsed (so
    // their errors show too), later ones would only repeat it.
    let cutoff = scan.errors.first().map_or(text.len(), |d| {
        let at = d.span.map_or(0, |s| s.start as usize);
        scan.top_level_lines
            .iter()
            .copied()
            .filter(|&l| l <= at)
            .max()
            .unwrap_or(0)
    });
    let mut diags = scan.warnings;
    // Every statement starts a top-level line: one allocation for the statement list.
    let mut items: Vec<ast::Item> = Vec::with_capacity(scan.top_level_lines.len());
    let mut stmts: Vec<ast::Stmt> = Vec::new();
    // Whether the last statement was an expression or `let` (which a `-` line could continue).
    let mut continuable = false;
    let mut fast_statements = 0;
    let mut syntax_errors = 0;
    let (version, mut pos) = header(file, text, &mut diags);
    let (fast_ends, mut tapes) = match path {
        Path::FastFirst => fast_line_ends(text, &scan.top_level_lines, cutoff),
        #[cfg(test)]
        Path::PestOnly => (FastLines { chunks: Vec::new() }, Vec::new()),
    };
    // Lines read here (not at a top-level line start) go on a tape of their own, the last.
    let own = tapes.len() as u32;
    tapes.push(fast::Tape::default());
    // Statements start at top-level lines, in order: `line` follows `pos` through them.
    let mut line = 0;
    while pos < cutoff {
        while scan.top_level_lines.get(line).is_some_and(|&l| l < pos) {
            line += 1;
        }
        let fast_end = match scan.top_level_lines.get(line) {
            Some(&l) if l == pos => fast_ends.get(line),
            _ if path == Path::FastFirst => {
                let tape = &mut tapes[own as usize];
                let at = tape.mark();
                fast::read(text, pos, cutoff, tape).map(|next| (next, own, at))
            }
            _ => None,
        };
        // Simple one-line statements (most of a generated file) skip pest; see fast/mod.rs.
        if let Some((next, tape, at)) = fast_end {
            // Only what reading found is kept: `File::stmts` builds it when it is visited.
            items.push(ast::Item::Line { tape, at });
            continuable = true;
            fast_statements += 1;
            pos = next;
            continue;
        }
        let rest = &text[pos..cutoff];
        match RtcParser::parse(Rule::stmt_line, rest) {
            Ok(mut pairs) => {
                let line = pairs.next().expect("grammar: stmt_line");
                let end = line.as_span().end();
                let b = build::Builder::new(file, pos);
                let mut done = false;
                for p in line.into_inner() {
                    if p.as_rule() == Rule::EOI {
                        done = true;
                    } else {
                        b.check_minus_line(continuable, &p);
                        let stmt = b.stmt(p);
                        continuable = build::continuable(&stmt);
                        items.push(ast::Item::Built(stmts.len() as u32));
                        stmts.push(stmt);
                    }
                }
                diags.extend(b.finish());
                if done || end == 0 {
                    break;
                }
                pos += end;
            }
            Err(first) => {
                // Parse again with pest's error detail (expected tokens) switched on: it costs
                // an allocation per attempted token, so the fast path above runs without it.
                pest::set_error_detail(true);
                let detailed = RtcParser::parse(Rule::stmt_line, rest);
                pest::set_error_detail(false);
                let e = detailed.err().unwrap_or(first);
                let d = errors::convert(file, text, pos, &e);
                let at = d.span.map_or(pos, |s| s.start as usize);
                diags.push(d);
                syntax_errors += 1;
                if syntax_errors >= crate::diag::MAX_ERRORS {
                    diags.push(stopped_reading(file, text, at));
                    break;
                }
                // From the first top-level line after the error (found by bisection: a file
                // of bad lines made this search quadratic).
                let from = scan.top_level_lines.partition_point(|&l| l <= at.max(pos));
                match scan.top_level_lines[from..]
                    .iter()
                    .find(|&&l| starts_statement(text, l))
                {
                    Some(&next) => pos = next,
                    None => break,
                }
            }
        }
    }
    diags.extend(scan.errors);
    // Errors in file order: the delimiter error may lie before later statements' errors.
    diags.sort_by_key(|d| d.span.map_or(0, |s| s.start));
    let has_errors = diags.iter().any(Diagnostic::is_error);
    let file_ast = ast::File {
        version,
        items,
        built: stmts,
        tapes,
        file,
        text,
    };
    Parsed {
        ast: if has_errors { None } else { Some(file_ast) },
        diags,
        fast_statements,
    }
}

/// The note after the syntax error that reached [`crate::diag::MAX_ERRORS`]: reading stopped
/// there, and where (what follows was not read, so its errors cannot be counted).
fn stopped_reading(file: FileId, text: &str, at: usize) -> Diagnostic {
    let line = text.as_bytes()[..at.min(text.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1;
    Diagnostic::new(
        crate::diag::Severity::Note,
        "rtc::diag::omitted",
        Some(Span::new(file, at, at)),
        format!(
            "{} syntax errors: the file was not read past line {line}",
            crate::diag::MAX_ERRORS
        ),
    )
    .with_label("reading stopped here")
    .with_help("fix these errors and run again to see the next ones")
}

/// Top-level lines from which reading fast is worth a thread of its own.
const PARALLEL_LINES: usize = 4096;

/// Top-level lines read into one tape (a unit of parallel work).
const CHUNK_LINES: usize = PARALLEL_LINES / 4;

/// A fast statement's line: the offset after it, and where it was written (tape, mark).
type FastLine = Option<(usize, u32, fast::Mark)>;

/// What the fast path read at each top-level line start, chunk by chunk: the offset after each
/// line read (`None` where pest must read it, or past `cutoff`) and where it was written; chunk
/// `k` wrote tape `k`.
struct FastLines {
    chunks: Vec<Vec<Option<(u32, fast::Mark)>>>,
}

impl FastLines {
    /// What reading top-level line `line` found.
    fn get(&self, line: usize) -> FastLine {
        let (k, i) = (line / CHUNK_LINES, line % CHUNK_LINES);
        let (next, at) = self.chunks.get(k)?.get(i).copied().flatten()?;
        Some((next as usize, k as u32, at))
    }
}

/// Reads every top-level line start with the fast path, returning what it found and the tapes
/// it wrote. Reading is a pure function of the text and the position (it interns no names), so
/// a large file's chunks are read on every core, each writing a tape of its own; the answers
/// do not depend on how they were cut.
fn fast_line_ends(text: &str, lines: &[usize], cutoff: usize) -> (FastLines, Vec<fast::Tape>) {
    use rayon::prelude::*;
    let read_chunk = |chunk: &[usize]| {
        let bytes = chunk.last().zip(chunk.first()).map_or(0, |(l, f)| l - f);
        let mut tape = fast::Tape::for_bytes(bytes);
        let ends = chunk
            .iter()
            .map(|&l| {
                let at = tape.mark();
                let next = (l < cutoff).then(|| fast::read(text, l, cutoff, &mut tape))??;
                Some((u32::try_from(next).ok()?, at))
            })
            .collect::<Vec<_>>();
        (ends, tape)
    };
    let chunks: Vec<_> = if lines.len() < PARALLEL_LINES {
        lines.chunks(CHUNK_LINES).map(read_chunk).collect()
    } else {
        lines.par_chunks(CHUNK_LINES).map(read_chunk).collect()
    };
    let (chunks, tapes) = chunks.into_iter().unzip();
    (FastLines { chunks }, tapes)
}

/// Reads the `rtc N` header; returns the version and the offset after it.
fn header(
    file: FileId,
    text: &str,
    diags: &mut Vec<Diagnostic>,
) -> (Option<(String, Span)>, usize) {
    let Ok(mut pairs) = RtcParser::parse(Rule::header_line, text) else {
        let first = first_token(text);
        diags.push(
            Diagnostic::error(
                "rtc::syntax::header",
                Span::new(file, first, first),
                "missing `rtc 1.1` header",
            )
            .with_label("the file must start with its language version")
            .with_help("add `rtc 1.1` as the first line"),
        );
        return (None, 0);
    };
    let line = pairs.next().expect("grammar: header_line");
    let end = line.as_span().end();
    let n = line.into_inner().next().and_then(|h| h.into_inner().next());
    let Some(n) = n else { return (None, end) };
    let s = n.as_span();
    let span = Span::new(file, s.start(), s.end());
    if !SUPPORTED_VERSIONS.contains(&n.as_str()) {
        diags.push(
            Diagnostic::error(
                "rtc::syntax::version",
                span,
                format!("unsupported language version `{}`", n.as_str()),
            )
            .with_label("this build understands versions 1 and 1.1")
            .with_help("write `rtc 1.1` as the first line"),
        );
    }
    (Some((n.as_str().to_owned(), span)), end)
}

/// Offset of the first non-blank, non-comment character (where a header would be).
fn first_token(text: &str) -> usize {
    let mut i = 0;
    for line in text.split_inclusive('\n') {
        let t = line.trim_start();
        if !t.is_empty() && !t.starts_with("//") {
            return i + (line.len() - t.len());
        }
        i += line.len();
    }
    0
}

/// A top-level line that can begin a new statement (not a continuation or a closer).
fn starts_statement(text: &str, at: usize) -> bool {
    let c = text[at..].chars().next();
    matches!(c, Some(c) if c.is_alphanumeric() || matches!(c, '_' | '[' | '(' | '"' | '#'))
}

fn too_deep(file: FileId, text: &str) -> Option<Diagnostic> {
    let mut depth = 0usize;
    // Brackets are ASCII, so bytes (not chars) suffice and keep the offsets.
    for (i, c) in text.bytes().enumerate() {
        match c {
            b'(' | b'[' | b'{' => {
                depth += 1;
                if depth > MAX_NESTING {
                    return Some(
                        Diagnostic::error(
                            "rtc::budget::nesting",
                            Span::new(file, i, i + 1),
                            "brackets nested too deeply",
                        )
                        .with_label(format!("more than {MAX_NESTING} levels deep"))
                        .with_help("move inner parts into `let` bindings or functions"),
                    );
                }
            }
            b')' | b']' | b'}' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    None
}

#[cfg(test)]
mod fast_tests;
#[cfg(test)]
mod tests;
