//! What a ray sees when it meets nothing and what lies along its way: the sky and the fog a
//! scene asks for (`render { sky: .., fog: .. }`, docs/language.md §19).

use glam::DVec3;

use super::texture::TextureId;

/// The sky: a texture read along the direction of a ray that meets nothing, in place of the
/// background colour (POV-Ray's `sky_sphere`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sky {
    /// The texture: a pattern or checker read at the ray's unit direction, or an image read as a
    /// latitude–longitude (equirectangular) map.
    pub texture: TextureId,
    /// The sky turned about +Y by this angle (radians, counter-clockwise seen from above).
    pub rotation: f64,
    /// The sky's colour is multiplied by this (≥ 0).
    pub strength: f64,
}

/// Fog along every ray that travels outside objects (POV-Ray's `fog`): after a distance `d`
/// through it a ray keeps `max(exp(−d/distance), transmit)` of its colour, tinted by `filter`,
/// and takes the rest from `color`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fog {
    /// The fog's colour (linear RGB).
    pub color: DVec3,
    /// The distance over which a ray keeps 1/e of its light (> 0).
    pub distance: f64,
    /// Share of the light passing the fog tinted by its colour (POV-Ray's fog filter).
    pub filter: f64,
    /// The least transmittance, however far the ray goes (POV-Ray's fog transmit).
    pub transmit: f64,
    /// Ground fog: the density falls off above an altitude (`None`: constant fog).
    pub ground: Option<GroundFog>,
    /// A pattern that thins the fog where its value is high (POV-Ray's fog turbulence).
    pub pattern: Option<FogPattern>,
}

/// A pattern modulating fog as POV-Ray's fog turbulence does: a segment of length `d` counts as
/// `d·(1 − exp(−d/distance)·min(1, depth·v))` long, `v` the pattern's value at its midpoint.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FogPattern {
    /// The pattern texture (its colour map unused).
    pub texture: TextureId,
    /// How strongly the value thins the fog (POV-Ray's `turb_depth`).
    pub depth: f64,
}

/// Ground fog's density: 1 at and below `offset` along +Y, `1 / (1 + h²)` at `h = (y −
/// offset) / altitude` above it (POV-Ray's `fog_type 2`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GroundFog {
    /// The height up to which the fog is full.
    pub offset: f64,
    /// The height scale of the falloff above `offset` (> 0).
    pub altitude: f64,
}
