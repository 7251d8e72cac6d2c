//! The parameters a shape's variant carries beyond points and numbers: spline kinds, a height
//! field's grid, blob components, an isosurface's container, a text's outlines and the named
//! modes of tori, prisms and texts. Plain data, named in the language and in `rtc convert`.

use std::sync::Arc;

use glam::{DVec2, DVec3};

/// A height field's grid: `nx × nz` heights in [0, 1], row by row from z = 0, point `(i, j)`
/// at x = i/(nx − 1), z = j/(nz − 1).
#[derive(Clone, Debug, PartialEq)]
pub struct HeightGrid {
    /// Points along x.
    pub nx: usize,
    /// Points along z.
    pub nz: usize,
    /// `heights[j·nx + i]`.
    pub heights: Arc<[f32]>,
}

/// How a prism's outline or a lathe's profile points are joined (POV-Ray's spline kinds).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Spline {
    /// Straight segments between neighbours.
    Linear,
    /// A segment from `p[i+1]` to `p[i+2]`, shaped by `p[i]` (POV-Ray's quadratic spline); the
    /// first point only steers.
    Quadratic,
    /// A segment from `p[i+1]` to `p[i+2]` with `p[i]` and `p[i+3]` as neighbours (POV-Ray's
    /// Catmull-Rom-like cubic spline); the first and last points only steer.
    Cubic,
    /// Cubic Bézier segments, four points each.
    Bezier,
}

impl Spline {
    /// The names the language reads, in the variants' order.
    pub const NAMES: [&str; 4] = ["linear", "quadratic", "cubic", "bezier"];

    /// The spline called `name`.
    pub fn named(name: &str) -> Option<Spline> {
        Spline::NAMED
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, s)| *s)
    }

    /// The fewest points a prism's outline needs (POV-Ray's counts).
    pub fn min_points(self) -> usize {
        match self {
            Spline::Linear => 3,
            Spline::Quadratic => 5,
            Spline::Cubic => 6,
            Spline::Bezier => 4,
        }
    }

    /// Every kind with its name, as the language spells it.
    pub const NAMED: [(&'static str, Spline); 4] = [
        ("linear", Spline::Linear),
        ("quadratic", Spline::Quadratic),
        ("cubic", Spline::Cubic),
        ("bezier", Spline::Bezier),
    ];

    /// Its name in the language.
    pub fn name(self) -> &'static str {
        Spline::NAMED
            .iter()
            .find(|(_, s)| *s == self)
            .map_or("linear", |(n, _)| n)
    }
}

/// How a sphere sweep interpolates its spheres (POV-Ray's `sphere_sweep` splines).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SweepSpline {
    /// Straight between neighbours: spheres joined by cones tangent to both.
    Linear,
    /// Through every sphere but the first and last, which only steer (POV-Ray's
    /// `cubic_spline`, a Catmull-Rom spline).
    CatmullRom,
    /// A uniform cubic B-spline: near the spheres, through none of them.
    BSpline,
}

impl SweepSpline {
    /// Every kind with its name, as the language spells it.
    pub const NAMED: [(&'static str, SweepSpline); 3] = [
        ("linear", SweepSpline::Linear),
        ("catmull_rom", SweepSpline::CatmullRom),
        ("b_spline", SweepSpline::BSpline),
    ];

    /// The names the language reads, in the variants' order.
    pub const NAMES: [&str; 3] = ["linear", "catmull_rom", "b_spline"];

    /// Its name in the language.
    pub fn name(self) -> &'static str {
        SweepSpline::NAMED
            .iter()
            .find(|(_, s)| *s == self)
            .map_or("linear", |(n, _)| n)
    }

    /// The fewest spheres it needs (POV-Ray's counts).
    pub fn min_spheres(self) -> usize {
        match self {
            SweepSpline::Linear => 2,
            SweepSpline::CatmullRom | SweepSpline::BSpline => 4,
        }
    }
}

/// The exponents `[i, j, k]` of x, y, z of each coefficient of a POV-Ray `poly` of `order`, in
/// POV-Ray's order: total degree falling, then the x exponent falling, then y's (so order 2
/// is x², xy, xz, x, y², yz, y, z², z, 1). The variables are rtc's own x, y, z (like
/// `quadric`'s): a POV-Ray scene's coefficients carry over after negating those of odd powers
/// of z, POV-Ray's z being rtc's −z.
pub fn poly_terms(order: u32) -> Vec<[u32; 3]> {
    let n = order;
    let mut out = Vec::new();
    for i in (0..=n).rev() {
        for j in (0..=n - i).rev() {
            for k in (0..=n - i - j).rev() {
                out.push([i, j, k]);
            }
        }
    }
    out
}

/// The region an isosurface is searched in (POV-Ray's `contained_by`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Container {
    /// An axis-aligned box.
    Box {
        /// Minimum corner.
        min: DVec3,
        /// Maximum corner.
        max: DVec3,
    },
    /// A sphere.
    Sphere {
        /// Centre.
        center: DVec3,
        /// Radius (> 0).
        radius: f64,
    },
}

/// One metaball.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlobComponent {
    /// Centre.
    pub center: DVec3,
    /// Radius of influence (field is 0 beyond it).
    pub radius: f64,
    /// Field strength at the centre (negative subtracts).
    pub strength: f64,
    /// The other end of a cylinder component (POV-Ray's blob `cylinder`: the field falls off
    /// with the distance to the segment from `center` to `end`, round at both ends); `None`
    /// for a sphere component.
    pub end: Option<DVec3>,
}

/// The parts of a spindle torus (minor radius larger than major) that are seen and that are
/// inside, after POV-Ray's spindle modes. The *spindle* is the lemon-shaped inner region the
/// self-intersecting tube covers twice; the *apple* is the whole tube.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Spindle {
    /// The apple's surface and the spindle's, the apple inside (POV-Ray's default).
    #[default]
    Union,
    /// The apple alone: its outer surface and its inside.
    Merge,
    /// The spindle alone: its surface and its inside.
    Intersection,
    /// Both surfaces, the apple without the spindle inside.
    Difference,
}

impl Spindle {
    /// The language's names, in order of the variants.
    pub const NAMES: [(&'static str, Spindle); 4] = [
        ("union", Spindle::Union),
        ("merge", Spindle::Merge),
        ("intersection", Spindle::Intersection),
        ("difference", Spindle::Difference),
    ];

    /// The language's name of this mode.
    pub fn name(self) -> &'static str {
        Spindle::NAMES
            .iter()
            .find(|(_, m)| *m == self)
            .map_or("union", |(n, _)| n)
    }
}

/// How a prism's outline is swept.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PrismSweep {
    /// Unchanged from the low height to the high one.
    Linear,
    /// Scaled by the height (`[x·y, y, z·y]`): a cone from the apex at the origin.
    Conic,
}

/// Which point of a text's line sits on the origin.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextAlign {
    /// The start of the first glyph's advance (POV-Ray's placement).
    Left,
    /// The middle of the line's advance.
    Center,
    /// The end of the last glyph's advance.
    Right,
}

impl TextAlign {
    /// The names the language reads, in this order.
    pub const NAMES: [&str; 3] = ["left", "center", "right"];

    /// Its name in the language.
    pub fn name(self) -> &'static str {
        TextAlign::NAMES[self as usize]
    }
}

/// One curve of a glyph's outline, in em units, placed on the line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GlyphCurve {
    /// A straight segment.
    Line([DVec2; 2]),
    /// A quadratic Bézier curve (TrueType).
    Quad([DVec2; 3]),
    /// A cubic Bézier curve (CFF / OpenType).
    Cubic([DVec2; 4]),
}

/// A text's outlines: per glyph, its closed contours as one list of curves (nonzero fill).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TextGlyphs {
    /// The glyphs with an outline (a space has none), in order.
    pub glyphs: Vec<Vec<GlyphCurve>>,
}
