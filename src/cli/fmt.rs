//! `rtc fmt PATH... [--check]`: lays `.rtc` files out in the canonical layout (docs/fmt.md).
//! Files are rewritten in place (temporary file and rename, only when the text changes);
//! `--check` writes nothing, shows a diff of what would change and fails when anything would.
//! `-` formats standard input to standard output.

use std::io::{IsTerminal, Read};
use std::path::{Path, PathBuf};

use rtc::diag::Diagnostic;
use rtc::source::SourceMap;

use super::report::{self, Format};
use crate::cli::Outcome;

/// Stack of the formatting thread (reserved address space; pages are touched only as needed).
const FMT_STACK_BYTES: usize = 256 << 20;

/// What formatting one file did.
enum Done {
    Unchanged,
    Changed,
    /// Syntax errors (or a file the formatter refused): reported, file untouched.
    Errors,
    /// Could not read or write.
    Io,
}

/// Formats every path (files, directories of `.rtc` files, or `-` for standard input).
pub(crate) fn run(paths: &[PathBuf], check: bool, format: Format) -> Outcome {
    let mut files = Vec::new();
    for p in paths {
        if p.as_os_str() == "-" {
            files.push(p.clone());
        } else if p.is_dir() {
            let before = files.len();
            if let Err(e) = super::check::rtc_files(p, &mut files) {
                eprintln!("error: cannot read the directory `{}`: {e}", p.display());
                return Outcome::IoOrUsage;
            }
            if files.len() == before {
                eprintln!("warning: no `.rtc` file below `{}`", p.display());
            }
        } else {
            files.push(p.clone());
        }
    }
    let mut changed = 0;
    let mut outcome = Outcome::Ok;
    for f in &files {
        let done = if f.as_os_str() == "-" {
            stdin(check, format)
        } else {
            file(f, check, format)
        };
        let o = match done {
            Done::Unchanged => Outcome::Ok,
            Done::Changed => {
                changed += 1;
                if check {
                    Outcome::SceneErrors
                } else {
                    Outcome::Ok
                }
            }
            Done::Errors => Outcome::SceneErrors,
            Done::Io => Outcome::IoOrUsage,
        };
        if o.severity() > outcome.severity() {
            outcome = o;
        }
    }
    let verb = if check {
        "would reformat"
    } else {
        "reformatted"
    };
    eprintln!(
        "{verb} {changed} of {} file{}",
        files.len(),
        if files.len() == 1 { "" } else { "s" }
    );
    outcome
}

/// Formats `text` read from `path`; `Err` after reporting the diagnostics.
fn formatted(path: &Path, text: String, format: Format) -> Result<String, ()> {
    let mut sources = SourceMap::new();
    let id = sources.add(path, text);
    let text = &sources.get(id).text;
    // The layout recurses once per level of the tree, as deep as the longest chain the
    // budgets allow (§24): on a thread with the evaluation's stack, not the main thread's.
    let run = || rtc::syntax::format::format(id, text);
    let result = std::thread::scope(|s| {
        std::thread::Builder::new()
            .name("rtc-fmt".into())
            .stack_size(FMT_STACK_BYTES)
            .spawn_scoped(s, run)
            .map(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p)))
    })
    .unwrap_or_else(|_| run());
    match result {
        Ok(out) => Ok(out),
        Err(diags) => {
            show(&diags, &sources, path, format);
            Err(())
        }
    }
}

fn show(diags: &[Diagnostic], sources: &SourceMap, path: &Path, format: Format) {
    let color = format == Format::Human && std::io::stderr().is_terminal();
    let subject = path.display().to_string();
    let text = report::render(diags, sources, &subject, format, color);
    eprintln!("{}", text.trim_end());
}

fn file(path: &Path, check: bool, format: Format) -> Done {
    let read = rtc::source::read_regular(path, rtc::source::MAX_SOURCE_BYTES).and_then(|b| {
        String::from_utf8(b).map_err(|_| {
            std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                "the file is not UTF-8 text",
            )
        })
    });
    let text = match read {
        Ok(t) => t,
        Err(e) => {
            eprintln!(
                "error: cannot read `{}`: {e}\n  help: give a `.rtc` text file or a directory",
                path.display()
            );
            return Done::Io;
        }
    };
    let Ok(out) = formatted(path, text.clone(), format) else {
        return Done::Errors;
    };
    if out == text {
        return Done::Unchanged;
    }
    if check {
        print!(
            "{}",
            super::diff::unified(&path.display().to_string(), &text, &out)
        );
        return Done::Changed;
    }
    // In place means the file the path names: through a symlink to its target (the link stays
    // a link), with the file's permissions (a 0600 file stays 0600).
    let target = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
    let permissions = std::fs::metadata(&target).ok().map(|m| m.permissions());
    match rtc::render::output::write_atomically_with(&target, out.as_bytes(), permissions) {
        Ok(()) => {
            println!("{}", path.display());
            Done::Changed
        }
        Err(d) => {
            eprintln!(
                "error: {}\n  help: check that the file is writable",
                d.message
            );
            Done::Io
        }
    }
}

/// `-`: standard input to standard output (with `--check`, only the diff).
fn stdin(check: bool, format: Format) -> Done {
    let mut text = String::new();
    if let Err(e) = std::io::stdin().read_to_string(&mut text) {
        eprintln!("error: cannot read standard input: {e}");
        return Done::Io;
    }
    let path = Path::new("<stdin>");
    let Ok(out) = formatted(path, text.clone(), format) else {
        return Done::Errors;
    };
    if check {
        print!("{}", super::diff::unified("<stdin>", &text, &out));
    } else {
        print!("{out}");
    }
    if out == text {
        Done::Unchanged
    } else {
        Done::Changed
    }
}
