//! Where spawned rays start: secondary and shadow rays begin a small distance along the normal
//! so they do not re-hit the surface they leave. (When hits carry a floating-point error bound,
//! this is the one place that turns it into an offset.)

use glam::DVec3;

use crate::opt::Prepared;

/// Relative size of the offset: `EPS_REL · max(|P|∞, scene extent)`. Scaling with the
/// coordinates keeps it above the rounding error of a hit point (about 1e-16·|P|) at any scale,
/// from millimetre scenes to the astronomical blue-earth scene (|P| ≈ 1.5e8 → 15 units).
pub const EPS_REL: f64 = 1e-9;

/// The offset along the normal for rays leaving point `p` of `scene`.
pub fn eps(scene: &Prepared, p: DVec3) -> f64 {
    (EPS_REL * p.abs().max_element())
        .max(EPS_REL * scene.extent())
        .max(1e-300)
}
