//! `rtc check PATH`: one scene or library module, or every `.rtc` file below a directory with
//! one summary. A library module (exports, emits nothing) is checked as an import would see it.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};

use rtc::diag::Diagnostics;
use rtc::eval::EvalOptions;
use rtc::loader::SceneFormat;
use rtc::source::SourceMap;

use super::report::{self, Format};
use crate::cli::Outcome;

/// What checking one file found.
struct FileCheck {
    file: PathBuf,
    sources: SourceMap,
    diagnostics: Diagnostics,
    outcome: Outcome,
    /// `PATH: ok: …` when clean, else the error and warning counts (without the path).
    summary: String,
    library: bool,
}

/// Checks a file or every `.rtc` file below a directory and prints the findings.
/// `options` carry the command line's frame, fps and `--set` overrides to every file.
pub(crate) fn run(
    path: &Path,
    format: Format,
    deny_warnings: bool,
    options: &EvalOptions,
) -> Outcome {
    if path.is_dir() {
        return run_dir(path, format, deny_warnings, options);
    }
    let c = check_file(path, deny_warnings, options);
    if format == Format::Json {
        let mut doc = json_of(&c, format);
        doc["ok"] = serde_json::Value::Bool(matches!(c.outcome, Outcome::Ok));
        println!("{doc}");
    } else {
        print_human(&c, format);
        eprintln!("{}", c.summary);
    }
    c.outcome
}

/// Every `.rtc` file below `dir`, sorted; hidden directories and `target` are skipped.
pub(crate) fn rtc_files(dir: &Path, out: &mut Vec<PathBuf>) -> std::io::Result<()> {
    let mut entries: Vec<_> = std::fs::read_dir(dir)?
        .filter_map(Result::ok)
        .map(|e| e.path())
        .collect();
    entries.sort();
    for p in entries {
        let name = p.file_name().map(|n| n.to_string_lossy().into_owned());
        let skipped = name.is_some_and(|n| n.starts_with('.') || n == "target");
        if p.is_dir() && !skipped {
            rtc_files(&p, out)?;
        } else if p.extension().is_some_and(|e| e == "rtc") {
            out.push(p);
        }
    }
    Ok(())
}

fn run_dir(dir: &Path, format: Format, deny_warnings: bool, options: &EvalOptions) -> Outcome {
    let mut files = Vec::new();
    if let Err(e) = rtc_files(dir, &mut files) {
        eprintln!("error: cannot read the directory `{}`: {e}", dir.display());
        return Outcome::IoOrUsage;
    }
    if files.is_empty() {
        eprintln!(
            "error: no `.rtc` file below `{}`\n  help: give a directory that holds scenes, or a scene file",
            dir.display()
        );
        return Outcome::IoOrUsage;
    }
    let checks: Vec<FileCheck> = files
        .iter()
        .map(|f| check_file(f, deny_warnings, options))
        .collect();
    let failed = checks
        .iter()
        .filter(|c| !matches!(c.outcome, Outcome::Ok))
        .count();
    let libraries = checks.iter().filter(|c| c.library).count();
    let errors: usize = checks.iter().map(|c| c.diagnostics.error_count()).sum();
    let warnings: usize = checks.iter().map(|c| c.diagnostics.warning_count()).sum();
    let summary = format!(
        "checked {} file{} below {}: {} ok ({libraries} librar{}), {failed} failed; {}",
        checks.len(),
        if checks.len() == 1 { "" } else { "s" },
        dir.display(),
        checks.len() - failed,
        if libraries == 1 { "y" } else { "ies" },
        counts(errors, warnings),
    );
    let outcome = checks
        .iter()
        .map(|c| c.outcome)
        .max_by_key(|o| o.severity())
        .unwrap_or(Outcome::Ok);
    if format == Format::Json {
        let doc = serde_json::json!({
            "files": checks.iter().map(|c| json_of(c, format)).collect::<Vec<_>>(),
            "summary": summary,
            "ok": matches!(outcome, Outcome::Ok),
        });
        println!("{doc}");
    } else {
        for c in &checks {
            print_human(c, format);
            match c.outcome {
                Outcome::Ok => eprintln!("{}", c.summary),
                _ => eprintln!("{}: {}", c.file.display(), c.summary),
            }
        }
        eprintln!("{summary}");
    }
    outcome
}

fn check_file(file: &Path, deny_warnings: bool, options: &EvalOptions) -> FileCheck {
    let mut sources = SourceMap::new();
    if SceneFormat::of(file) == Some(SceneFormat::Rtc)
        && let Ok(Ok(text)) = rtc::source::read_file(file).map(String::from_utf8)
        && let Some(lib) = rtc::eval::library::load_library(file, &text, &mut sources, options)
    {
        let outcome = crate::cli::outcome_of(&lib.diagnostics, deny_warnings);
        let summary = match outcome {
            Outcome::Ok => format!(
                "{}: ok: library module exporting {} name{}: {}",
                file.display(),
                lib.exports.len(),
                if lib.exports.len() == 1 { "" } else { "s" },
                lib.exports.join(", ")
            ),
            _ => count_line(&lib.diagnostics),
        };
        return FileCheck {
            file: file.to_path_buf(),
            sources,
            diagnostics: lib.diagnostics,
            outcome,
            summary,
            library: true,
        };
    }
    let mut loaded = rtc::loader::load(file, &mut sources, options);
    // The scene is not needed after its check: it is freed as it is checked.
    let summary = loaded.scene.take().map(|scene| {
        let (diagnostics, summary) = rtc::check::check_owned(scene);
        loaded.diagnostics.extend(diagnostics);
        summary
    });
    let outcome = crate::cli::outcome_of(&loaded.diagnostics, deny_warnings);
    let summary = match (&outcome, summary) {
        (Outcome::Ok, Some(summary)) => format!("{}: ok: {summary}", file.display()),
        _ => count_line(&loaded.diagnostics),
    };
    FileCheck {
        file: file.to_path_buf(),
        sources,
        diagnostics: loaded.diagnostics,
        outcome,
        summary,
        library: false,
    }
}

fn print_human(c: &FileCheck, format: Format) {
    // Diagnostics and the summary are a compiler's messages: stderr. Only `--format json`,
    // which a tool asked for, writes to stdout.
    let color = format == Format::Human && std::io::stderr().is_terminal();
    let subject = c.file.display().to_string();
    let text = report::render(&c.diagnostics.items, &c.sources, &subject, format, color);
    if !text.is_empty() {
        eprintln!("{}", text.trim_end());
        if format == Format::Short {
            eprintln!();
        }
    }
}

fn json_of(c: &FileCheck, format: Format) -> serde_json::Value {
    let subject = c.file.display().to_string();
    let mut doc: serde_json::Value = serde_json::from_str(&report::render(
        &c.diagnostics.items,
        &c.sources,
        &subject,
        format,
        false,
    ))
    .unwrap_or_default();
    doc["file"] = serde_json::Value::String(subject);
    doc["summary"] = serde_json::Value::String(c.summary.clone());
    doc["library"] = serde_json::Value::Bool(c.library);
    doc["ok"] = serde_json::Value::Bool(matches!(c.outcome, Outcome::Ok));
    doc
}

/// "1 error, 2 warnings".
pub(crate) fn count_line(diags: &Diagnostics) -> String {
    counts(diags.error_count(), diags.warning_count())
}

fn counts(e: usize, w: usize) -> String {
    format!(
        "{e} error{}, {w} warning{}",
        if e == 1 { "" } else { "s" },
        if w == 1 { "" } else { "s" }
    )
}
