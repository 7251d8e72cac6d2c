//! Bump mapping: the gradient of a height field tilts the shading normal. Heights are the green
//! channel of an image (as the course framework's derivative accessor) or the luminance of a
//! procedural texture. The tangent frame is T = normalize(+Y × N) (the direction of increasing
//! longitude u on a sphere) and B = T × N (increasing v, i.e. southwards), so on spheres the
//! gradient follows the texture exactly; on other shapes it is an approximation.

use crate::num::Norm;
use glam::{DVec2, DVec3};

use super::texture;
use crate::geometry::{MappingFrame, SurfaceHit};
use crate::opt::TextureMap;

/// The normal `n` (unit, facing the viewer) tilted by the height field `tex` scaled by `scale`.
pub(crate) fn perturb(
    tex: &TextureMap,
    scale: f64,
    hit: &SurfaceHit,
    frame: MappingFrame,
    n: DVec3,
) -> DVec3 {
    let up = if n.y.abs() > 0.999 {
        DVec3::X
    } else {
        DVec3::Y
    };
    let t = up.cross(n).unit();
    let b = t.cross(n);
    let (dh_du, dh_dv) = match tex {
        TextureMap::Image(pic, mapping) => {
            let uv = texture::uv(*mapping, hit, frame);
            let (du, dv) = pic.texel_size();
            let h = |o: DVec2| pic.nearest(uv + o).y;
            let h0 = h(DVec2::ZERO);
            (
                (h(DVec2::new(du, 0.0)) - h0) / du,
                (h(DVec2::new(0.0, dv)) - h0) / dv,
            )
        }
        TextureMap::Checker(_, _, size) | TextureMap::Stripes(_, _, size) => {
            let step = size / 8.0;
            let lum = |p: DVec3| {
                let c = texture::solid(tex, hit, frame, p);
                (c.x + c.y + c.z) / 3.0
            };
            let h0 = lum(hit.local_point);
            (
                (lum(hit.local_point + step * t) - h0) / step,
                (lum(hit.local_point + step * b) - h0) / step,
            )
        }
    };
    if dh_du == 0.0 && dh_dv == 0.0 {
        return n;
    }
    let tilted = n - scale * (dh_du * t + dh_dv * b);
    tilted.try_unit().unwrap_or(n)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::world::primitive::SurfaceId;
    use crate::ir::{Mapping, MaterialId};
    use crate::opt::textures::Picture;

    const SPHERE: MappingFrame = MappingFrame::Sphere {
        center: DVec3::ZERO,
        radius: 1.0,
    };

    fn hit_at(n: DVec3) -> SurfaceHit {
        SurfaceHit {
            t: 1.0,
            point: n,
            normal: n,
            geometric_normal: n,
            uv: crate::geometry::ray::equirectangular_uv(n),
            local_point: n,
            surface_point: n,
            error: DVec3::ZERO,
            material: MaterialId(0),
            surface: SurfaceId(0),
        }
    }

    #[test]
    fn flat_height_keeps_the_normal_and_a_ramp_tilts_it() {
        let n = DVec3::new(1.0, 0.2, -0.3).unit();
        let flat = Picture::new(4, 4, vec![DVec3::splat(0.5); 16]).unwrap();
        let flat = TextureMap::Image(flat.into(), Mapping::Spherical);
        assert_eq!(perturb(&flat, 1.0, &hit_at(n), SPHERE, n), n);
        // Height grows with u (eastwards): the normal tilts westwards, against T.
        let ramp: Vec<DVec3> = (0..64)
            .map(|i| DVec3::splat(f64::from(i % 64) / 63.0))
            .collect();
        let ramp = TextureMap::Image(
            Picture::new(64, 1, ramp).unwrap().into(),
            Mapping::Spherical,
        );
        let tilted = perturb(&ramp, 0.01, &hit_at(n), SPHERE, n);
        let t = DVec3::Y.cross(n).unit();
        assert!((tilted.norm() - 1.0).abs() < 1e-12);
        assert!(tilted.dot(t) < 0.0);
    }
}
