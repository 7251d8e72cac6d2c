//! Progress and cancellation: the renderer reports rows done to a callback its caller
//! implements (the CLI draws a bar; `rtc watch` or a time budget would cancel), and prints
//! nothing itself.

/// The error code of a render its [`Progress`] cancelled.
pub const CANCELLED: &str = "rtc::render::cancelled";

/// What a render tells its caller while it runs. Every method may be called from any render
/// thread.
pub trait Progress: Sync {
    /// The render will report `rows` rows in all (every pass over the image counts its rows).
    fn start(&self, _rows: u64) {}

    /// `rows` more rows are done.
    fn advance(&self, _rows: u64) {}

    /// The render ended (finished or cancelled).
    fn finish(&self) {}

    /// Polled before each band of rows: `true` stops the render, which then returns the error
    /// `rtc::render::cancelled` (and no film).
    fn cancelled(&self) -> bool {
        false
    }
}

/// Reports nothing and never cancels.
#[derive(Clone, Copy, Debug, Default)]
pub struct Silent;

impl Progress for Silent {}
