//! Ctrl-C, SIGTERM and SIGHUP for every command (the `ctrlc` crate with its `termination`
//! feature: its own thread runs the handler, so nothing runs inside the signal handler itself).
//!
//! A signal ends the command with exit code 130 after removing the temporary files of the
//! atomic writes in progress ([`rtc::render::output::abandon_writes`]): the default action
//! would end the process without destructors and leave `.NAME.XXXXXX.tmp` files beside the
//! outputs. A write that had already renamed its file into place keeps it, and an image being
//! replaced is never touched. `rtc accuracy` asks for a graceful first signal instead
//! ([`graceful`]): it only sets a flag (the sweep stops after the current render and writes its
//! partial report); a second one ends the process as above.

use std::sync::atomic::{AtomicBool, Ordering};

/// Whether the first signal only sets [`INTERRUPTED`].
static GRACEFUL: AtomicBool = AtomicBool::new(false);

/// Set by the first signal.
static INTERRUPTED: AtomicBool = AtomicBool::new(false);

/// The exit code of a command ended by a signal.
const EXIT_CODE: i32 = 130;

/// Installs the handler (once per process; a second call changes nothing).
pub(crate) fn install() {
    // Without a handler (a platform that refuses one) signals keep their default action.
    let _ = ctrlc::set_handler(|| {
        if GRACEFUL.load(Ordering::SeqCst) && !INTERRUPTED.swap(true, Ordering::SeqCst) {
            return;
        }
        rtc::render::output::abandon_writes(|| std::process::exit(EXIT_CODE))
    });
}

/// Makes the first signal only set the flag [`interrupted`] reads.
pub(crate) fn graceful() {
    GRACEFUL.store(true, Ordering::SeqCst);
}

/// Whether a signal came since [`graceful`].
pub(crate) fn interrupted() -> bool {
    INTERRUPTED.load(Ordering::Relaxed)
}
