//! Lens flare: a post stage that draws, over the film, what stray light in a lens makes of each
//! bright light the camera sees: ghosts (reflections between lens elements) along the line from
//! the light's image position through the image centre, a halo ring around the light and a star
//! of streaks (diffraction at the aperture blades), in the spirit of Blender's glare node and
//! game-engine flares.
//!
//! Each light's flare is scaled by its visible fraction, ray traced from the eye to the light's
//! samples (a point light: one ray; an area light: its sample grid's cell centres), so an area
//! light half hidden behind an object gives half the flare and a light behind a wall gives none.
//! Lights behind the camera or outside the frame flare not. Every term is a pure function of the
//! pixel, added to the film's linear colour before quantisation, so the bytes do not depend on the
//! thread count. The visibility rays are counted as shadow rays.

use crate::num::Norm;
use glam::{DVec2, DVec3};

use super::camera::Camera;
use super::film::Stats;
use super::offset;
use super::shading::disk_point;
use crate::geometry::Ray;
use crate::ir::{Color, Flare, LightKind};
use crate::opt::{Prepared, PreparedLight};

/// One light's flare as drawn: where the light is on the image and the colour of its flare.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Source {
    /// The light's image position (pixels, y down).
    at: DVec2,
    /// Light colour × visible fraction × intensity.
    color: Color,
}

/// The fraction of `light` the eye sees: its samples not hidden behind something.
fn visible_fraction(scene: &Prepared, eye: DVec3, light: &PreparedLight, stats: &mut Stats) -> f64 {
    let points: Vec<DVec3> = match light.kind {
        LightKind::Point { .. } | LightKind::Parallel { .. } | LightKind::Cylinder { .. } => {
            vec![light.kind.center()]
        }
        LightKind::Area {
            corner,
            u,
            v,
            samples,
            circular,
            orient,
        } => {
            let (nu, nv) = (samples[0].max(1), samples[1].max(1));
            (0..nu * nv)
                .map(|k| {
                    let a = (f64::from(k % nu) + 0.5) / f64::from(nu);
                    let b = (f64::from(k / nu) + 0.5) / f64::from(nv);
                    if circular {
                        disk_point(corner, u, v, orient, eye, a, b)
                    } else {
                        corner + a * u + b * v
                    }
                })
                .collect()
        }
    };
    let seen = points
        .iter()
        .filter(|&&p| {
            stats.shadow_rays += 1;
            let d = p - eye;
            let dist = d.norm();
            if dist <= 0.0 {
                return true;
            }
            let margin = offset::shadow_margin(eye, p, dist);
            !scene
                .world()
                .occluded(&Ray::new(eye, d / dist), 0.0, dist - margin)
        })
        .count();
    seen as f64 / points.len() as f64
}

/// The flare sources of `scene` through `camera`: the lights in front of the eye, inside the
/// frame, and bright enough once hidden parts are taken off.
pub(crate) fn sources(
    scene: &Prepared,
    camera: &Camera,
    f: &Flare,
    stats: &mut Stats,
) -> Vec<Source> {
    let (w, h) = (f64::from(camera.width()), f64::from(camera.height()));
    let mut out = Vec::new();
    for light in scene.lights() {
        let Some((x, y)) = camera.project(light.kind.center()) else {
            continue;
        };
        if !(0.0..=w).contains(&x) || !(0.0..=h).contains(&y) {
            continue;
        }
        let fraction = visible_fraction(scene, camera.eye(), light, stats);
        let brightness = light.color.element_sum() / 3.0 * fraction;
        if fraction <= 0.0 || brightness < f.threshold {
            continue;
        }
        out.push(Source {
            at: DVec2::new(x, y),
            color: light.color * (fraction * f.intensity),
        });
    }
    out
}

/// Where ghost `i` (1-based) of a light at `at` lies on an image of size `size`: on the line
/// from the light through the centre, `i·dispersal` of the way (past the centre beyond 1).
fn ghost_position(at: DVec2, size: DVec2, dispersal: f64, i: u32) -> DVec2 {
    at + (0.5 * size - at) * (f64::from(i) * dispersal)
}

/// Ghost `i`'s radius as a fraction of the image diagonal, and its tint (lens coatings colour
/// the ghosts differently).
fn ghost_look(i: u32) -> (f64, Color) {
    const LOOKS: [(f64, [f64; 3]); 4] = [
        (0.035, [1.0, 0.7, 0.4]),
        (0.02, [0.5, 0.8, 1.0]),
        (0.05, [0.6, 1.0, 0.6]),
        (0.025, [1.0, 0.5, 0.9]),
    ];
    let (r, c) = LOOKS[i as usize % LOOKS.len()];
    (r, Color::from_array(c))
}

/// A disc of radius `r` around the origin, anti-aliased over one pixel at its edge, softened
/// towards it: 1 at the centre, falling off to 0 at `r`.
fn soft_disc(d: f64, r: f64) -> f64 {
    if d >= r + 0.5 {
        return 0.0;
    }
    let edge = (r + 0.5 - d).clamp(0.0, 1.0);
    let fall = 1.0 - (d / r.max(1e-9)).powi(2) * 0.5;
    edge * fall.max(0.0)
}

/// The flare of `src` at pixel centre `p` on an image of `size` pixels.
fn at_pixel(src: &Source, f: &Flare, p: DVec2, size: DVec2) -> Color {
    let diag = size.norm();
    let mut c = Color::ZERO;
    for i in 1..=f.ghosts {
        let (r, tint) = ghost_look(i);
        let g = ghost_position(src.at, size, f.dispersal, i);
        let k = soft_disc(p.distance_to(g), r * diag);
        if k > 0.0 {
            c += 0.15 * k * tint * src.color;
        }
    }
    let d = p - src.at;
    let dist = d.norm();
    if f.halo > 0.0 {
        let radius = f.halo * diag;
        let width = (0.08 * radius).max(1.0);
        let x = (dist - radius) / width;
        if x.abs() < 4.0 {
            c += 0.04 * libm::exp(-x * x) * src.color;
        }
    }
    // The glow around the light itself, and the streaks: thin anti-aliased rays out of it
    // whose brightness falls off with the distance along them.
    let glow = dist / (0.01 * diag);
    c += 0.5 * libm::exp(-glow * glow) * src.color;
    for k in 0..f.streaks {
        let angle = std::f64::consts::FRAC_PI_2
            + std::f64::consts::TAU * f64::from(k) / f64::from(f.streaks);
        let dir = DVec2::new(libm::cos(angle), -libm::sin(angle));
        let along = d.dot(dir);
        if along <= 0.0 {
            continue;
        }
        let across = (d - along * dir).norm();
        let line = (1.0 - across / 1.5).max(0.0);
        if line > 0.0 {
            c += 0.5 * line * libm::exp(-along / (0.06 * diag)) * src.color;
        }
    }
    c
}

/// Adds the flare of every source to the colour values of a `w`×`h` film (`stride` values per
/// pixel, the colour first).
pub(crate) fn apply(
    sources: &[Source],
    f: &Flare,
    w: u32,
    h: u32,
    stride: usize,
    values: &mut [Color],
) {
    if sources.is_empty() {
        return;
    }
    let size = DVec2::new(f64::from(w), f64::from(h));
    for y in 0..h {
        for x in 0..w {
            let p = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
            let i = (y as usize * w as usize + x as usize) * stride;
            for s in sources {
                values[i] += at_pixel(s, f, p, size);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ghosts_lie_on_the_line_through_the_centre() {
        let size = DVec2::new(200.0, 100.0);
        let at = DVec2::new(30.0, 20.0);
        for i in 1..=5 {
            let g = ghost_position(at, size, 0.4, i);
            let (a, b) = (g - at, 0.5 * size - at);
            assert!(a.perp_dot(b).abs() < 1e-9);
        }
        assert_eq!(ghost_position(at, size, 0.5, 2), 0.5 * size);
    }

    #[test]
    fn flare_is_bright_at_ghosts_and_dark_off_the_line() {
        let f = Flare {
            streaks: 0,
            halo: 0.0,
            ..Flare::default()
        };
        let size = DVec2::new(200.0, 200.0);
        let src = Source {
            at: DVec2::new(40.0, 40.0),
            color: Color::ONE,
        };
        let g = ghost_position(src.at, size, f.dispersal, 2);
        assert!(at_pixel(&src, &f, g, size).min_element() > 0.05);
        // Perpendicular to the line, well away from any ghost.
        assert_eq!(
            at_pixel(&src, &f, DVec2::new(180.0, 20.0), size),
            Color::ZERO
        );
    }
}
