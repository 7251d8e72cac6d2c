//! Texture lookups at a hit: images nearest-pixel as the course framework does (COURSE.md
//! §2.5) through a surface mapping; checker, stripes and patterns are solid textures in object
//! space (a pattern may read the surface's uv instead).
//! Every coordinate comes from the hit (its uv, its object-space point and its mapping frame),
//! so a lookup never needs the shape.

use glam::{DVec2, DVec3};

use super::footprint;
use crate::geometry::{MappingFrame, SurfaceHit};
use crate::ir::Sampling;
use crate::ir::{Color, Mapping, PatternSpace};
use crate::num::Norm;
use crate::opt::textures::MipChain;
use crate::opt::{Prepared, PreparedPattern, TextureMap};
use crate::pattern::Rgbft;

/// The colour of `tex` at `hit`, whose surface's mapping frame is `frame` (`World::frame`).
pub(crate) fn color(tex: &TextureMap, hit: &SurfaceHit, frame: MappingFrame) -> Color {
    solid(tex, hit, frame, hit.local_point)
}

/// The colour of `tex` at `hit`, with solid textures read at object-space point `p` (bump
/// mapping reads them at points near the hit).
pub(crate) fn solid(tex: &TextureMap, hit: &SurfaceHit, frame: MappingFrame, p: DVec3) -> Color {
    match tex {
        TextureMap::Image(pic, mapping) => pic.nearest(uv(*mapping, hit, frame)),
        TextureMap::Bilinear(pic, mapping) | TextureMap::NormalMap(pic, mapping) => {
            pic.bilinear(uv(*mapping, hit, frame))
        }
        // Without a footprint (a bump's neighbour, an explanation): the full-size picture.
        TextureMap::Mipmap(chain, mapping) => chain.level(0).bilinear(uv(*mapping, hit, frame)),
        TextureMap::Checker(a, b, size) => {
            // A hit on a cell face (a plane at y = 0) is ±1e-13 off it, so a plain floor flips
            // the parity pixel by pixel; snapping to a tiny fraction of a cell first keeps the
            // whole face in one cell.
            let q = p / *size;
            let c = ((q * 1e6).round() / 1e6).floor();
            if (c.x + c.y + c.z).rem_euclid(2.0) < 0.5 {
                *a
            } else {
                *b
            }
        }
        TextureMap::Stripes(a, b, size) => {
            if (p.x / *size).floor().rem_euclid(2.0) < 0.5 {
                *a
            } else {
                *b
            }
        }
        TextureMap::Pattern(pt) => pt.map.at(pattern_value(pt, hit, p)).rgb,
    }
}

/// The colour of mip-mapped image `chain` at `hit` under `mapping`: trilinear over the
/// footprint of one sample (a pixel over the supersampling factor, at most eight per axis, as
/// pbrt-v4 scales it) measured in the picture's texels along the wider of the pixel's two
/// screen steps; the full-size picture where no footprint is found (a silhouette, a grazing
/// view).
pub(crate) fn mipmapped(
    scene: &Prepared,
    chain: &MipChain,
    mapping: Mapping,
    hit: &SurfaceHit,
    frame: MappingFrame,
) -> Color {
    let fraction = match scene.settings().sampling {
        Sampling::Grid { factor } => 1.0 / f64::from(factor.clamp(1, 8)),
        Sampling::Adaptive { min, .. } => 1.0 / f64::from(min.clamp(1, 8)),
    };
    let (w, h) = chain.level(0).size();
    let texels = DVec2::new(f64::from(w), f64::from(h));
    let footprint =
        footprint::surface_steps(scene.camera(), hit.point, hit.geometric_normal, fraction)
            .and_then(|steps| {
                footprint::coordinate_steps(scene, hit, steps, |h| {
                    uv(mapping, h, scene.world().frame(h))
                })
            })
            .map_or(1.0, |[dx, dy]| {
                (dx * texels).norm().max((dy * texels).norm())
            });
    chain.lookup(uv(mapping, hit, frame), footprint)
}

/// The colour of `tex` at `hit` with its filter and transmit (opaque but for patterns whose
/// colour map says otherwise): what a layer shows of the layers below.
pub(crate) fn rgbft(tex: &TextureMap, hit: &SurfaceHit, frame: MappingFrame) -> Rgbft {
    match tex {
        TextureMap::Pattern(pt) => pt.map.at(pattern_value(pt, hit, hit.local_point)),
        _ => Rgbft::opaque(color(tex, hit, frame)),
    }
}

/// The value of pattern texture `pt` at `hit`, reading object-space point `p` (or the hit's uv
/// for a uv-space pattern): the number its colour map reads.
#[inline]
pub(crate) fn pattern_value(pt: &PreparedPattern, hit: &SurfaceHit, p: DVec3) -> f64 {
    pt.field
        .eval(pt.to_pattern.transform_point3(pattern_point(pt, hit, p)))
}

/// The point a pattern reads before its own transform: `p`, or (u, v, 0) in uv space.
#[inline]
fn pattern_point(pt: &PreparedPattern, hit: &SurfaceHit, p: DVec3) -> DVec3 {
    match pt.space {
        PatternSpace::Object => p,
        PatternSpace::Uv => DVec3::new(hit.uv.x, hit.uv.y, 0.0),
    }
}

/// Surface coordinates of a hit under a mapping, in its surface's mapping `frame` (+Y is the
/// north pole).
pub(crate) fn uv(mapping: Mapping, hit: &SurfaceHit, frame: MappingFrame) -> DVec2 {
    let p = frame.point(hit.local_point);
    match mapping {
        Mapping::Uv => hit.uv,
        Mapping::Spherical => frame.spherical_uv(hit.local_point),
        Mapping::Planar => DVec2::new(p.x - p.x.floor(), p.z - p.z.floor()),
        Mapping::Cylindrical => {
            let phi = libm::atan2(-p.z, p.x).rem_euclid(std::f64::consts::TAU);
            DVec2::new(phi / std::f64::consts::TAU, p.y - p.y.floor())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::world::primitive::SurfaceId;

    fn hit_at(p: DVec3) -> SurfaceHit {
        SurfaceHit {
            t: 1.0,
            point: p,
            normal: DVec3::Y,
            geometric_normal: DVec3::Y,
            uv: DVec2::ZERO,
            local_point: p,
            surface_point: p,
            error: DVec3::ZERO,
            material: crate::ir::MaterialId(0),
            surface: SurfaceId(0),
            vertex_color: None,
        }
    }

    fn at(tex: &TextureMap, hit: &SurfaceHit) -> Color {
        color(tex, hit, MappingFrame::Object)
    }

    #[test]
    fn checker_on_a_cell_face_does_not_speckle() {
        // Hits on a floor at y = 0 land a rounding error above or below it; both must give the
        // colour of one cell (the gallery floor showed salt-and-pepper before).
        let checker = TextureMap::Checker(DVec3::X, DVec3::Z, 1.0);
        for x in [0.25, 1.5, -3.75, 123.5] {
            let above = at(&checker, &hit_at(DVec3::new(x, 1e-13, 0.5)));
            let below = at(&checker, &hit_at(DVec3::new(x, -1e-13, 0.5)));
            assert_eq!(above, below, "x = {x}");
        }
    }

    #[test]
    fn checker_and_stripes_alternate_in_object_space() {
        let (a, b) = (DVec3::X, DVec3::Z);
        let checker = TextureMap::Checker(a, b, 2.0);
        assert_eq!(at(&checker, &hit_at(DVec3::new(0.5, 0.5, 0.5))), a);
        assert_eq!(at(&checker, &hit_at(DVec3::new(2.5, 0.5, 0.5))), b);
        assert_eq!(at(&checker, &hit_at(DVec3::new(2.5, 2.5, 0.5))), a);
        assert_eq!(at(&checker, &hit_at(DVec3::new(-0.5, 0.5, 0.5))), b);
        let stripes = TextureMap::Stripes(a, b, 1.0);
        assert_eq!(at(&stripes, &hit_at(DVec3::new(0.2, 9.0, -4.0))), a);
        assert_eq!(at(&stripes, &hit_at(DVec3::new(1.2, 9.0, -4.0))), b);
        assert_eq!(at(&stripes, &hit_at(DVec3::new(-0.2, 0.0, 0.0))), b);
    }

    #[test]
    fn mappings_read_a_sphere_about_its_own_centre() {
        // The same point of a sphere centred at c, as a hit framed by that sphere: every
        // mapping sees it relative to c (a sphere inside a CSG node used to map about the
        // origin).
        let c = DVec3::new(5.0, -2.0, 1.0);
        let on = DVec3::new(0.0, 0.0, -1.0);
        let framed = MappingFrame::Sphere {
            center: c,
            radius: 1.0,
        };
        let at_origin = MappingFrame::Sphere {
            center: DVec3::ZERO,
            radius: 1.0,
        };
        for m in [Mapping::Spherical, Mapping::Planar, Mapping::Cylindrical] {
            let (a, b) = (hit_at(c + on), hit_at(on));
            assert_eq!(uv(m, &a, framed), uv(m, &b, at_origin), "{m:?}");
        }
    }
}
