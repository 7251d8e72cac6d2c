//! `rtc convert FILE [-o OUT]`: a course scene (`.in`, YAML) as rtc source (docs/convert.md).
//! The text goes to stdout, or atomically to OUT; a course file with errors gets its
//! diagnostics and exit 1, and OUT is left as it was.

use std::io::{IsTerminal, Write as _};
use std::path::Path;

use rtc::source::SourceMap;

use super::report::{self, Format};
use crate::cli::{Outcome, outcome_of};

/// Converts `file`; asset paths are written relative to OUT's directory, or to the working
/// directory when the text goes to stdout (where `> out.rtc` puts it).
pub(crate) fn run(file: &Path, output: Option<&Path>, format: Format) -> Outcome {
    let out_dir = match output {
        Some(o) => o
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(Path::new("."))
            .to_path_buf(),
        None => Path::new(".").to_path_buf(),
    };
    let mut sources = SourceMap::default();
    let converted = rtc::convert::convert(file, &out_dir, &mut sources);
    let diags = &converted.diagnostics;
    if !diags.items.is_empty() {
        let subject = file.display().to_string();
        let color = format == Format::Human && std::io::stderr().is_terminal();
        eprint!(
            "{}",
            report::render(&diags.items, &sources, &subject, format, color)
        );
    }
    let Some(text) = converted.text else {
        return match outcome_of(diags, false) {
            Outcome::Ok => Outcome::SceneErrors,
            other => other,
        };
    };
    match output {
        Some(path) => {
            if let Err(d) = rtc::render::output::write_atomically(path, text.as_bytes()) {
                eprint!(
                    "{}",
                    report::render(&[d], &sources, &path.display().to_string(), format, false)
                );
                return Outcome::IoOrUsage;
            }
        }
        None => {
            if std::io::stdout().write_all(text.as_bytes()).is_err() {
                return Outcome::IoOrUsage;
            }
        }
    }
    Outcome::Ok
}
