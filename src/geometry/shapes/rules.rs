//! The rules that turn an IR shape into its intersectable [`Leaf`]: range checks that name the
//! parameter to blame, then the shape's constructor. One arm per shape.

use crate::num::Norm;

use glam::DVec3;

use crate::diag::number;
use crate::ir::{Shape, Spline, poly_terms};

use super::blob::Blob;
use super::cone::Cone;
use super::cuboid::Cuboid;
use super::cylinder::Cylinder;
use super::disk::Disk;
use super::flaw::{finite, in_range, positive, vec3};
use super::lathe::{Lathe, segment_count};
use super::parallelogram::Quad;
use super::poly::Poly;
use super::polygon::{Polygon, PolygonError};
use super::quadric::Quadric;
use super::ring::Ring;
use super::superellipsoid::Superellipsoid;
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
        } => {
            positive("major_radius", *major_radius)?;
            positive("minor_radius", *minor_radius)?;
            in_range(
                minor_radius < major_radius,
                "minor_radius",
                &format!("< major_radius ({})", number(*major_radius)),
                *minor_radius,
            )?;
            finite("center", &[*center])?;
            Leaf::Torus(
                Torus::new(*center, *major_radius, *minor_radius)
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
        Shape::Lathe { points, spline } => lathe(points, *spline)?,
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

/// A lathe's rules: enough points for its spline, each finite with `r >= 0`, and a profile
/// with some extent.
fn lathe(points: &[[f64; 2]], spline: Spline) -> Result<Leaf, ShapeFlaw> {
    let (least, what) = match spline {
        Spline::Linear => (2, "2 points"),
        Spline::Quadratic => (3, "3 points (the first only steers)"),
        Spline::Cubic => (4, "4 points (the first and last only steer)"),
        Spline::Bezier => (4, "4 points per segment"),
    };
    let name = spline.name();
    if points.len() < least || (spline == Spline::Bezier && !points.len().is_multiple_of(4)) {
        return Err(ShapeFlaw::other(
            "points",
            OUT_OF_RANGE,
            format!(
                "a `{name}` lathe needs at least {what}, found {}",
                points.len()
            ),
            format!("{} points", points.len()),
            if spline == Spline::Bezier {
                "give 4 points per Bézier segment (end, control, control, end)".to_owned()
            } else {
                format!("add points until there are at least {least}")
            },
        ));
    }
    for p in points {
        if !(p[0].is_finite() && p[1].is_finite()) {
            return Err(ShapeFlaw::other(
                "points",
                OUT_OF_RANGE,
                "a lathe point is not finite",
                "a coordinate is infinite or not a number",
                "use finite `[r, y]` pairs",
            ));
        }
        in_range(
            p[0] >= 0.0,
            "points",
            "r >= 0 (the profile is right of the axis)",
            p[0],
        )?;
    }
    debug_assert!(segment_count(spline, points.len()) > 0);
    Ok(Leaf::Lathe(Box::new(Lathe::new(points, spline).ok_or_else(
        || {
            ShapeFlaw::degenerate(
                "points",
                "the lathe's profile encloses no area",
                "its points lie on one line or on the axis",
                "move points away from the axis and off one line, e.g. `[[0, 0], [1, 0], [1, 1], [0, 1]]`",
            )
        },
    )?)))
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
