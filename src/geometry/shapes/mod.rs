//! Every single shape in one place: whether an IR shape can be drawn, its intersectable form
//! ([`Leaf`]) and what that answers (bounds, hits, crossings, membership). This is the one home
//! of a shape's validity and bounds: the scene language checks each shape here as it is made,
//! the course front ends as they read it, and the preparation stage builds its [`Leaf`] through
//! [`leaf`]; `.bounds` in the language and the world's BVH boxes both come from
//! [`Leaf::bounds`] (and [`crate::geometry::shapes::csg::bounds`] for CSG). Adding a shape: its file here
//! and its `pub mod` line above, a `Leaf` variant with its arms below, its rule in [`leaf`] (`rules.rs`).
//!
//! Diagnostic codes (one set for every front end): `rtc::param::out_of_range` (a number outside
//! its range, value shown), `rtc::param::degenerate` (a shape with no surface),
//! `rtc::param::not_planar` (a polygon off its plane), `rtc::csg::operands` (a CSG node with
//! fewer than two operands).

mod bicubic;
mod blob;
mod bracket;
pub(crate) mod circle_quadratic;
mod cone;
pub(crate) mod csg;
mod cuboid;
mod cylinder;
mod disk;
pub(crate) mod extrusion;
mod height_field;
mod height_field_walk;
pub(crate) mod isosurface;
mod lathe;
mod parallelogram;
pub(crate) mod plane;
mod poly;
mod polygon;
mod prism;
mod quadric;
mod quartic;
mod ring;
mod sor;
pub(crate) mod sphere;
mod sphere_sweep;
mod superellipsoid;
mod text;
mod torus;
pub(crate) mod triangle;

use glam::DVec3;

use crate::geometry::shapes::bicubic::BicubicPatch;
use crate::geometry::shapes::blob::Blob;
use crate::geometry::shapes::cone::Cone;
use crate::geometry::shapes::cuboid::Cuboid;
use crate::geometry::shapes::cylinder::Cylinder;
use crate::geometry::shapes::disk::Disk;
use crate::geometry::shapes::extrusion::Extrusion;
use crate::geometry::shapes::height_field::HeightField;
use crate::geometry::shapes::isosurface::Isosurface;
use crate::geometry::shapes::lathe::Lathe;
use crate::geometry::shapes::parallelogram::Quad;
use crate::geometry::shapes::poly::Poly;
use crate::geometry::shapes::polygon::Polygon;
use crate::geometry::shapes::quadric::Quadric;
use crate::geometry::shapes::ring::Ring;
use crate::geometry::shapes::sor::Sor;
use crate::geometry::shapes::sphere_sweep::SphereSweep;
use crate::geometry::shapes::superellipsoid::Superellipsoid;
use crate::geometry::shapes::torus::Torus;
use crate::geometry::shapes::triangle::Triangle;
use crate::geometry::{aabb::Aabb, ray::Crossing, ray::Hit, ray::MappingFrame, ray::Ray};
use crate::ir::{CsgOp, Shape};

mod flaw;
mod rules;
mod rules_outline;
mod rules_sweep;

pub(crate) use flaw::{CSG_OPERANDS, DEGENERATE, NOT_PLANAR, OUT_OF_RANGE, ShapeFlaw};
pub(crate) use rules::leaf;

/// Whether `shape` can be drawn: `Ok` for every valid shape, a mesh (its file is checked when
/// it is loaded) and a CSG node with at least two operands (its operands are checked as shapes
/// of their own).
pub(crate) fn check(shape: &Shape) -> Result<(), ShapeFlaw> {
    match shape {
        Shape::Mesh { .. } => Ok(()),
        Shape::Csg {
            op: CsgOp::Inverse,
            children,
        } => operand_count(
            children.len(),
            1,
            "an inverse turns exactly one solid inside out",
        ),
        Shape::Csg {
            op: CsgOp::Clip,
            children,
        } => operand_count(
            children.len(),
            2,
            "a clip has one surface and one clipping solid",
        ),
        Shape::Csg { children, .. } => csg_operands(children.len()),
        // A valid sphere, the commonest shape of large scenes (checked when it is made and again
        // when it is prepared), without building its `Leaf`: `leaf` accepts exactly these.
        Shape::Sphere { center, radius }
            if *radius > 0.0 && radius.is_finite() && center.is_finite() =>
        {
            Ok(())
        }
        leaf_shape => leaf(leaf_shape).map(|_| ()),
    }
}

/// A single shape's geometry in object space: every shape but meshes and CSG nodes. Shapes
/// larger than a box are boxed, so a million spheres do not each take a polygon's room.
#[derive(Clone, Debug)]
pub(crate) enum Leaf {
    /// A sphere.
    Sphere {
        /// Centre.
        center: DVec3,
        /// Radius.
        radius: f64,
    },
    /// A half-space bounded by a plane.
    Plane {
        /// A point on it.
        point: DVec3,
        /// Unit outward normal.
        normal: DVec3,
    },
    /// A box.
    Box(Cuboid),
    /// A triangle.
    Triangle(Box<Triangle>),
    /// A parallelogram.
    Quad(Box<Quad>),
    /// A planar polygon.
    Polygon(Box<Polygon>),
    /// A disk.
    Disk(Disk),
    /// A flat ring.
    Ring(Ring),
    /// A cylinder.
    Cylinder(Box<Cylinder>),
    /// A cone or frustum.
    Cone(Box<Cone>),
    /// A torus.
    Torus(Torus),
    /// Metaballs.
    Blob(Box<Blob>),
    /// A quadric surface.
    Quadric(Box<Quadric>),
    /// A swept outline: a prism or a text.
    Extrusion(Box<Extrusion>),
    /// A lathe.
    Lathe(Box<Lathe>),
    /// A surface of revolution.
    Sor(Box<Sor>),
    /// A sphere sweep.
    SphereSweep(Box<SphereSweep>),
    /// A superellipsoid.
    Superellipsoid(Superellipsoid),
    /// An algebraic surface.
    Poly(Box<Poly>),
    /// An isosurface of a compiled function.
    Isosurface(Box<Isosurface>),
    /// A height field.
    HeightField(Box<HeightField>),
    /// A bicubic Bézier patch.
    Bicubic(Box<BicubicPatch>),
}

impl Leaf {
    /// Object-space bounds (infinite for a plane).
    pub(crate) fn bounds(&self) -> Aabb {
        match self {
            Leaf::Sphere { center, radius } => sphere::bounds(*center, *radius),
            Leaf::Plane { .. } => Aabb::new(DVec3::NEG_INFINITY, DVec3::INFINITY),
            Leaf::Box(b) => b.bounds(),
            Leaf::Triangle(x) => x.bounds(),
            Leaf::Quad(x) => x.bounds(),
            Leaf::Polygon(x) => x.bounds(),
            Leaf::Disk(x) => x.bounds(),
            Leaf::Ring(x) => x.bounds(),
            Leaf::Cylinder(x) => x.bounds(),
            Leaf::Cone(x) => x.bounds(),
            Leaf::Torus(x) => x.bounds(),
            Leaf::Blob(x) => x.bounds(),
            Leaf::Quadric(x) => x.bounds(),
            Leaf::Extrusion(x) => x.bounds(),
            Leaf::Lathe(x) => x.bounds(),
            Leaf::Sor(x) => x.bounds(),
            Leaf::SphereSweep(x) => x.bounds(),
            Leaf::Superellipsoid(x) => x.bounds(),
            Leaf::Poly(x) => x.bounds(),
            Leaf::Isosurface(x) => x.bounds(),
            Leaf::HeightField(x) => x.bounds(),
            Leaf::Bicubic(x) => x.bounds(),
        }
    }

    /// Nearest hit in (t_min, t_max), in object space.
    #[inline]
    pub(crate) fn intersect(&self, r: &Ray, t_min: f64, t_max: f64) -> Option<Hit> {
        match self {
            Leaf::Sphere { center, radius } => sphere::intersect(*center, *radius, r, t_min, t_max),
            Leaf::Plane { point, normal } => plane::intersect(*point, *normal, r, t_min, t_max),
            Leaf::Box(b) => b.intersect(r, t_min, t_max),
            Leaf::Triangle(x) => x.intersect(r, t_min, t_max),
            Leaf::Quad(x) => x.intersect(r, t_min, t_max),
            Leaf::Polygon(x) => x.intersect(r, t_min, t_max),
            Leaf::Disk(x) => x.intersect(r, t_min, t_max),
            Leaf::Ring(x) => x.intersect(r, t_min, t_max),
            Leaf::Cylinder(x) => x.intersect(r, t_min, t_max),
            Leaf::Cone(x) => x.intersect(r, t_min, t_max),
            Leaf::Torus(x) => x.intersect(r, t_min, t_max),
            Leaf::Blob(x) => x.intersect(r, t_min, t_max),
            Leaf::Quadric(x) => x.intersect(r, t_min, t_max),
            Leaf::Extrusion(x) => x.intersect(r, t_min, t_max),
            Leaf::Lathe(x) => x.intersect(r, t_min, t_max),
            Leaf::Sor(x) => x.intersect(r, t_min, t_max),
            Leaf::SphereSweep(x) => x.intersect(r, t_min, t_max),
            Leaf::Superellipsoid(x) => x.intersect(r, t_min, t_max),
            Leaf::Poly(x) => x.intersect(r, t_min, t_max),
            Leaf::Isosurface(x) => x.intersect(r, t_min, t_max),
            Leaf::HeightField(x) => x.intersect(r, t_min, t_max),
            Leaf::Bicubic(x) => x.intersect(r, t_min, t_max),
        }
    }

    /// A per-axis bound on how far the computed object-space point `p` of a hit may lie from
    /// the surface (see [`crate::geometry::rounding`]).
    pub(crate) fn point_error(&self, p: DVec3) -> DVec3 {
        match self {
            Leaf::Sphere { center, radius } => sphere::point_error(*center, *radius, p),
            Leaf::Plane { point, normal } => plane::point_error(*point, *normal, p),
            Leaf::Box(b) => b.point_error(p),
            Leaf::Triangle(x) => x.point_error(p),
            Leaf::Quad(x) => x.point_error(p),
            Leaf::Polygon(x) => x.point_error(p),
            Leaf::Disk(x) => x.point_error(p),
            Leaf::Ring(x) => x.point_error(p),
            Leaf::Cylinder(x) => x.point_error(p),
            Leaf::Cone(x) => x.point_error(p),
            Leaf::Torus(x) => x.point_error(p),
            Leaf::Blob(x) => x.point_error(p),
            Leaf::Quadric(x) => x.point_error(p),
            Leaf::Extrusion(x) => x.point_error(p),
            Leaf::Lathe(x) => x.point_error(p),
            Leaf::Sor(x) => x.point_error(p),
            Leaf::SphereSweep(x) => x.point_error(p),
            Leaf::Superellipsoid(x) => x.point_error(p),
            Leaf::Poly(x) => x.point_error(p),
            Leaf::Isosurface(x) => x.point_error(p),
            Leaf::HeightField(x) => x.point_error(p),
            Leaf::Bicubic(x) => x.point_error(p),
        }
    }

    /// Every boundary crossing along the whole line of `r` (solids; surfaces have none).
    pub(crate) fn crossings(&self, r: &Ray, out: &mut Vec<Crossing>) {
        match self {
            Leaf::Sphere { center, radius } => sphere::crossings(*center, *radius, r, out),
            Leaf::Plane { point, normal } => {
                if let Some(h) =
                    plane::intersect(*point, *normal, r, f64::NEG_INFINITY, f64::INFINITY)
                {
                    out.push(Crossing {
                        hit: h,
                        entering: normal.dot(r.dir) < 0.0,
                    });
                }
            }
            Leaf::Box(b) => b.crossings(r, out),
            Leaf::Cylinder(x) => x.crossings(r, out),
            Leaf::Cone(x) => x.crossings(r, out),
            Leaf::Torus(x) => x.crossings(r, out),
            Leaf::Blob(x) => x.crossings(r, out),
            Leaf::Quadric(x) => x.crossings(r, out),
            Leaf::Extrusion(x) => x.crossings(r, out),
            Leaf::Lathe(x) => x.crossings(r, out),
            Leaf::Sor(x) => x.crossings(r, out),
            Leaf::SphereSweep(x) => x.crossings(r, out),
            Leaf::Superellipsoid(x) => x.crossings(r, out),
            Leaf::Poly(x) => x.crossings(r, out),
            Leaf::Isosurface(x) => x.crossings(r, out),
            Leaf::HeightField(x) => x.crossings(r, out),
            Leaf::Triangle(_)
            | Leaf::Quad(_)
            | Leaf::Polygon(_)
            | Leaf::Disk(_)
            | Leaf::Ring(_)
            | Leaf::Bicubic(_) => {}
        }
    }

    /// Point membership in object space (closed solids; surfaces, an open sor included, contain nothing).
    pub(crate) fn contains(&self, q: DVec3) -> bool {
        match self {
            Leaf::Sphere { center, radius } => sphere::contains(*center, *radius, q),
            Leaf::Plane { point, normal } => (q - *point).dot(*normal) <= 0.0,
            Leaf::Box(b) => b.contains(q),
            Leaf::Cylinder(c) => c.is_closed() && c.contains(q),
            Leaf::Cone(c) => c.is_closed() && c.contains(q),
            Leaf::Torus(t) => t.contains(q),
            Leaf::Blob(b) => b.contains(q),
            Leaf::Quadric(x) => x.contains(q),
            Leaf::Extrusion(x) => x.contains(q),
            Leaf::Lathe(x) => x.contains(q),
            Leaf::Sor(x) => x.is_closed() && x.contains(q),
            Leaf::SphereSweep(x) => x.contains(q),
            Leaf::Superellipsoid(x) => x.contains(q),
            Leaf::Poly(x) => x.contains(q),
            Leaf::Isosurface(x) => x.contains(q),
            Leaf::HeightField(x) => x.contains(q),
            Leaf::Triangle(_)
            | Leaf::Quad(_)
            | Leaf::Polygon(_)
            | Leaf::Disk(_)
            | Leaf::Ring(_)
            | Leaf::Bicubic(_) => false,
        }
    }

    /// Whether the line of `r` starts (at t → −∞) inside (only a half-space or an unbounded
    /// quadric or polynomial surface can).
    pub(crate) fn inside_at_start(&self, r: &Ray) -> bool {
        match self {
            Leaf::Plane { point, normal } => {
                let dn = normal.dot(r.dir);
                dn > 0.0 || (dn == 0.0 && (r.origin - *point).dot(*normal) < 0.0)
            }
            Leaf::Quadric(x) => x.inside_at_start(r),
            Leaf::Poly(x) => x.inside_at_start(r),
            _ => false,
        }
    }

    /// The frame texture mappings read this shape's hits in.
    pub(crate) fn frame(&self) -> MappingFrame {
        match *self {
            Leaf::Sphere { center, radius } => MappingFrame::Sphere { center, radius },
            _ => MappingFrame::Object,
        }
    }
}

/// Whether a one- or two-operand node (`inverse`, `clipped_by`) has exactly `want` operands;
/// the IR of the front ends always has, so this guards hand-built scenes.
fn operand_count(count: usize, want: usize, why: &str) -> Result<(), ShapeFlaw> {
    if count == want {
        return Ok(());
    }
    Err(ShapeFlaw::other(
        "objects",
        CSG_OPERANDS,
        format!("{count} operand(s) where {want} belong"),
        why.to_string(),
        "build it with `.inverse()` or `.clipped_by(solid)`",
    ))
}

/// Whether a CSG node with `count` operands can be built (it needs two or more).
pub(crate) fn csg_operands(count: usize) -> Result<(), ShapeFlaw> {
    if count >= 2 {
        return Ok(());
    }
    Err(ShapeFlaw::other(
        "objects",
        CSG_OPERANDS,
        format!("a CSG operation needs at least two objects, found {count}"),
        "too few operands",
        "pass a list of two or more objects",
    ))
}

/// Object-space bounds of a valid shape other than a mesh or CSG node (infinite for a plane);
/// `None` for those and for an invalid shape.
pub(crate) fn bounds(shape: &Shape) -> Option<Aabb> {
    leaf(shape).ok().map(|g| g.bounds())
}

/// Whether a shape encloses a volume CSG can classify against: surfaces (triangle, quad,
/// polygon, disk, ring, bicubic patch) and open cylinders, cones and sors do not; a mesh does when `closed_mesh` says its
/// file is closed; a CSG node when all its operands do (an inverted solid is one; a clipped
/// surface never).
pub(crate) fn encloses_volume(
    shape: &Shape,
    closed_mesh: &dyn Fn(&crate::ir::MeshSource, bool) -> bool,
) -> bool {
    match shape {
        Shape::Triangle { .. }
        | Shape::Quad { .. }
        | Shape::Polygon { .. }
        | Shape::Disk { .. }
        | Shape::Ring { .. }
        | Shape::BicubicPatch { .. } => false,
        Shape::Cylinder { capped, .. } | Shape::Cone { capped, .. } => *capped,
        Shape::Isosurface { open, .. } => !*open,
        Shape::Sor { open, .. } => !*open,
        Shape::Mesh { source, smooth, .. } => closed_mesh(source, *smooth),
        // A clipped surface is open: its clipper's faces are not shown.
        Shape::Csg {
            op: CsgOp::Clip, ..
        } => false,
        Shape::Csg { children, .. } => children
            .iter()
            .all(|c| encloses_volume(&c.shape, closed_mesh)),
        Shape::Sphere { .. }
        | Shape::Plane { .. }
        | Shape::Box { .. }
        | Shape::Torus { .. }
        | Shape::Quadric { .. }
        | Shape::Blob { .. }
        | Shape::Prism { .. }
        | Shape::Text { .. }
        | Shape::Lathe { .. }
        | Shape::SphereSweep { .. }
        | Shape::Superellipsoid { .. }
        | Shape::Poly { .. }
        | Shape::HeightField { .. } => true,
    }
}
