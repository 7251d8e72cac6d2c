//! Scene analysis and optimisation between the IR and the renderer.

pub mod effects;

pub use effects::Effects;
