//! The renderer: IR scene → image. (Contract placeholder: the renderer branch replaces it.)

pub mod output;

use crate::diag::Diagnostic;
use crate::ir::Scene;

/// Options that are not part of the scene.
#[derive(Clone, Debug, Default)]
pub struct RenderOptions {
    /// Worker threads; 0 means all cores.
    pub threads: usize,
    /// Show a progress bar (the CLI sets this when stderr is a terminal).
    pub progress: bool,
}

/// A rendered 8-bit RGB image.
pub type Image = image::RgbImage;

/// Renders a scene.
pub fn render(scene: &Scene, options: &RenderOptions) -> Result<Image, Diagnostic> {
    let _ = options;
    Err(Diagnostic::new(
        crate::diag::Severity::Error,
        "rtc::unsupported",
        Some(scene.camera.span),
        "the renderer is not built yet",
    ))
}
