//! The scene IR: plain data produced by the language evaluator and the legacy front ends, consumed
//! by the preparation stage (`opt`). No parsing types and no render types live here.
//!
//! Conventions: world units are free (the course uses pixels), `f64` everywhere, colours are linear
//! RGB with no upper clamp, every item carries the [`Span`] of the source that made it.

use glam::DVec3;

use crate::source::Span;

mod atmosphere;
mod call;
mod camera;
mod flare;
mod light;
pub mod limits;
mod loaded;
mod mesh;
mod motion;
mod object;
mod placement;
pub mod provenance;
mod settings;
mod shape_parts;
mod texture;

pub use atmosphere::{Fog, FogPattern, GroundFog, Sky};
pub(crate) use call::{Arg, COMPILED_FUNCTION};
pub use camera::{Camera, Projection};
pub(crate) use flare::Flare;
pub use light::{Fade, Light, LightKind, PARALLEL_DISTANCE, Spot, cylinder_share};
pub use loaded::Loaded;
pub use mesh::{InlineMesh, MeshSource};
pub(crate) use motion::{CameraMotion, Motion, Shutter};
pub use object::{CsgOp, Object, Shape, Visibility};
pub use placement::Transform;
pub use provenance::Provenance;
pub use settings::{
    AmbientConvention, DepthRange, Encoding, Integrator, LightSampling, PathTracing, RenderMode,
    RenderSettings, Sampling, ShadingModel,
};
pub(crate) use settings::{GoochParams, LANGUAGE_CUTOFF};
pub use shape_parts::{
    BlobComponent, Container, GlyphCurve, HeightGrid, PrismSweep, Spindle, Spline, SweepSpline,
    TextAlign, TextGlyphs, poly_terms,
};
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
    /// Whether the surface emits on both sides (the default) or only on the side its normal
    /// points to (the outside of a solid; `u × v` of a quad). The path tracer's rule; Whitted
    /// adds the emission wherever the surface is seen.
    pub emits_both_sides: bool,
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
            emits_both_sides: true,
            span: Span::default(),
        }
    }
}
