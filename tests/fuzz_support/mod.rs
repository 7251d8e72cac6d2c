//! Shared helpers for the proptest fuzzers of the front ends (`compat_fuzz.rs`, `mesh_fuzz.rs`,
//! `obj_fast.rs`): mutations of known-good text.

/// Replaces `len` bytes at `at` (rounded to char boundaries) with `with`.
pub fn splice(base: &str, at: usize, len: usize, with: &str) -> String {
    let mut a = at.min(base.len());
    while !base.is_char_boundary(a) {
        a -= 1;
    }
    let mut b = (a + len).min(base.len());
    while !base.is_char_boundary(b) {
        b -= 1;
    }
    format!("{}{}{}", &base[..a], with, &base[b..])
}
