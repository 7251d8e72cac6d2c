//! Light through glass: with `render { glass_shadows: true }` a shadow ray passes through
//! refractive surfaces instead of stopping at them.
//!
//! Rule: every surface the shadow ray crosses multiplies the light by its material's
//! `refract` times its tint (`scatter::tint`, the rule refracted light follows: `refract · colour`
//! with the language's `filter: 1`; a closed glass object is crossed twice, so it passes
//! `(refract · colour)²`), and a segment inside an absorbing object `exp(−absorption·d)`; an
//! opaque surface (`refract = 0`) blocks it. The ray is not bent and
//! Fresnel reflection is not counted: the shadow is the glass's tinted, lighter silhouette, not a
//! caustic.

use super::surface::{LightSample, Surface};
use crate::ir::{Color, Visibility};
use crate::opt::Prepared;
use crate::render::film::Stats;
use crate::render::offset::SpawnPoint;
use crate::render::scatter::{beer_lambert, straight_through};

/// Most surfaces one shadow ray passes through before it counts as blocked (a stack of glass
/// panes deeper than this passes next to nothing anyway).
pub(crate) const MAX_CROSSINGS: u32 = 32;

/// The share of light sample `ls` that reaches surface point `s` through the glass in between,
/// per channel; `None` when an opaque surface blocks it.
pub(crate) fn transmission(
    scene: &Prepared,
    s: &Surface<'_>,
    ls: &LightSample,
    stats: &mut Stats,
) -> Option<Color> {
    let Some((first, mut left)) = s.spawn.ray_to(ls.position) else {
        return Some(Color::ONE);
    };
    let mut ray = first.at_time(s.time);
    let mut pass = Color::ONE;
    for _ in 0..MAX_CROSSINGS {
        stats.shadow_rays += 1;
        let Some(hit) = scene.seen_hit(&ray, 0.0, left, Visibility::NO_SHADOW) else {
            return Some(pass);
        };
        // The glass passes what its scattering lets through along a straight line.
        let mat = scene.material(hit.material);
        pass *= straight_through(mat)?;
        // Leaving an absorbing object: what the segment inside it kept (Beer–Lambert).
        if scene.effects().absorption
            && mat.absorption != Color::ZERO
            && hit.normal.dot(ray.dir) > 0.0
        {
            pass *= beer_lambert(mat.absorption, hit.t);
        }
        if pass.max_element() <= 0.0 {
            return None;
        }
        // Leave the glass on the far side and aim at the light again from there.
        let Some((next, t_max)) = SpawnPoint::of(&hit).ray_to(ls.position) else {
            return Some(pass);
        };
        ray = next.at_time(s.time);
        left = t_max;
        if left <= 0.0 {
            return Some(pass);
        }
    }
    None
}
