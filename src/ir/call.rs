//! A shape as the language's constructor call that makes it (`Shape::call`): what `rtc
//! convert` writes, so the back end needs no arm per shape. A leaf of the IR.

use std::path::PathBuf;

use glam::DVec3;

use super::object::Shape;
use super::shape_parts::{BlobComponent, Container, Spindle, Spline, SweepSpline};

/// What `rtc convert` writes for a compiled function it cannot spell as source (none the
/// compiler makes): a string, so the written scene stops with a type error naming why.
pub(crate) const COMPILED_FUNCTION: &str = "a compiled function cannot be written back as source";

/// A constructor call: the built-in's name and its named arguments, in the order written.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ShapeCall {
    /// The constructor (`sphere`, `ring`, ...).
    pub(crate) name: &'static str,
    /// The arguments by parameter name; parameters at their defaults are left out.
    pub(crate) args: Vec<(&'static str, Arg)>,
}

/// An argument value as the IR holds it.
#[derive(Clone, Debug, PartialEq)]
pub enum Arg {
    /// A number.
    Number(f64),
    /// A point or vector, written as given.
    Point(DVec3),
    /// A unit direction the constructor normalises: written as a vector whose unit vector is
    /// exactly this one.
    Direction(DVec3),
    /// A Boolean.
    Bool(bool),
    /// An asset's path (written relative to the converted file).
    Path(PathBuf),
    /// A string (a name among a parameter's choices, a text's characters).
    Str(String),
    /// A list.
    List(Vec<Arg>),
    /// A record of named fields.
    Record(Vec<(&'static str, Arg)>),
    /// A compiled function of the point (an isosurface's `f`), written as a `fn(p)` literal.
    Function(std::sync::Arc<crate::pattern::Program>),
}

impl Shape {
    /// The constructor call that makes this shape (parameters at their defaults left out), for
    /// `rtc convert`; `None` for CSG, whose operands are objects the back end writes itself.
    /// Kept beside the variants so a new shape is one arm here, not one in the back end.
    pub(crate) fn call(&self) -> Option<ShapeCall> {
        use Arg::{Bool, Direction, List, Number, Point, Record};
        let (name, args): (&'static str, Vec<(&'static str, Arg)>) = match self {
            Shape::Sphere { center, radius } => {
                let mut a = Vec::new();
                if *center != DVec3::ZERO {
                    a.push(("center", Point(*center)));
                }
                a.push(("radius", Number(*radius)));
                ("sphere", a)
            }
            Shape::Plane { point, normal } => (
                "plane",
                vec![("point", Point(*point)), ("normal", Direction(*normal))],
            ),
            Shape::Box { min, max } => ("box", vec![("min", Point(*min)), ("max", Point(*max))]),
            Shape::Triangle {
                vertices: [a, b, c],
            } => (
                "triangle",
                vec![("a", Point(*a)), ("b", Point(*b)), ("c", Point(*c))],
            ),
            Shape::Quad { corner, u, v } => (
                "quad",
                vec![
                    ("corner", Point(*corner)),
                    ("u", Point(*u)),
                    ("v", Point(*v)),
                ],
            ),
            Shape::Polygon { points } => (
                "polygon",
                vec![("points", List(points.iter().map(|p| Point(*p)).collect()))],
            ),
            Shape::Disk {
                center,
                normal,
                radius,
            } => (
                "disk",
                vec![
                    ("center", Point(*center)),
                    ("normal", Direction(*normal)),
                    ("radius", Number(*radius)),
                ],
            ),
            Shape::Ring {
                center,
                normal,
                radius,
                inner,
            } => (
                "ring",
                vec![
                    ("center", Point(*center)),
                    ("normal", Direction(*normal)),
                    ("radius", Number(*radius)),
                    ("inner", Number(*inner)),
                ],
            ),
            Shape::Cylinder {
                base,
                top,
                radius,
                capped,
            } => {
                let mut a = vec![
                    ("base", Point(*base)),
                    ("top", Point(*top)),
                    ("radius", Number(*radius)),
                ];
                if !*capped {
                    a.push(("capped", Bool(false)));
                }
                ("cylinder", a)
            }
            Shape::Cone {
                base,
                top,
                base_radius,
                top_radius,
                capped,
            } => {
                let mut a = vec![
                    ("base", Point(*base)),
                    ("top", Point(*top)),
                    ("base_radius", Number(*base_radius)),
                    ("top_radius", Number(*top_radius)),
                ];
                if !*capped {
                    a.push(("capped", Bool(false)));
                }
                ("cone", a)
            }
            Shape::Torus {
                center,
                major_radius,
                minor_radius,
                spindle,
            } => {
                let mut a = vec![
                    ("center", Point(*center)),
                    ("major_radius", Number(*major_radius)),
                    ("minor_radius", Number(*minor_radius)),
                ];
                if *spindle != Spindle::default() {
                    a.push(("spindle", Arg::Str(spindle.name().to_string())));
                }
                ("torus", a)
            }
            Shape::Quadric {
                squares,
                mixed,
                linear,
                constant,
            } => (
                "quadric",
                vec![
                    ("squares", Point(*squares)),
                    ("mixed", Point(*mixed)),
                    ("linear", Point(*linear)),
                    ("constant", Number(*constant)),
                ],
            ),
            Shape::Blob {
                components,
                threshold,
            } => {
                let component = |c: &BlobComponent| {
                    let mut fields = vec![("center", Point(c.center))];
                    if let Some(end) = c.end {
                        fields.push(("end", Point(end)));
                    }
                    fields.push(("radius", Number(c.radius)));
                    fields.push(("strength", Number(c.strength)));
                    Record(fields)
                };
                (
                    "blob",
                    vec![
                        (
                            "components",
                            List(components.iter().map(component).collect()),
                        ),
                        ("threshold", Number(*threshold)),
                    ],
                )
            }
            Shape::Lathe { points, spline } => {
                let pair = |p: &[f64; 2]| List(vec![Number(p[0]), Number(p[1])]);
                let mut a = vec![("points", List(points.iter().map(pair).collect()))];
                if *spline != Spline::Linear {
                    a.push(("spline", Arg::Str(spline.name().to_string())));
                }
                ("lathe", a)
            }
            Shape::Sor { points, open } => {
                let pair = |p: &[f64; 2]| List(vec![Number(p[0]), Number(p[1])]);
                let mut a = vec![("points", List(points.iter().map(pair).collect()))];
                if *open {
                    a.push(("open", Bool(true)));
                }
                ("sor", a)
            }
            Shape::SphereSweep { spline, spheres } => {
                let mut a = vec![
                    (
                        "points",
                        List(spheres.iter().map(|(c, _)| Point(*c)).collect()),
                    ),
                    (
                        "radii",
                        List(spheres.iter().map(|(_, r)| Number(*r)).collect()),
                    ),
                ];
                if *spline != SweepSpline::Linear {
                    a.push(("spline", Arg::Str(spline.name().to_string())));
                }
                ("sphere_sweep", a)
            }
            Shape::Superellipsoid { e, n } => {
                ("superellipsoid", vec![("e", Number(*e)), ("n", Number(*n))])
            }
            Shape::Poly {
                order,
                coefficients,
            } => (
                "poly",
                vec![
                    ("order", Number(f64::from(*order))),
                    (
                        "coefficients",
                        List(coefficients.iter().map(|c| Number(*c)).collect()),
                    ),
                ],
            ),
            Shape::Isosurface {
                function,
                container,
                threshold,
                max_gradient,
                accuracy,
                open,
                ..
            } => {
                let mut a = vec![("f", Arg::Function(function.clone()))];
                match *container {
                    Container::Box { min, max } => {
                        if min != DVec3::splat(-1.0) {
                            a.push(("min", Point(min)));
                        }
                        if max != DVec3::splat(1.0) {
                            a.push(("max", Point(max)));
                        }
                    }
                    Container::Sphere { center, radius } => {
                        if center != DVec3::ZERO {
                            a.push(("center", Point(center)));
                        }
                        a.push(("radius", Number(radius)));
                    }
                }
                if *threshold != 0.0 {
                    a.push(("threshold", Number(*threshold)));
                }
                if let Some(g) = max_gradient {
                    a.push(("max_gradient", Number(*g)));
                }
                if *accuracy != 0.001 {
                    a.push(("accuracy", Number(*accuracy)));
                }
                if *open {
                    a.push(("open", Bool(true)));
                }
                ("isosurface", a)
            }
            Shape::HeightField {
                image,
                heights,
                smooth,
                water_level,
            } => {
                let mut a = vec![match image {
                    Some(path) => ("image", Arg::Path(path.clone())),
                    // A grid from numbers or a function: its heights, row by row.
                    None => (
                        "heights",
                        List(
                            heights
                                .heights
                                .chunks(heights.nx)
                                .map(|row| {
                                    List(row.iter().map(|&h| Number(f64::from(h))).collect())
                                })
                                .collect(),
                        ),
                    ),
                }];
                if *smooth {
                    a.push(("smooth", Bool(true)));
                }
                if *water_level != 0.0 {
                    a.push(("water_level", Number(*water_level)));
                }
                ("height_field", a)
            }
            Shape::BicubicPatch { points } => (
                "bicubic_patch",
                vec![(
                    "points",
                    List(
                        points
                            .iter()
                            .map(|row| List(row.iter().map(|p| Point(*p)).collect()))
                            .collect(),
                    ),
                )],
            ),
            Shape::Mesh {
                source,
                smooth,
                use_mtl,
            } => {
                let mut a = match source {
                    super::mesh::MeshSource::File(path) => vec![("path", Arg::Path(path.clone()))],
                    super::mesh::MeshSource::Inline(m) => inline_mesh_args(m),
                };
                if *smooth {
                    a.push(("smooth", Bool(true)));
                }
                if *use_mtl {
                    a.push(("use_mtl", Bool(true)));
                }
                ("mesh", a)
            }
            Shape::Prism {
                points,
                heights,
                spline,
                sweep,
            } => {
                let pair = |a: f64, b: f64| List(vec![Number(a), Number(b)]);
                let mut a = vec![
                    (
                        "points",
                        List(points.iter().map(|p| pair(p.x, p.y)).collect()),
                    ),
                    ("heights", pair(heights[0], heights[1])),
                ];
                if *spline != super::shape_parts::Spline::Linear {
                    a.push(("spline", Arg::Str(spline.name().to_string())));
                }
                if *sweep == super::shape_parts::PrismSweep::Conic {
                    a.push(("sweep", Arg::Str("conic".to_string())));
                }
                ("prism", a)
            }
            Shape::Text {
                font,
                string,
                thickness,
                spacing,
                align,
                ..
            } => {
                let mut a = vec![("string", Arg::Str(string.clone()))];
                if let Some(f) = font {
                    a.push(("font", Arg::Path(f.clone())));
                }
                a.push(("thickness", Number(*thickness)));
                if *spacing != glam::DVec2::ZERO {
                    a.push(("spacing", List(vec![Number(spacing.x), Number(spacing.y)])));
                }
                if *align != super::shape_parts::TextAlign::Left {
                    a.push(("align", Arg::Str(align.name().to_string())));
                }
                ("text", a)
            }
            Shape::Csg { .. } => return None,
        };
        Some(ShapeCall { name, args })
    }
}

/// An inline mesh's lists as `mesh(vertices:, faces:, normals:, uv:)` reads them (the empty
/// optional lists left out).
fn inline_mesh_args(m: &super::mesh::InlineMesh) -> Vec<(&'static str, Arg)> {
    let number_list = |xs: &[f64]| Arg::List(xs.iter().map(|x| Arg::Number(*x)).collect());
    let mut a = vec![
        (
            "vertices",
            Arg::List(m.vertices.iter().map(|v| Arg::Point(*v)).collect()),
        ),
        (
            "faces",
            Arg::List(
                m.triangles
                    .iter()
                    .map(|t| number_list(&t.map(f64::from)))
                    .collect(),
            ),
        ),
    ];
    if !m.normals.is_empty() {
        a.push((
            "normals",
            Arg::List(m.normals.iter().map(|v| Arg::Point(*v)).collect()),
        ));
    }
    if !m.uvs.is_empty() {
        a.push((
            "uv",
            Arg::List(m.uvs.iter().map(|v| number_list(&v.to_array())).collect()),
        ));
    }
    a
}
