//! The render progress bar: the CLI's implementation of the renderer's progress callback, a bar
//! with ETA on stderr, shown only when stderr is a terminal.

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// A bar over image rows; a no-op when stderr is not a terminal.
pub struct Bar {
    bar: Option<ProgressBar>,
}

impl Bar {
    /// A bar on stderr if it is a terminal.
    pub fn on_stderr() -> Bar {
        if !std::io::stderr().is_terminal() {
            return Bar { bar: None };
        }
        let style = ProgressStyle::with_template(
            "{spinner} rendering [{bar:40}] {percent:>3}% {elapsed} elapsed, ETA {eta}",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> ");
        let bar =
            ProgressBar::with_draw_target(Some(0), ProgressDrawTarget::stderr()).with_style(style);
        Bar { bar: Some(bar) }
    }
}

impl rtc::render::Progress for Bar {
    fn start(&self, rows: u64) {
        if let Some(b) = &self.bar {
            b.set_length(rows);
        }
    }

    fn advance(&self, rows: u64) {
        if let Some(b) = &self.bar {
            b.inc(rows);
        }
    }

    fn finish(&self) {
        if let Some(b) = &self.bar {
            b.finish_and_clear();
        }
    }
}
