//! Textures and what materials build from them: colour sources (images, checker, stripes and
//! procedural patterns with colour maps), bump maps, and material mixes (material maps and
//! layers), all in the IR's terms.

use std::path::PathBuf;

use crate::pattern::{ColorMap, Field};
use crate::source::Span;
use glam::{DAffine3, DVec3};

/// A linear RGB colour (`ir::Color`, which this file cannot import: `ir` imports it).
type Color = DVec3;

/// Index into [`super::Scene::materials`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct MaterialId(pub u32);

/// Index into [`super::Scene::textures`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct TextureId(pub u32);

/// A bump map: a height texture whose gradient perturbs the normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bump {
    /// The height field (the green channel of an image, or a procedural texture's luminance).
    pub texture: TextureId,
    /// Strength of the perturbation.
    pub scale: f64,
}

/// A colour source over surface coordinates.
#[derive(Clone, Debug, PartialEq)]
pub enum Texture {
    /// An image file read through a surface mapping, v = 0 at the top row.
    Image {
        /// Resolved path.
        path: PathBuf,
        /// How surface points map to (u, v).
        mapping: Mapping,
        /// How a point between texel centres is read.
        filter: ImageFilter,
        /// Where the path was written.
        span: Span,
    },
    /// A tangent-space normal map: an image whose texels encode unit normals as
    /// `(n + 1) / 2`, x along increasing u, y up the picture (decreasing v), z out of the
    /// surface (the OpenGL convention), read bilinearly. As a bump it replaces the normal; as
    /// a colour it shows its texels.
    NormalMap {
        /// Resolved path.
        path: PathBuf,
        /// How surface points map to (u, v).
        mapping: Mapping,
        /// Where the path was written.
        span: Span,
    },
    /// A 3-D checkerboard of cubes of edge `size` in object space.
    Checker {
        /// First colour.
        a: Color,
        /// Second colour.
        b: Color,
        /// Cube edge length.
        size: f64,
    },
    /// Stripes along object-space x of width `size`.
    Stripes {
        /// First colour.
        a: Color,
        /// Second colour.
        b: Color,
        /// Stripe width.
        size: f64,
    },
    /// A procedural pattern read through a colour map (boxed: it is far larger than the rest).
    Pattern(Box<PatternTexture>),
}

/// Surface parameterisation used for texture lookups.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mapping {
    /// The shape's own (u, v).
    Uv,
    /// Equirectangular about object-space +Y (the north pole): v = θ/π from the pole, u = φ/2π.
    Spherical,
    /// Object-space x, z, wrapped to [0, 1).
    Planar,
    /// Angle about +Y and height.
    Cylindrical,
}

/// How an image is read between its texels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ImageFilter {
    /// The texel at `(int(u·(w−1)), int(v·(h−1)))`: the course's lookup, blocky up close.
    #[default]
    Nearest,
    /// The four texels around the point, weighted by distance (texel centres at
    /// `((i + ½)/w, (j + ½)/h)`, edges clamped): smooth up close.
    Bilinear,
    /// Trilinear through the image's mip chain, at the level whose texels match the pixel's
    /// footprint on the surface: smooth up close and free of moiré far away.
    Mipmap,
}

/// Where a pattern reads its point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PatternSpace {
    /// The hit's object-space point (the object's transform, instancing, CSG and motion carry
    /// the pattern with the object).
    Object,
    /// The hit's surface coordinates as the point (u, v, 0).
    Uv,
}

/// A pattern with its modifiers, placed relative to the object, read through a colour map.
#[derive(Clone, Debug, PartialEq)]
pub struct PatternTexture {
    /// The pattern, its warps and its wave.
    pub field: Field,
    /// The pattern's own space → object (or uv) space: the transforms written on the pattern,
    /// composed as an object's are (the point meets the inverse; `opt` inverts it once).
    pub placement: DAffine3,
    /// Where the point comes from.
    pub space: PatternSpace,
    /// Value → colour (with filter and transmit).
    pub map: ColorMap,
}

impl PatternTexture {
    /// The name of the language's constructor of its pattern (`marble`, `spherical_falloff`).
    pub fn name(&self) -> &'static str {
        use crate::pattern::Pattern as P;
        match &self.field.pattern {
            P::Gradient { .. } => "gradient",
            P::Checker => "checker",
            P::Hexagon => "hexagon",
            P::Brick { .. } => "brick",
            P::Radial => "radial",
            P::Onion => "onion",
            P::Spherical => "spherical_falloff",
            P::Cylindrical => "cylindrical_falloff",
            P::Boxed => "boxed",
            P::Planar => "planar_falloff",
            P::Square => "square",
            P::Triangular => "triangular",
            P::Spiral1 { .. } => "spiral1",
            P::Spiral2 { .. } => "spiral2",
            P::Agate { .. } => "agate",
            P::Bozo { .. } => "bozo",
            P::Granite { .. } => "granite",
            P::Marble { .. } => "marble",
            P::Wood { .. } => "wood",
            P::Leopard => "leopard",
            P::Ripples { .. } => "ripples",
            P::Waves { .. } => "waves",
            P::Wrinkles { .. } => "wrinkles",
            P::Dents { .. } => "dents",
            P::Crackle { .. } => "crackle",
            P::Cells { .. } => "cells",
            P::Function(_) => "function",
        }
    }
}

/// A material made of other materials, resolved per hit (boxed in [`super::Material`]: few
/// materials mix): how it combines its parts at a point.
#[derive(Clone, Debug, PartialEq)]
pub enum Mix {
    /// A material map: the pattern value of `texture` (its colour map unused) picks the two
    /// stops around it; `blend` interpolates every field between them, otherwise the lower stop
    /// holds (POV-Ray's material_map and texture_map with sharp or smooth entries).
    Map {
        /// The pattern texture whose value is read.
        texture: TextureId,
        /// (position, material), sorted by position.
        stops: Vec<(f64, MaterialId)>,
        /// Interpolate between stops (true) or switch at each stop (false).
        blend: bool,
    },
    /// Layers, top first: each layer's colour (with its filter and transmit) lies over the
    /// ones below; the finish is the layers' finishes weighted by how much of each shows.
    Layers(Vec<MaterialId>),
}
