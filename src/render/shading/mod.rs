//! Shading models: what a surface point looks like under the lights, before the scattering
//! layer's reflection and refraction are added by the Whitted integrator.

pub(crate) mod finish;
mod glass_shadow;
pub(crate) mod gooch;
pub(crate) mod hatching;
pub(crate) mod phong;
pub(crate) mod phong_packet;
mod surface;

pub(crate) use surface::{LightSample, Surface, disk_point, highlight, light_sample, visible};

use crate::geometry::SurfaceHit;
use crate::ir::{Color, Visibility};
use crate::opt::Prepared;
use crate::render::film::Stats;
use crate::render::offset::SpawnPoint;
use crate::render::scatter::straight_through;

/// The first opaque surface between `s` and light sample `ls` (for explanations: the shadow
/// test itself only asks whether there is one). With glass shadows, glass on the way is
/// passed as [`glass_shadow`] passes it.
fn occluder(scene: &Prepared, s: &Surface<'_>, ls: &LightSample) -> Option<SurfaceHit> {
    if !ls.shadows {
        return None;
    }
    let (mut ray, mut left) = s.spawn.ray_to(ls.position)?;
    for _ in 0..glass_shadow::MAX_CROSSINGS {
        let hit = scene.seen_hit(&ray.at_time(s.time), 0.0, left, Visibility::NO_SHADOW)?;
        if !scene.effects().glass_shadows
            || straight_through(scene.material(hit.material)).is_none()
        {
            return Some(hit);
        }
        (ray, left) = SpawnPoint::of(&hit).ray_to(ls.position)?;
    }
    None
}

/// The share of light sample `ls` reaching `s`, per channel: `Some(ONE)` when nothing blocks
/// it, `None` when something opaque does, and with light through glass the tint of the glass
/// in between ([`glass_shadow`]).
pub(crate) fn transmission(
    scene: &Prepared,
    s: &Surface<'_>,
    ls: &LightSample,
    stats: &mut Stats,
) -> Option<Color> {
    if scene.effects().glass_shadows && ls.shadows {
        glass_shadow::transmission(scene, s, ls, stats)
    } else {
        visible(scene, s, ls, stats).then_some(Color::ONE)
    }
}
