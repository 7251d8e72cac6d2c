//! The scene IR: plain data produced by the language evaluator and the legacy front ends, consumed
//! by the preparation stage (`opt`). No parsing types and no render types live here.
//!
//! Conventions: world units are free (the course uses pixels), `f64` everywhere, colours are linear
//! RGB with no upper clamp, every item carries the [`Span`] of the source that made it.

use std::path::PathBuf;

use glam::DVec3;

use crate::source::Span;

mod atmosphere;
mod call;
mod camera;
mod flare;
mod light;
pub mod limits;
mod loaded;
mod motion;
mod placement;
pub mod provenance;
mod settings;
mod texture;

pub use atmosphere::{Fog, FogPattern, GroundFog, Sky};
pub(crate) use call::{Arg, ShapeCall};
pub use camera::{Camera, Projection};
pub(crate) use flare::Flare;
pub use light::{Fade, Light, LightKind, PARALLEL_DISTANCE, Spot, cylinder_share};
pub use loaded::Loaded;
pub(crate) use motion::{CameraMotion, Motion, Shutter};
pub use placement::Transform;
pub use provenance::Provenance;
pub use settings::{
    AmbientConvention, DepthRange, Encoding, LightSampling, RenderMode, RenderSettings, Sampling,
    ShadingModel,
};
pub(crate) use settings::{GoochParams, LANGUAGE_CUTOFF};
pub use texture::{
    Bump, ImageFilter, Mapping, MaterialId, Mix, PatternSpace, PatternTexture, Texture, TextureId,
};

/// Linear RGB colour (channels may exceed 1 for bright lights).
pub(crate) type Color = DVec3;

/// A whole evaluated scene, ready for optimisation and rendering. Two scenes are equal when
/// what they show and how they render are: `memory` is the load's bookkeeping (a course
/// scene read from `.in` and from YAML is the same scene, charged differently).
#[derive(Clone, Debug)]
pub struct Scene {
    /// The one camera.
    pub camera: Camera,
    /// All light sources.
    pub lights: Vec<Light>,
    /// Materials referenced by objects.
    pub materials: Vec<Material>,
    /// Textures referenced by materials.
    pub textures: Vec<Texture>,
    /// Top-level objects (groups are flattened by the front ends; CSG nodes keep children).
    pub objects: Vec<Object>,
    /// How to render.
    pub settings: RenderSettings,
    /// The load's memory budget and what the front end charged to it; the preparation
    /// charges the textures and meshes it loads on top.
    pub memory: limits::Memory,
}

impl PartialEq for Scene {
    fn eq(&self, other: &Scene) -> bool {
        let Scene {
            camera,
            lights,
            materials,
            textures,
            objects,
            settings,
            memory: _,
        } = self;
        *camera == other.camera
            && *lights == other.lights
            && *materials == other.materials
            && *textures == other.textures
            && *objects == other.objects
            && *settings == other.settings
    }
}

impl Scene {
    /// The material behind an id.
    pub fn material(&self, id: MaterialId) -> &Material {
        &self.materials[id.0 as usize]
    }

    /// Adds a material and returns its id.
    pub fn add_material(&mut self, m: Material) -> MaterialId {
        self.materials.push(m);
        MaterialId((self.materials.len() - 1) as u32)
    }

    /// Adds a texture and returns its id.
    pub fn add_texture(&mut self, t: Texture) -> TextureId {
        self.textures.push(t);
        TextureId((self.textures.len() - 1) as u32)
    }
}

/// Surface appearance.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// Base colour C (replaced by `texture` where present).
    pub color: Color,
    /// Colour texture, replacing `color`.
    pub texture: Option<TextureId>,
    /// Bump map perturbing the normal.
    pub bump: Option<Bump>,
    /// A material made of others (a material map or layers), resolved per hit; the fields
    /// above are then its first part's, for the code that reads a material without a hit.
    pub mix: Option<Box<Mix>>,
    /// Ambient coefficient.
    pub ka: f64,
    /// Diffuse coefficient.
    pub kd: f64,
    /// Specular coefficient.
    pub ks: f64,
    /// Phong exponent.
    pub n: f64,
    /// Mirror reflection weight (course files: equal to `ks`).
    pub reflect: f64,
    /// Transmission weight.
    pub refract: f64,
    /// Index of refraction of the material; the outside is 1.
    pub eta: f64,
    /// Glossiness: reflected and refracted rays spread over a cone of half-angle `gloss·90°`
    /// around the mirror and refraction directions; 0 is a perfect mirror.
    pub gloss: f64,
    /// Rays per glossy lobe at a camera ray's hit (one ray after the first bounce).
    pub gloss_samples: u32,
    /// Shading model for this material; `None` uses the scene's.
    pub shading: Option<ShadingModel>,
    /// The share of the transmitted light tinted by the surface colour (POV-Ray's filter over
    /// filter + transmit): refracted light is multiplied by `filter·C + (1 − filter)`. 0 (the
    /// course rule) passes it untinted; the language's default is [`LANGUAGE_FILTER`].
    pub filter: f64,
    /// Beer–Lambert absorption per unit length inside the object, per channel: light crossing
    /// `d` of it keeps `exp(−absorption·d)`.
    pub absorption: Color,
    /// The mirror weight follows the exact unpolarised dielectric Fresnel reflectance (times
    /// `reflect`), and the refracted share is the rest.
    pub fresnel: bool,
    /// The reflected share is taken from the transmitted light (POV-Ray's `conserve_energy`).
    pub conserve_energy: bool,
    /// How much the highlight takes the surface colour (POV-Ray's `metallic`), in [0, 1].
    pub metallic: f64,
    /// The diffuse falloff exponent: the diffuse term goes with `(N·L)^brilliance`.
    pub brilliance: f64,
    /// Light the surface emits whatever the lights, times its colour C (POV-Ray's `emission`).
    pub emission: Color,
    /// Where it was defined.
    pub span: Span,
}

/// The `filter` of a material written in the language: its colour tints what is seen through
/// it, as it tints its glass shadow (red glass looks red).
pub const LANGUAGE_FILTER: f64 = 1.0;

impl Material {
    /// Whether it uses none of the finish terms beyond Phong's (metallic, brilliance, emission,
    /// Fresnel): a packet of its hits shades exactly as one ray does.
    pub fn plain_finish(&self) -> bool {
        self.metallic == 0.0
            && self.brilliance == 1.0
            && self.emission == Color::ZERO
            && !self.fresnel
    }
}

impl Default for Material {
    fn default() -> Material {
        Material {
            color: DVec3::splat(0.8),
            texture: None,
            bump: None,
            mix: None,
            ka: 0.2,
            kd: 0.8,
            ks: 0.0,
            n: 1.0,
            reflect: 0.0,
            refract: 0.0,
            eta: 1.0,
            gloss: 0.0,
            gloss_samples: 8,
            shading: None,
            filter: 0.0,
            absorption: Color::ZERO,
            fresnel: false,
            conserve_energy: false,
            metallic: 0.0,
            brilliance: 1.0,
            emission: Color::ZERO,
            span: Span::default(),
        }
    }
}

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
        /// Tube radius.
        minor_radius: f64,
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
    /// Metaballs: the surface where the summed field equals `threshold`.
    Blob {
        /// Field sources.
        components: Vec<BlobComponent>,
        /// Iso-value.
        threshold: f64,
    },
    /// A triangle mesh from an OBJ file (loaded when the scene is prepared; instanced by path).
    Mesh {
        /// Resolved path.
        path: PathBuf,
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
            Shape::Mesh { .. } => "mesh",
            Shape::Csg { .. } => "csg",
        }
    }

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
            } => (
                "torus",
                vec![
                    ("center", Point(*center)),
                    ("major_radius", Number(*major_radius)),
                    ("minor_radius", Number(*minor_radius)),
                ],
            ),
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
                    Record(vec![
                        ("center", Point(c.center)),
                        ("radius", Number(c.radius)),
                        ("strength", Number(c.strength)),
                    ])
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
            Shape::Mesh {
                path,
                smooth,
                use_mtl,
            } => {
                let mut a = vec![("path", Arg::Path(path.clone()))];
                if *smooth {
                    a.push(("smooth", Bool(true)));
                }
                if *use_mtl {
                    a.push(("use_mtl", Bool(true)));
                }
                ("mesh", a)
            }
            Shape::Csg { .. } => return None,
        };
        Some(ShapeCall { name, args })
    }
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
}
