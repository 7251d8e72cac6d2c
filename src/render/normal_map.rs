//! Tangent-space normal maps: a texel `c` encodes the normal `m = 2c − 1` in the surface's
//! tangent frame, x along increasing u, y up the picture (decreasing v), z out of the surface
//! (the OpenGL convention, which most tools bake by default). The frame comes from how the
//! surface point moves with (u, v): measured on the surface from the pixel's footprint
//! (`footprint`), so every shape and mapping gets its own; where that fails (a silhouette) the
//! bump maps' frame stands in (increasing longitude and latitude about +Y, exact on spheres).

use glam::{DMat2, DVec3};

use super::footprint;
use super::texture;
use crate::geometry::{MappingFrame, SurfaceHit};
use crate::ir::Mapping;
use crate::num::Norm;
use crate::opt::Prepared;
use crate::opt::textures::Picture;

/// How the surface point moves per unit of u and of v at `hit` (world space), from the
/// pixel's footprint: the two screen steps and the (u, v) they change, inverted. `None` at a
/// silhouette, a grazing view, or where (u, v) does not change across the pixel.
pub(crate) fn measured_tangents(
    scene: &Prepared,
    hit: &SurfaceHit,
    mapping: Mapping,
) -> Option<[DVec3; 2]> {
    let steps = footprint::surface_steps(scene.camera(), hit.point, hit.geometric_normal, 1.0)?;
    let [du, dv] = footprint::coordinate_steps(scene, hit, steps, |h| {
        texture::uv(mapping, h, scene.world().frame(h))
    })?;
    // Columns: (u, v) per screen step; its inverse gives screen steps per unit of u and v.
    let per_step = DMat2::from_cols(du, dv);
    if per_step.determinant().abs() < 1e-300 {
        return None;
    }
    let per_uv = per_step.inverse();
    let along = |c: glam::DVec2| steps[0] * c.x + steps[1] * c.y;
    let tangents = [along(per_uv.col(0)), along(per_uv.col(1))];
    tangents.iter().all(|t| t.is_finite()).then_some(tangents)
}

/// The normal `n` (unit, facing the viewer) replaced by normal map `pic`'s at `hit`, its
/// tangential part times `scale`, in the frame of `tangents` (dp/du, dp/dv); `n` itself where
/// the texel points into the surface or the frame degenerates.
pub(crate) fn tilt(
    pic: &Picture,
    mapping: Mapping,
    scale: f64,
    hit: &SurfaceHit,
    frame: MappingFrame,
    n: DVec3,
    tangents: [DVec3; 2],
) -> DVec3 {
    let m = 2.0 * pic.bilinear(texture::uv(mapping, hit, frame)) - DVec3::ONE;
    if m.z <= 0.0 {
        return n;
    }
    let [dpdu, dpdv] = tangents;
    let Some(t) = (dpdu - n.dot(dpdu) * n).try_unit() else {
        return n;
    };
    // Up the picture is against dp/dv; square to n and t, on dp/dv's side.
    let across = n.cross(t);
    let up = if across.dot(dpdv) > 0.0 {
        -across
    } else {
        across
    };
    (scale * (m.x * t + m.y * up) + m.z * n)
        .try_unit()
        .unwrap_or(n)
}

/// The bump maps' tangent frame at `n` as dp/du, dp/dv: increasing longitude and latitude
/// about +Y ([`tangent_frame`]).
pub(crate) fn fallback_tangents(n: DVec3) -> [DVec3; 2] {
    let (t, b) = tangent_frame(n);
    [t, b]
}

/// The tangent frame at unit normal `n`: T = normalize(+Y × N) (increasing longitude u on a
/// sphere; +X × N at the poles) and B = T × N (increasing v, southwards).
pub(crate) fn tangent_frame(n: DVec3) -> (DVec3, DVec3) {
    let up = if n.y.abs() > 0.999 {
        DVec3::X
    } else {
        DVec3::Y
    };
    let t = up.cross(n).unit();
    (t, t.cross(n))
}
