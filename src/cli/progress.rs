//! The render progress bar: the CLI's implementation of the renderer's progress callback, a bar
//! with ETA on stderr, shown only when stderr is a terminal, and the `--time-limit` deadline that
//! cancels the render (the renderer polls it before each band of rows).

use std::io::IsTerminal;
use std::time::Instant;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// A bar over image rows (a no-op when stderr is not a terminal), with an optional deadline.
pub(crate) struct Bar {
    bar: Option<ProgressBar>,
    deadline: Option<Instant>,
}

impl Bar {
    /// A bar on stderr if it is a terminal; past `deadline` the render is cancelled.
    pub(crate) fn on_stderr(deadline: Option<Instant>) -> Bar {
        if !std::io::stderr().is_terminal() {
            return Bar {
                bar: None,
                deadline,
            };
        }
        let style = ProgressStyle::with_template(
            "{spinner} rendering [{bar:40}] {percent:>3}% {elapsed} elapsed, ETA {eta}",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> ");
        let bar =
            ProgressBar::with_draw_target(Some(0), ProgressDrawTarget::stderr()).with_style(style);
        Bar {
            bar: Some(bar),
            deadline,
        }
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

    fn cancelled(&self) -> bool {
        self.deadline.is_some_and(|d| Instant::now() >= d)
    }
}
