//! An object of the scene: its shape (every kind of geometry the renderer knows), placement,
//! material and visibility, as plain data.

use std::path::PathBuf;
use std::sync::Arc;

use glam::{DVec2, DVec3};

use crate::source::Span;

use super::motion::Motion;
use super::placement::Transform;
use super::shape_parts::{
    BlobComponent, Container, HeightGrid, PrismSweep, Spindle, Spline, SweepSpline, TextAlign,
    TextGlyphs,
};
use super::texture::MaterialId;

/// An object: a shape in its own space, placed by an affine transform, with a material.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// Geometry in object space.
    pub shape: Shape,
    /// Object-to-world transform (applied after the shape's own parameters).
    pub transform: Transform,
    /// The material; `None` inherits from the enclosing CSG node, else [`RenderSettings::default_material`].
    pub material: Option<MaterialId>,
    /// How it moves while the shutter is open (`None`: it stands still; `transform` is its
    /// placement at shutter open). Boxed: few objects move, and inline it would double the
    /// size of every object.
    pub motion: Option<Box<Motion>>,
    /// Where it was defined.
    pub span: Span,
    /// The rays that see it (all, unless `.no_shadow()`, `.no_image()` or `.no_reflection()`).
    pub visibility: Visibility,
}

/// Which rays see an object (POV-Ray's `no_shadow`, `no_image` and `no_reflection`): a set of
/// the kinds of ray that pass through it as if it were not there.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Visibility(u8);

impl Visibility {
    /// Seen by every ray.
    pub const ALL: Visibility = Visibility(0);
    /// Casts no shadow: shadow rays pass through it.
    pub const NO_SHADOW: Visibility = Visibility(1);
    /// Not in the image: camera rays, and rays refracted from them, pass through it.
    pub const NO_IMAGE: Visibility = Visibility(2);
    /// Not in reflections: rays that have been reflected pass through it.
    pub const NO_REFLECTION: Visibility = Visibility(4);

    /// Both sets' hidden ray kinds.
    pub fn with(self, other: Visibility) -> Visibility {
        Visibility(self.0 | other.0)
    }

    /// Whether the kinds of `flag` pass through it.
    pub fn hides(self, flag: Visibility) -> bool {
        self.0 & flag.0 != 0
    }

    /// Whether every ray sees it.
    pub fn is_all(self) -> bool {
        self.0 == 0
    }
}

/// Every kind of geometry the renderer knows.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// A sphere.
    Sphere {
        /// Centre.
        center: DVec3,
        /// Radius (> 0).
        radius: f64,
    },
    /// An infinite plane through `point`; `normal` points to the outside of the half-space.
    Plane {
        /// A point on the plane.
        point: DVec3,
        /// Outward unit normal.
        normal: DVec3,
    },
    /// An axis-aligned box.
    Box {
        /// Minimum corner.
        min: DVec3,
        /// Maximum corner.
        max: DVec3,
    },
    /// A single triangle.
    Triangle {
        /// Corners, counter-clockwise seen from the front.
        vertices: [DVec3; 3],
    },
    /// A parallelogram `corner + s·u + t·v`, s, t ∈ [0, 1].
    Quad {
        /// One corner.
        corner: DVec3,
        /// First edge.
        u: DVec3,
        /// Second edge.
        v: DVec3,
    },
    /// A planar polygon (convex or concave), closed implicitly.
    Polygon {
        /// Vertices in order (≥ 3, coplanar).
        points: Vec<DVec3>,
    },
    /// A flat disk.
    Disk {
        /// Centre.
        center: DVec3,
        /// Unit normal.
        normal: DVec3,
        /// Radius (> 0).
        radius: f64,
    },
    /// A flat ring: a disk with a round hole in its middle.
    Ring {
        /// Centre.
        center: DVec3,
        /// Unit normal.
        normal: DVec3,
        /// Outer radius (> 0).
        radius: f64,
        /// Radius of the hole (0 ≤ inner < radius).
        inner: f64,
    },
    /// A cylinder between two points.
    Cylinder {
        /// Centre of the bottom cap.
        base: DVec3,
        /// Centre of the top cap.
        top: DVec3,
        /// Radius (> 0).
        radius: f64,
        /// Whether the ends are closed.
        capped: bool,
    },
    /// A cone or frustum between two points.
    Cone {
        /// Centre of the base.
        base: DVec3,
        /// Centre of the top.
        top: DVec3,
        /// Radius at `base` (≥ 0).
        base_radius: f64,
        /// Radius at `top` (≥ 0, not both 0).
        top_radius: f64,
        /// Whether the ends are closed.
        capped: bool,
    },
    /// A torus about the +Y axis through `center`.
    Torus {
        /// Centre.
        center: DVec3,
        /// Distance from the centre to the tube's centre line.
        major_radius: f64,
        /// Tube radius (larger than `major_radius`: a spindle torus, self-intersecting).
        minor_radius: f64,
        /// What a spindle torus shows and holds (ignored unless `minor_radius > major_radius`).
        spindle: Spindle,
    },
    /// A quadric surface `A·x² + B·y² + C·z² + D·xy + E·xz + F·yz + G·x + H·y + I·z + J = 0`,
    /// inside where the polynomial is negative (POV-Ray's `quadric`; usually unbounded).
    Quadric {
        /// `A, B, C`: the coefficients of `x², y², z²`.
        squares: DVec3,
        /// `D, E, F`: the coefficients of `xy, xz, yz`.
        mixed: DVec3,
        /// `G, H, I`: the coefficients of `x, y, z`.
        linear: DVec3,
        /// `J`: the constant.
        constant: f64,
    },
    /// A lathe (POV-Ray's `lathe`): a profile of `[r, y]` points joined by `spline`, revolved
    /// about the +Y axis.
    Lathe {
        /// Profile points `[r, y]` (r ≥ 0).
        points: Vec<[f64; 2]>,
        /// How the points are joined.
        spline: Spline,
    },
    /// A surface of revolution (POV-Ray's `sor`): about the +Y axis, its radius² a cubic of
    /// the height on each segment, interpolating the `[r, y]` points (the first and last only
    /// steer).
    Sor {
        /// Profile points `[r, y]` (r ≥ 0, heights increasing from the second to the last
        /// but one).
        points: Vec<[f64; 2]>,
        /// Without the base and cap disks (a surface, not a solid).
        open: bool,
    },
    /// A sphere sweep (POV-Ray's `sphere_sweep`): the union of the spheres whose centre and
    /// radius run along a spline through `spheres`.
    SphereSweep {
        /// How the spheres are interpolated.
        spline: SweepSpline,
        /// The modelling spheres `(centre, radius)`, in order.
        spheres: Vec<(DVec3, f64)>,
    },
    /// A superellipsoid (POV-Ray's `superellipsoid { <e, n> }`) in the cube [-1, 1]³:
    /// `(|x|^(2/e) + |z|^(2/e))^(e/n) + |y|^(2/n) = 1`, its round sections about the Y axis.
    Superellipsoid {
        /// East-west exponent (the sections' squareness).
        e: f64,
        /// North-south exponent (the profile's squareness).
        n: f64,
    },
    /// An algebraic surface (POV-Ray's `poly`, `cubic`, `quartic`): the zeros of a polynomial
    /// of `order` in x, y, z, inside where it is negative (usually unbounded).
    Poly {
        /// The total degree (2 to 15).
        order: u32,
        /// The coefficients in POV-Ray's order (see [`crate::ir::poly_terms`]).
        coefficients: Vec<f64>,
    },
    /// An isosurface (POV-Ray's `isosurface`): where a compiled function of the point equals
    /// `threshold` inside a container, inside where it is below; the container's walls close
    /// it where the function is inside (unless `open`).
    Isosurface {
        /// The function of the point, compiled once (the same program as `pattern(f)`).
        function: Arc<crate::pattern::Program>,
        /// The box or sphere the surface is searched in.
        container: Container,
        /// The function's value on the surface.
        threshold: f64,
        /// A bound on the function's rate of change (per unit length); `None`: estimated
        /// when the shape is prepared.
        max_gradient: Option<f64>,
        /// The shortest step of the search along a ray (features thinner may be missed).
        accuracy: f64,
        /// Whether the container's walls are left open (a surface, not a solid).
        open: bool,
    },
    /// Metaballs: the surface where the summed field equals `threshold`.
    Blob {
        /// Field sources.
        components: Vec<BlobComponent>,
        /// Iso-value.
        threshold: f64,
    },
    /// POV-Ray's `prism`: a closed outline of spline segments in the ground plane (`[x, z]`
    /// points), swept up `y` between two heights.
    Prism {
        /// The outline's points as the spline reads them.
        points: Vec<DVec2>,
        /// `[low, high]` (low < high; for a conic sweep low ≥ 0).
        heights: [f64; 2],
        /// How the points make segments.
        spline: Spline,
        /// Straight up, or scaled by the height from an apex at the origin.
        sweep: PrismSweep,
    },
    /// A string set in a TrueType/OpenType font, facing +z, its baseline on `y = 0`, extruded
    /// from `z = 0` back to `z = −thickness` (1 unit = 1 em).
    Text {
        /// The font file (resolved); `None`: the built-in DejaVu Sans.
        font: Option<PathBuf>,
        /// The string.
        string: String,
        /// How deep it is extruded (> 0).
        thickness: f64,
        /// Extra space after each character, `[x, y]` (POV-Ray's `offset`).
        spacing: DVec2,
        /// Which point of the string sits on the origin.
        align: TextAlign,
        /// The glyph outlines laid out (from the font when the text was made).
        glyphs: Arc<TextGlyphs>,
    },
    /// A height field (POV-Ray's `height_field`): a grid of heights over the unit square
    /// x, z ∈ [0, 1], each cell two triangles; a solid (below the surface, over the square).
    HeightField {
        /// The greyscale image it was read from (resolved), or `None` for a grid given as
        /// numbers or sampled from a function (`heights` then holds it all).
        image: Option<PathBuf>,
        /// The heights.
        heights: Arc<HeightGrid>,
        /// Interpolate vertex normals.
        smooth: bool,
        /// Parts below this height are cut away (0: none).
        water_level: f64,
    },
    /// A bicubic Bézier patch (POV-Ray's `bicubic_patch`): `Σ Bᵢ(s)·Bⱼ(t)·points[i][j]`, a
    /// surface (not a solid); uv = `(t, s)`, POV-Ray's.
    BicubicPatch {
        /// The 4 × 4 control points, row by row (POV-Ray's order); boxed, as they would
        /// make every shape four times larger.
        points: Box<[[DVec3; 4]; 4]>,
    },
    /// A triangle mesh from a file (loaded when the scene is prepared; instanced by path) or
    /// written inline.
    Mesh {
        /// Where its data comes from.
        source: super::mesh::MeshSource,
        /// Interpolate normals.
        smooth: bool,
        /// Use the file's MTL materials where present.
        use_mtl: bool,
    },
    /// Constructive solid geometry over closed children.
    Csg {
        /// The operation.
        op: CsgOp,
        /// Operands (two or more; for `Difference` the first is the base).
        children: Vec<Object>,
    },
}

impl Shape {
    /// Short lower-case kind name used in messages and statistics.
    pub fn kind_name(&self) -> &'static str {
        match self {
            Shape::Sphere { .. } => "sphere",
            Shape::Plane { .. } => "plane",
            Shape::Box { .. } => "box",
            Shape::Triangle { .. } => "triangle",
            Shape::Quad { .. } => "quad",
            Shape::Polygon { .. } => "polygon",
            Shape::Disk { .. } => "disk",
            Shape::Ring { .. } => "ring",
            Shape::Cylinder { .. } => "cylinder",
            Shape::Cone { .. } => "cone",
            Shape::Torus { .. } => "torus",
            Shape::Quadric { .. } => "quadric",
            Shape::Blob { .. } => "blob",
            Shape::Prism { .. } => "prism",
            Shape::Text { .. } => "text",
            Shape::Lathe { .. } => "lathe",
            Shape::Sor { .. } => "sor",
            Shape::SphereSweep { .. } => "sphere_sweep",
            Shape::Superellipsoid { .. } => "superellipsoid",
            Shape::Poly { .. } => "poly",
            Shape::Isosurface { .. } => "isosurface",
            Shape::HeightField { .. } => "height_field",
            Shape::BicubicPatch { .. } => "bicubic_patch",
            Shape::Mesh { .. } => "mesh",
            Shape::Csg { .. } => "csg",
        }
    }
}

/// A CSG operation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CsgOp {
    /// Inside any operand; internal surfaces kept.
    Union,
    /// Inside any operand; internal surfaces removed (POV-Ray's `merge`).
    Merge,
    /// Inside every operand.
    Intersection,
    /// Inside the first operand and outside all others.
    Difference,
    /// Outside its one operand: the solid turned inside out (POV-Ray's `inverse`), for CSG.
    Inverse,
    /// The first operand's surface where it lies inside the second, a solid (POV-Ray's
    /// `clipped_by`): an open surface, not a solid.
    Clip,
}
