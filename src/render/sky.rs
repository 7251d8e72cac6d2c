//! The sky: what a ray that meets nothing sees (`render { sky: .. }`). A pattern (or checker,
//! stripes) is read at the ray's unit direction, as POV-Ray's `sky_sphere` reads its pigment
//! (`source/core/render/trace.cpp`, `Trace::ComputeSky`); an image is a latitude–longitude
//! (equirectangular) map laid out as the equirectangular camera's picture: its centre column
//! looks along −Z, x grows to +X, the top row is +Y. A sky colour's filter and transmit let the
//! background show through, as POV-Ray 3.7 composes a sky sphere over the background.

use glam::{DVec2, DVec3};

use crate::ir::{Color, Sky};
use crate::opt::{Prepared, TextureMap};
use crate::pattern::Rgbft;

/// The colour a ray of unit direction `dir` sees where it meets nothing, under `sky` in
/// `scene` (whose textures hold the sky's) over `background`.
pub(crate) fn color(scene: &Prepared, sky: &Sky, dir: DVec3, background: Color) -> Color {
    let d = turned(dir, sky.rotation);
    let seen = match &scene.textures()[sky.texture.0 as usize] {
        TextureMap::Image(pic, _) => Rgbft::opaque(pic.nearest(lat_long(d))),
        TextureMap::Bilinear(pic, _) | TextureMap::NormalMap(pic, _) => {
            Rgbft::opaque(pic.bilinear(lat_long(d)))
        }
        // A direction has no footprint on the sky: the full-size picture.
        TextureMap::Mipmap(chain, _) => Rgbft::opaque(chain.level(0).bilinear(lat_long(d))),
        TextureMap::Pattern(pt) => pt.map.at(pt.field.eval(pt.to_pattern.transform_point3(d))),
        TextureMap::Checker(a, b, size) => {
            let c = (d / *size).floor();
            Rgbft::opaque(if (c.x + c.y + c.z).rem_euclid(2.0) < 0.5 {
                *a
            } else {
                *b
            })
        }
        TextureMap::Stripes(a, b, size) => {
            let even = (d.x / *size).floor().rem_euclid(2.0) < 0.5;
            Rgbft::opaque(if even { *a } else { *b })
        }
    };
    Rgbft {
        rgb: seen.rgb * sky.strength,
        ..seen
    }
    .over(Rgbft::opaque(background))
    .rgb
}

/// `dir` in the sky's own frame: the sky turned by `rotation` about +Y moves what it shows
/// counter-clockwise seen from above, so a direction meets the sky turned back by it.
fn turned(dir: DVec3, rotation: f64) -> DVec3 {
    if rotation == 0.0 {
        return dir;
    }
    let (s, c) = (libm::sin(-rotation), libm::cos(-rotation));
    DVec3::new(c * dir.x + s * dir.z, dir.y, -s * dir.x + c * dir.z)
}

/// The (u, v) of unit direction `d` on a latitude–longitude picture: u = ½ + longitude/2π with
/// longitude `atan2(x, −z)` (0 looking along −Z, π/2 along +X), v = ½ − latitude/π (0 at +Y):
/// the inverse of the equirectangular camera's mapping (`panorama.rs`) for a camera looking
/// along −Z with +Y up.
pub(crate) fn lat_long(d: DVec3) -> DVec2 {
    let lon = libm::atan2(d.x, -d.z);
    let lat = libm::asin(d.y.clamp(-1.0, 1.0));
    DVec2::new(
        0.5 + lon / std::f64::consts::TAU,
        0.5 - lat / std::f64::consts::PI,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The mapping is the equirectangular camera's inverse at a few directions.
    #[test]
    fn lat_long_matches_the_camera() {
        let close = |a: DVec2, b: DVec2| (a - b).abs().max_element() < 1e-12;
        assert!(close(lat_long(-DVec3::Z), DVec2::new(0.5, 0.5)));
        assert!(close(lat_long(DVec3::X), DVec2::new(0.75, 0.5)));
        assert!(close(lat_long(-DVec3::X), DVec2::new(0.25, 0.5)));
        // At the pole the longitude is any: only the row is fixed.
        assert!(lat_long(DVec3::Y).y.abs() < 1e-12);
        assert!(close(
            lat_long(DVec3::new(0.0, 1.0, -1e-9)),
            DVec2::new(0.5, 0.0)
        ));
    }

    /// Turned by 90° counter-clockwise seen from above, the sky shows along −Z what it showed
    /// along +X (a right-handed turn about +Y takes +X to −Z).
    #[test]
    fn rotation_turns_counter_clockwise() {
        let d = turned(-DVec3::Z, std::f64::consts::FRAC_PI_2);
        assert!((d - DVec3::X).abs().max_element() < 1e-12, "{d}");
    }
}
