//! Light through glass: with `render { glass_shadows: true }` a shadow ray passes through
//! refractive surfaces instead of stopping at them.
//!
//! Rule: every surface the shadow ray crosses multiplies the light by its material's
//! `refract · colour` (a closed glass object is crossed twice, so it passes
//! `(refract · colour)²`); an opaque surface (`refract = 0`) blocks it. The ray is not bent and
//! Fresnel reflection is not counted: the shadow is the glass's tinted, lighter silhouette, not a
//! caustic.

use super::{LightSample, Surface};
use crate::geometry::Ray;
use crate::ir::Color;
use crate::opt::Prepared;
use crate::render::film::Stats;
use crate::render::offset;

/// Most surfaces one shadow ray passes through before it counts as blocked (a stack of glass
/// panes deeper than this passes next to nothing anyway).
const MAX_CROSSINGS: u32 = 32;

/// The share of light sample `ls` that reaches surface point `s` through the glass in between,
/// per channel; `None` when an opaque surface blocks it.
pub fn transmission(
    scene: &Prepared,
    s: &Surface<'_>,
    ls: &LightSample,
    stats: &mut Stats,
) -> Option<Color> {
    let eps = offset::eps(scene, s.p);
    let mut origin = s.p + eps * s.n;
    let mut left = ls.dist - eps;
    let mut pass = Color::ONE;
    for _ in 0..MAX_CROSSINGS {
        stats.shadow_rays += 1;
        let ray = Ray::new(origin, ls.l);
        let Some(hit) = scene.world().intersect(&ray, 0.0, left) else {
            return Some(pass);
        };
        let m = scene.material(hit.material);
        if m.refract <= 0.0 {
            return None;
        }
        pass *= m.refract * m.color;
        if pass.max_element() <= 0.0 {
            return None;
        }
        let step = offset::eps(scene, hit.point);
        origin = hit.point + step * ls.l;
        left -= hit.t + step;
        if left <= 0.0 {
            return Some(pass);
        }
    }
    None
}
