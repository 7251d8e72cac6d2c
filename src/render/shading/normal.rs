//! Normal buffer: `(N + 1) / 2` of the outward normal at the first hit (COURSE.md §2.5), which
//! quantises to the consensus `trunc(255·(N+1)/2)`.

use glam::DVec3;

use crate::ir::Color;

/// The colour that encodes a unit normal.
pub fn encode(n: DVec3) -> Color {
    (n + DVec3::ONE) * 0.5
}
