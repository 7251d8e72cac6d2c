//! Bump mapping: the gradient of a height field tilts the shading normal. Heights are the green
//! channel of an image (as the course framework's derivative accessor) or the luminance of a
//! procedural texture. The tangent frame is T = normalize(+Y × N) (the direction of increasing
//! longitude u on a sphere) and B = T × N (increasing v, i.e. southwards), so on spheres the
//! gradient follows the texture exactly; on other shapes it is an approximation.

use crate::num::Norm;
use glam::{DMat3, DVec2, DVec3};

use super::texture;
use crate::geometry::{MappingFrame, SurfaceHit};
use crate::ir::PatternSpace;
use crate::opt::{PreparedPattern, TextureMap};

/// The normal `n` (unit, facing the viewer) tilted by the height field `tex` scaled by `scale`;
/// `to_world` carries a gradient of the hit's object space to world space
/// (`World::normal_matrix`).
pub(crate) fn perturb(
    tex: &TextureMap,
    scale: f64,
    hit: &SurfaceHit,
    frame: MappingFrame,
    to_world: DMat3,
    n: DVec3,
) -> DVec3 {
    if let TextureMap::Pattern(pt) = tex
        && pt.space == PatternSpace::Object
    {
        let g = to_world * solid_gradient(pt, hit.local_point);
        return (n - scale * (g - g.dot(n) * n)).try_unit().unwrap_or(n);
    }
    let (t, b) = super::normal_map::tangent_frame(n);
    let (dh_du, dh_dv) = match tex {
        TextureMap::NormalMap(pic, mapping) => {
            let tangents = super::normal_map::fallback_tangents(n);
            return super::normal_map::tilt(pic, *mapping, scale, hit, frame, n, tangents);
        }
        TextureMap::Image(_, mapping)
        | TextureMap::Bilinear(_, mapping)
        | TextureMap::Mipmap(_, mapping) => {
            // A mip-mapped height field takes its slopes from the full-size picture.
            let (pic, bilinear) = match tex {
                TextureMap::Image(pic, _) => (&**pic, false),
                TextureMap::Bilinear(pic, _) => (&**pic, true),
                TextureMap::Mipmap(chain, _) => (chain.level(0), true),
                _ => unreachable!("an image texture"),
            };
            let uv = texture::uv(*mapping, hit, frame);
            let (du, dv) = pic.texel_size();
            let h = |o: DVec2| {
                if bilinear {
                    pic.bilinear(uv + o).y
                } else {
                    pic.nearest(uv + o).y
                }
            };
            let h0 = h(DVec2::ZERO);
            (
                (h(DVec2::new(du, 0.0)) - h0) / du,
                (h(DVec2::new(0.0, dv)) - h0) / dv,
            )
        }
        TextureMap::Pattern(pt) => {
            // A uv-space pattern: its value's slopes along u and v.
            let q = pt
                .to_pattern
                .transform_point3(DVec3::new(hit.uv.x, hit.uv.y, 0.0));
            if let Some(g) = pt.field.gradient(q, PATTERN_STEP) {
                let g = pt.to_pattern.matrix3.transpose() * g;
                return tilt(n, scale, g.x * t + g.y * b);
            }
            let h = |du: f64, dv: f64| {
                let q = DVec3::new(hit.uv.x + du, hit.uv.y + dv, 0.0);
                pt.field.eval(pt.to_pattern.transform_point3(q))
            };
            let d = PATTERN_STEP;
            (
                (h(d, 0.0) - h(-d, 0.0)) / (2.0 * d),
                (h(0.0, d) - h(0.0, -d)) / (2.0 * d),
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
    tilt(n, scale, dh_du * t + dh_dv * b)
}

/// `n` tilted against the height's slope `slope` (a tangent vector) by `scale`, unit; `n`
/// itself where the slope is zero or the tilt degenerates.
fn tilt(n: DVec3, scale: f64, slope: DVec3) -> DVec3 {
    if slope == DVec3::ZERO {
        return n;
    }
    (n - scale * slope).try_unit().unwrap_or(n)
}

/// The step of a pattern's finite differences, in the pattern's own space: POV-Ray's default
/// `accuracy` (0.02). Smaller steps follow the finest octaves more closely but turn a
/// pattern's edges (crackle's, brick's) into single-pixel spikes.
pub(crate) const PATTERN_STEP: f64 = 0.02;

/// The gradient of pattern `pt`'s value at object-space point `p`, in object space: the
/// pattern's own where it has one (`pattern::slopes`, octaves faded at [`PATTERN_STEP`]),
/// otherwise central differences of [`PATTERN_STEP`] along the pattern's own axes; carried back
/// through its transform (∇ₚ f(Tp) = Tᵀ ∇f).
pub(crate) fn solid_gradient(pt: &PreparedPattern, p: DVec3) -> DVec3 {
    let q = pt.to_pattern.transform_point3(p);
    if let Some(g) = pt.field.gradient(q, PATTERN_STEP) {
        return pt.to_pattern.matrix3.transpose() * g;
    }
    let d = PATTERN_STEP;
    let slope =
        |axis: DVec3| (pt.field.eval(q + d * axis) - pt.field.eval(q - d * axis)) / (2.0 * d);
    let g = DVec3::new(slope(DVec3::X), slope(DVec3::Y), slope(DVec3::Z));
    pt.to_pattern.matrix3.transpose() * g
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
            vertex_color: None,
        }
    }

    /// A placed noise pattern: wrinkles, rotated, stretched and moved.
    fn placed_noise() -> PreparedPattern {
        use glam::{DAffine3, DQuat};
        let place = DAffine3::from_scale_rotation_translation(
            DVec3::new(0.7, 1.3, 0.4),
            DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).unit(), 0.8),
            DVec3::new(0.3, -1.0, 2.0),
        );
        PreparedPattern::of(&crate::ir::PatternTexture {
            field: crate::pattern::Field::new(crate::pattern::Pattern::Bozo { seed: 3 }),
            placement: place,
            space: PatternSpace::Object,
            map: crate::pattern::ColorMap::grey(),
        })
    }

    #[test]
    fn a_pattern_gradient_matches_the_numerical_gradient_in_object_space() {
        // The analytic chain rule (Tᵀ ∇f) against central differences taken directly in object
        // space along object axes, at points where the smooth noise is well resolved: the two
        // differ by the finite-difference error of each, both O(h²).
        let pt = placed_noise();
        let value = |p: DVec3| pt.field.eval(pt.to_pattern.transform_point3(p));
        let mut rnd = crate::geometry::testing::test_uniform(5);
        for _ in 0..200 {
            let p = DVec3::new(rnd(), rnd(), rnd()) * 4.0 - 2.0;
            let h = 1e-5;
            let numeric = DVec3::new(
                (value(p + h * DVec3::X) - value(p - h * DVec3::X)) / (2.0 * h),
                (value(p + h * DVec3::Y) - value(p - h * DVec3::Y)) / (2.0 * h),
                (value(p + h * DVec3::Z) - value(p - h * DVec3::Z)) / (2.0 * h),
            );
            let ours = solid_gradient(&pt, p);
            let scale = numeric.norm().max(1.0);
            assert!(
                (ours - numeric).norm() < 0.05 * scale,
                "at {p}: {ours} vs {numeric}"
            );
        }
    }

    #[test]
    fn a_bump_pattern_tilts_against_the_world_gradient() {
        // An object scaled 2× along x: the world gradient is half the object one along x.
        let pt = placed_noise();
        let tex = TextureMap::Pattern(Box::new(pt.clone()));
        let n = DVec3::Z;
        let p = DVec3::new(0.2, 0.1, 0.0);
        let to_world = glam::DMat3::from_diagonal(DVec3::new(0.5, 1.0, 1.0));
        let mut hit = hit_at(n);
        hit.local_point = p;
        let tilted = perturb(&tex, 0.3, &hit, MappingFrame::Object, to_world, n);
        let g = to_world * solid_gradient(&pt, p);
        let want = (n - 0.3 * (g - g.dot(n) * n)).unit();
        assert!((tilted - want).norm() < 1e-15);
        assert!((tilted.norm() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn flat_height_keeps_the_normal_and_a_ramp_tilts_it() {
        let n = DVec3::new(1.0, 0.2, -0.3).unit();
        let flat = Picture::new(4, 4, vec![DVec3::splat(0.5); 16]).unwrap();
        let flat = TextureMap::Image(flat.into(), Mapping::Spherical);
        assert_eq!(
            perturb(&flat, 1.0, &hit_at(n), SPHERE, DMat3::IDENTITY, n),
            n
        );
        // Height grows with u (eastwards): the normal tilts westwards, against T.
        let ramp: Vec<DVec3> = (0..64)
            .map(|i| DVec3::splat(f64::from(i % 64) / 63.0))
            .collect();
        let ramp = TextureMap::Image(
            Picture::new(64, 1, ramp).unwrap().into(),
            Mapping::Spherical,
        );
        let tilted = perturb(&ramp, 0.01, &hit_at(n), SPHERE, DMat3::IDENTITY, n);
        let t = DVec3::Y.cross(n).unit();
        assert!((tilted.norm() - 1.0).abs() < 1e-12);
        assert!(tilted.dot(t) < 0.0);
    }
}
