//! Textures: images are decoded once before rendering; lookups are nearest-pixel as the course
//! framework does (COURSE.md §2.5); checker and stripes are solid textures in object space.

use std::sync::Arc;

use glam::{DVec2, DVec3};

use crate::assets::Picture;
use crate::diag::Diagnostic;
use crate::geometry::{SurfaceHit, sphere};
use crate::ir::{Color, Mapping, Scene, Shape, Texture};

/// A texture ready for lookups.
#[derive(Clone, Debug)]
pub enum Loaded {
    /// An image with its surface mapping.
    Image(Arc<Picture>, Mapping),
    /// A 3-D checkerboard.
    Checker(Color, Color, f64),
    /// Stripes along object-space x.
    Stripes(Color, Color, f64),
}

/// Decodes every texture of a scene once.
pub fn load_all(scene: &Scene) -> Result<Vec<Loaded>, Diagnostic> {
    scene.textures.iter().map(load).collect()
}

fn load(t: &Texture) -> Result<Loaded, Diagnostic> {
    Ok(match t {
        Texture::Image {
            path,
            mapping,
            span,
        } => {
            let pic = crate::assets::picture(path).map_err(|e| e.diagnostic(*span, path))?;
            Loaded::Image(pic, *mapping)
        }
        Texture::Checker { a, b, size } => Loaded::Checker(*a, *b, positive(*size)),
        Texture::Stripes { a, b, size } => Loaded::Stripes(*a, *b, positive(*size)),
    })
}

fn positive(size: f64) -> f64 {
    if size > 0.0 && size.is_finite() {
        size
    } else {
        1.0
    }
}

impl Loaded {
    /// The colour at a hit on an object of shape `shape`.
    pub fn color(&self, hit: &SurfaceHit, shape: &Shape) -> Color {
        match self {
            Loaded::Image(pic, mapping) => pic.nearest(uv(*mapping, hit, shape)),
            Loaded::Checker(a, b, size) => {
                // A hit on a cell face (a plane at y = 0) is ±1e-13 off it, so a plain floor
                // flips the parity pixel by pixel; snapping to a tiny fraction of a cell first
                // keeps the whole face in one cell.
                let q = hit.local_point / *size;
                let c = ((q * 1e6).round() / 1e6).floor();
                if (c.x + c.y + c.z).rem_euclid(2.0) < 0.5 {
                    *a
                } else {
                    *b
                }
            }
            Loaded::Stripes(a, b, size) => {
                if (hit.local_point.x / *size).floor().rem_euclid(2.0) < 0.5 {
                    *a
                } else {
                    *b
                }
            }
        }
    }
}

/// Surface coordinates of a hit under a mapping (object space; +Y is the north pole).
pub fn uv(mapping: Mapping, hit: &SurfaceHit, shape: &Shape) -> DVec2 {
    let centre = match shape {
        Shape::Sphere { center, .. } => *center,
        _ => DVec3::ZERO,
    };
    let p = hit.local_point - centre;
    match mapping {
        Mapping::Uv => hit.uv,
        Mapping::Spherical => {
            if matches!(shape, Shape::Sphere { .. }) {
                hit.uv
            } else {
                sphere::uv(p.try_normalize().unwrap_or(DVec3::Y))
            }
        }
        Mapping::Planar => DVec2::new(p.x - p.x.floor(), p.z - p.z.floor()),
        Mapping::Cylindrical => {
            let phi = (-p.z).atan2(p.x).rem_euclid(std::f64::consts::TAU);
            DVec2::new(phi / std::f64::consts::TAU, p.y - p.y.floor())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hit_at(p: DVec3) -> SurfaceHit {
        SurfaceHit {
            t: 1.0,
            point: p,
            normal: DVec3::Y,
            geometric_normal: DVec3::Y,
            uv: DVec2::ZERO,
            local_point: p,
            material: crate::ir::MaterialId(0),
            object: 0,
        }
    }

    #[test]
    fn checker_on_a_cell_face_does_not_speckle() {
        // Hits on a floor at y = 0 land a rounding error above or below it; both must give the
        // colour of one cell (the gallery floor showed salt-and-pepper before).
        let plane = Shape::Plane {
            point: DVec3::ZERO,
            normal: DVec3::Y,
        };
        let checker = Loaded::Checker(DVec3::X, DVec3::Z, 1.0);
        for x in [0.25, 1.5, -3.75, 123.5] {
            let above = checker.color(&hit_at(DVec3::new(x, 1e-13, 0.5)), &plane);
            let below = checker.color(&hit_at(DVec3::new(x, -1e-13, 0.5)), &plane);
            assert_eq!(above, below, "x = {x}");
        }
    }

    #[test]
    fn checker_and_stripes_alternate_in_object_space() {
        let (a, b) = (DVec3::X, DVec3::Z);
        let plane = Shape::Plane {
            point: DVec3::ZERO,
            normal: DVec3::Y,
        };
        let checker = Loaded::Checker(a, b, 2.0);
        assert_eq!(checker.color(&hit_at(DVec3::new(0.5, 0.5, 0.5)), &plane), a);
        assert_eq!(checker.color(&hit_at(DVec3::new(2.5, 0.5, 0.5)), &plane), b);
        assert_eq!(checker.color(&hit_at(DVec3::new(2.5, 2.5, 0.5)), &plane), a);
        assert_eq!(
            checker.color(&hit_at(DVec3::new(-0.5, 0.5, 0.5)), &plane),
            b
        );
        let stripes = Loaded::Stripes(a, b, 1.0);
        assert_eq!(
            stripes.color(&hit_at(DVec3::new(0.2, 9.0, -4.0)), &plane),
            a
        );
        assert_eq!(
            stripes.color(&hit_at(DVec3::new(1.2, 9.0, -4.0)), &plane),
            b
        );
        assert_eq!(
            stripes.color(&hit_at(DVec3::new(-0.2, 0.0, 0.0)), &plane),
            b
        );
    }
}
