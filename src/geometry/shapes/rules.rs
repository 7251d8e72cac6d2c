//! The rules that turn an IR shape into its intersectable [`Leaf`]: range checks that name the
//! parameter to blame, then the shape's constructor. One arm per shape.

use crate::num::Norm;

use glam::DVec3;

use crate::diag::number;
use crate::ir::{Shape, Spindle, poly_terms};

use super::bicubic::BicubicPatch;
use super::blob::Blob;
use super::cone::Cone;
use super::cuboid::Cuboid;
use super::cylinder::Cylinder;
use super::disk::Disk;
use super::flaw::{finite, in_range, positive, vec3};
use super::height_field::HeightField;
use super::parallelogram::Quad;
use super::poly::Poly;
use super::polygon::{Polygon, PolygonError};
use super::quadric::Quadric;
use super::ring::Ring;
use super::rules_outline::{lathe, prism_leaf};
use super::rules_sweep::{sor, sphere_sweep};
use super::superellipsoid::Superellipsoid;
use super::text;
use super::torus::Torus;
use super::triangle::Triangle;
use super::{DEGENERATE, Leaf, NOT_PLANAR, OUT_OF_RANGE, ShapeFlaw};

/// The intersectable form of a shape other than a mesh or a CSG node (which the preparation
/// stage assembles from loaded files and prepared operands), or its flaw.
pub(crate) fn leaf(shape: &Shape) -> Result<Leaf, ShapeFlaw> {
    Ok(match shape {
        Shape::Sphere { center, radius } => {
            positive("radius", *radius)?;
            finite("center", &[*center])?;
            Leaf::Sphere {
                center: *center,
                radius: *radius,
            }
        }
        Shape::Plane { point, normal } => {
            finite("point", &[*point])?;
            match normal.try_unit() {
                Some(normal) => Leaf::Plane {
                    point: *point,
                    normal,
                },
                None => {
                    return Err(ShapeFlaw::degenerate(
                        "normal",
                        "the plane's normal is the zero vector",
                        "a direction needs a non-zero length",
                        "give a direction, e.g. `normal: Y`",
                    ));
                }
            }
        }
        Shape::Box { min, max } => {
            finite("min", &[*min, *max])?;
            if !max.cmpgt(*min).all() {
                return Err(ShapeFlaw::other(
                    "max",
                    OUT_OF_RANGE,
                    "`max` must be greater than `min` on every axis",
                    format!("max = {} but min = {}", vec3(*max), vec3(*min)),
                    "swap the corners or fix the smaller coordinate",
                ));
            }
            Leaf::Box(Cuboid::new(*min, *max))
        }
        Shape::Triangle { vertices } => {
            finite("c", vertices)?;
            Leaf::Triangle(Box::new(Triangle::new(*vertices).ok_or_else(|| {
                ShapeFlaw::degenerate(
                    "c",
                    "the triangle has zero area",
                    "its corners lie on one line",
                    "move one corner off the line through the other two",
                )
            })?))
        }
        Shape::Quad { corner, u, v } => {
            finite("v", &[*corner, *u, *v])?;
            Leaf::Quad(Box::new(Quad::new(*corner, *u, *v).ok_or_else(|| {
                ShapeFlaw::degenerate(
                    "v",
                    "the quad has zero area",
                    "`u` and `v` are parallel or zero",
                    "use two edges that span a parallelogram",
                )
            })?))
        }
        Shape::Polygon { points } => {
            finite("points", points)?;
            Leaf::Polygon(Box::new(Polygon::new(points).map_err(|e| match e {
                PolygonError::TooFew => ShapeFlaw::other(
                    "points",
                    OUT_OF_RANGE,
                    format!("a polygon needs at least 3 points, found {}", points.len()),
                    "too few points",
                    "list three or more corners",
                ),
                PolygonError::Degenerate => ShapeFlaw::degenerate(
                    "points",
                    "the polygon encloses no area",
                    "its points lie on one line",
                    "spread the corners out in a plane",
                ),
                PolygonError::NotPlanar => ShapeFlaw::other(
                    "points",
                    NOT_PLANAR,
                    "the points of this polygon do not lie in one plane",
                    "non-planar polygon",
                    "split it into triangles, or move the points onto one plane",
                ),
            })?))
        }
        Shape::Disk {
            center,
            normal,
            radius,
        } => {
            positive("radius", *radius)?;
            finite("center", &[*center, *normal])?;
            Leaf::Disk(Disk::new(*center, *normal, *radius).ok_or_else(|| {
                ShapeFlaw::degenerate(
                    "normal",
                    "the disk's normal is the zero vector",
                    "a direction needs a non-zero length",
                    "give a direction, e.g. `normal: Y`",
                )
            })?)
        }
        Shape::Ring {
            center,
            normal,
            radius,
            inner,
        } => {
            positive("radius", *radius)?;
            finite("center", &[*center, *normal])?;
            if !(*inner >= 0.0 && *inner < *radius) {
                return Err(ShapeFlaw::degenerate(
                    "inner",
                    "the ring's hole is not smaller than the ring",
                    "a ring's `inner` radius must be at least 0 and less than its `radius`",
                    "make `inner` smaller than `radius` (0 gives a whole disk)",
                ));
            }
            Leaf::Ring(Ring::new(*center, *normal, *radius, *inner).ok_or_else(|| {
                ShapeFlaw::degenerate(
                    "normal",
                    "the ring's normal is the zero vector",
                    "a direction needs a non-zero length",
                    "give a direction, e.g. `normal: Y`",
                )
            })?)
        }
        Shape::Cylinder {
            base,
            top,
            radius,
            capped,
        } => {
            positive("radius", *radius)?;
            finite("top", &[*base, *top])?;
            Leaf::Cylinder(Box::new(
                Cylinder::new(*base, *top, *radius, *capped).ok_or_else(ends_coincide)?,
            ))
        }
        Shape::Cone {
            base,
            top,
            base_radius,
            top_radius,
            capped,
        } => {
            in_range(*base_radius >= 0.0, "base_radius", ">= 0", *base_radius)?;
            in_range(*top_radius >= 0.0, "top_radius", ">= 0", *top_radius)?;
            if *base_radius == 0.0 && *top_radius == 0.0 {
                return Err(ShapeFlaw::degenerate(
                    "base_radius",
                    "a cone needs a non-zero radius at one end",
                    "both radii are 0",
                    "set `base_radius` greater than 0",
                ));
            }
            finite("top", &[*base, *top])?;
            Leaf::Cone(Box::new(
                Cone::new(*base, *top, *base_radius, *top_radius, *capped)
                    .ok_or_else(ends_coincide)?,
            ))
        }
        Shape::Torus {
            center,
            major_radius,
            minor_radius,
            spindle,
        } => {
            positive("major_radius", *major_radius)?;
            positive("minor_radius", *minor_radius)?;
            // POV-Ray's rule: only the spindle's own mode is empty on a ring torus.
            in_range(
                *spindle != Spindle::Intersection || minor_radius > major_radius,
                "spindle",
                &format!(
                    "\"intersection\" only with minor_radius > major_radius ({})",
                    number(*major_radius)
                ),
                *minor_radius,
            )?;
            finite("center", &[*center])?;
            Leaf::Torus(
                Torus::new(*center, *major_radius, *minor_radius, *spindle)
                    .ok_or_else(|| ShapeFlaw::range("major_radius", "> 0", *major_radius))?,
            )
        }
        Shape::Blob {
            components,
            threshold,
        } => {
            if components.is_empty() {
                return Err(ShapeFlaw::other(
                    "components",
                    OUT_OF_RANGE,
                    "a blob needs at least one component",
                    "empty list",
                    "add `{ center: [0, 0, 0], radius: 1, strength: 1 }`",
                ));
            }
            for c in components {
                positive("radius", c.radius)?;
                in_range(true, "strength", "finite", c.strength)?;
                finite("components", &[c.center])?;
                if let Some(end) = c.end {
                    finite("end", &[end])?;
                }
            }
            positive("threshold", *threshold)?;
            Leaf::Blob(Box::new(Blob::new(components, *threshold).ok_or_else(
                || {
                    ShapeFlaw::degenerate(
                        "components",
                        "the blob has no surface",
                        "no component has a positive strength",
                        "give at least one component a positive `strength`",
                    )
                },
            )?))
        }
        Shape::Quadric {
            squares,
            mixed,
            linear,
            constant,
        } => {
            finite("squares", &[*squares])?;
            finite("mixed", &[*mixed])?;
            finite("linear", &[*linear])?;
            in_range(constant.is_finite(), "constant", "finite", *constant)?;
            if *squares == DVec3::ZERO && *mixed == DVec3::ZERO && *linear == DVec3::ZERO {
                return Err(ShapeFlaw::degenerate(
                    "squares",
                    "a quadric needs a non-zero coefficient besides the constant",
                    "every coefficient of x, y and z is 0",
                    "give `squares`, `mixed` or `linear` a non-zero entry",
                ));
            }
            Leaf::Quadric(Box::new(Quadric {
                squares: *squares,
                mixed: *mixed,
                linear: *linear,
                constant: *constant,
            }))
        }
        Shape::Prism {
            points,
            heights,
            spline,
            sweep,
        } => Leaf::Extrusion(Box::new(prism_leaf(points, *heights, *spline, *sweep)?)),
        Shape::Text {
            thickness, glyphs, ..
        } => {
            positive("thickness", *thickness)?;
            Leaf::Extrusion(Box::new(text::build(glyphs, *thickness).ok_or_else(
                || {
                    ShapeFlaw::degenerate(
                        "string",
                        "the text has no glyph with an outline",
                        "only spaces, or glyphs the font draws empty",
                        "give a string with at least one visible character",
                    )
                },
            )?))
        }
        Shape::Lathe { points, spline } => Leaf::Lathe(Box::new(lathe(points, *spline)?)),
        Shape::Sor { points, open } => sor(points, *open)?,
        Shape::SphereSweep { spline, spheres } => sphere_sweep(*spline, spheres)?,
        Shape::Superellipsoid { e, n } => {
            for (name, v) in [("e", *e), ("n", *n)] {
                in_range((0.001..=10.0).contains(&v), name, "in 0.001..=10", v)?;
            }
            Leaf::Superellipsoid(
                Superellipsoid::new(*e, *n).ok_or_else(|| ShapeFlaw::range("e", "> 0", *e))?,
            )
        }
        Shape::Poly {
            order,
            coefficients,
        } => poly(*order, coefficients)?,
        Shape::Isosurface {
            function,
            container,
            threshold,
            max_gradient,
            accuracy,
            open,
        } => Leaf::Isosurface(Box::new(super::isosurface::build(
            function,
            container,
            *threshold,
            *max_gradient,
            *accuracy,
            *open,
        )?)),
        Shape::HeightField {
            heights,
            smooth,
            water_level,
            ..
        } => height_field(heights, *smooth, *water_level)?,
        Shape::BicubicPatch { points } => {
            finite("points", points.as_flattened())?;
            Leaf::Bicubic(Box::new(BicubicPatch::new(**points).ok_or_else(|| {
                ShapeFlaw::degenerate(
                    "points",
                    "the bicubic patch has no area",
                    "its points lie on one line, or every row is the same curve",
                    "move the rows apart, e.g. rows at z = 0, 1, 2, 3",
                )
            })?))
        }
        Shape::Mesh { .. } | Shape::Csg { .. } => {
            return Err(ShapeFlaw::other(
                "shape",
                DEGENERATE,
                format!("a {} is not a single shape", shape.kind_name()),
                "assembled from its parts",
                "build it through the preparation stage",
            ));
        }
    })
}

fn ends_coincide() -> ShapeFlaw {
    ShapeFlaw::degenerate(
        "top",
        "`top` equals `base`",
        "zero height",
        "move `top` away from `base`",
    )
}

/// A polynomial surface's rules: an order from 2 to 15, one finite coefficient per term, and
/// a non-zero one besides the constant.
fn poly(order: u32, coefficients: &[f64]) -> Result<Leaf, ShapeFlaw> {
    in_range(
        (2..=15).contains(&order),
        "order",
        "in 2..=15",
        f64::from(order),
    )?;
    let terms = poly_terms(order);
    if coefficients.len() != terms.len() {
        return Err(ShapeFlaw::other(
            "coefficients",
            OUT_OF_RANGE,
            format!(
                "a poly of order {order} has {} coefficients, found {}",
                terms.len(),
                coefficients.len()
            ),
            format!("{} coefficients", coefficients.len()),
            format!(
                "list all {} coefficients, 0 for absent terms (x^{order} first, the constant last)",
                terms.len()
            ),
        ));
    }
    for &c in coefficients {
        in_range(true, "coefficients", "finite", c)?;
    }
    Ok(Leaf::Poly(Box::new(
        Poly::new(order as usize, &terms, coefficients).ok_or_else(|| {
            ShapeFlaw::degenerate(
                "coefficients",
                "a poly needs a non-zero coefficient besides the constant",
                "every coefficient of a term in x, y or z is 0",
                "give a term in x, y or z a non-zero coefficient",
            )
        })?,
    )))
}

/// A height field's rules: at least 2 × 2 points and no more than the budget, one height in
/// [0, 1] per point, a finite water level.
fn height_field(
    grid: &crate::ir::HeightGrid,
    smooth: bool,
    water_level: f64,
) -> Result<Leaf, ShapeFlaw> {
    let (nx, nz) = (grid.nx, grid.nz);
    if nx < 2 || nz < 2 {
        return Err(ShapeFlaw::degenerate(
            "heights",
            &format!("a height field needs at least 2 × 2 points, found {nx} × {nz}"),
            "one point has no cell to make triangles of",
            "use an image (or `resolution`) of at least 2 × 2 points",
        ));
    }
    let points = nx as u64 * nz as u64;
    let max = crate::ir::limits::MAX_HEIGHT_FIELD_POINTS;
    if points > max {
        return Err(ShapeFlaw::other(
            "heights",
            OUT_OF_RANGE,
            format!(
                "a height field of {nx} × {nz} = {points} points is larger than the {max} allowed"
            ),
            "too many points",
            "use an image (or `resolution`) of at most 4096 × 4096 points",
        ));
    }
    if grid.heights.len() as u64 != points {
        return Err(ShapeFlaw::other(
            "heights",
            OUT_OF_RANGE,
            format!(
                "a height field of {nx} × {nz} points has {} heights",
                grid.heights.len()
            ),
            "the rows differ in length",
            format!("give {nz} rows of {nx} heights each"),
        ));
    }
    for &h in grid.heights.iter() {
        in_range(
            (0.0..=1.0).contains(&h),
            "heights",
            "in 0..=1",
            f64::from(h),
        )?;
    }
    in_range(true, "water_level", "finite", water_level)?;
    HeightField::new(nx, nz, grid.heights.clone(), smooth, water_level)
        .map(|h| Leaf::HeightField(Box::new(h)))
        .ok_or_else(|| ShapeFlaw::range("heights", "in 0..=1", f64::NAN))
}
