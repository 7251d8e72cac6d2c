//! The lens flare a scene asks for: a post stage drawn over the film for every light the camera
//! sees (docs/language.md, `flare`).

/// Lens flare parameters (each with its default and range in [`Flare::RANGES`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Flare {
    /// Ghost discs along the line from the light's image position through the image centre.
    pub(crate) ghosts: u32,
    /// Spacing of the ghosts as a fraction of the light-to-centre vector.
    pub(crate) dispersal: f64,
    /// Radius of the halo ring around the light, as a fraction of the image diagonal (0: none).
    pub(crate) halo: f64,
    /// Number of star streaks through the light (0: none).
    pub(crate) streaks: u32,
    /// Lights whose seen brightness (luminance × visible fraction) is below this flare not.
    pub(crate) threshold: f64,
    /// Overall strength of the flare.
    pub(crate) intensity: f64,
}

impl Default for Flare {
    fn default() -> Flare {
        Flare {
            ghosts: 4,
            dispersal: 0.4,
            halo: 0.15,
            streaks: 6,
            threshold: 0.1,
            intensity: 0.5,
        }
    }
}

impl Flare {
    /// Each parameter's allowed range (inclusive), in declaration order.
    pub(crate) const RANGES: [(&'static str, f64, f64); 6] = [
        ("ghosts", 0.0, 16.0),
        ("dispersal", 0.0, 2.0),
        ("halo", 0.0, 1.0),
        ("streaks", 0.0, 32.0),
        ("threshold", 0.0, 1000.0),
        ("intensity", 0.0, 10.0),
    ];
}
