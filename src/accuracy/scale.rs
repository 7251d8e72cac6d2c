//! Sweeping a big scene at a reduced resolution (the same view with fewer, larger pixels),
//! or on a region of it.

use crate::ir::{Projection, Scene};
use crate::render::Region;

/// The default pixel budget of a sweep: a scene with more pixels is swept at the scale that
/// brings it under this (256×256), so a sweep of dozens of renders takes minutes.
pub const DEFAULT_MAX_PIXELS: u64 = 256 * 256;

/// The resolution a sweep renders at.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepSize {
    /// The scene's own width.
    pub full_width: u32,
    /// The scene's own height.
    pub full_height: u32,
    /// The factor applied to each side.
    pub scale: f64,
    /// The swept width.
    pub width: u32,
    /// The swept height.
    pub height: u32,
    /// The region rendered, in the swept image's pixels (`None`: all of it).
    pub region: Option<Region>,
}

impl SweepSize {
    /// The size of the images rendered: the region's, or the swept image's.
    pub(crate) fn rendered(&self) -> (u32, u32) {
        self.region
            .map_or((self.width, self.height), |r| (r.width, r.height))
    }

    /// How many times more pixels the full image has than a rendered one (what a measured
    /// time is multiplied by to predict the full render's; for a region this assumes its
    /// pixels cost what the image's do on average).
    pub(crate) fn pixel_ratio(&self) -> f64 {
        let (w, h) = self.rendered();
        (f64::from(self.full_width) * f64::from(self.full_height)) / (f64::from(w) * f64::from(h))
    }
}

/// The scale that brings `width × height` under `max_pixels` (1 when it already is).
pub(crate) fn auto_scale(width: u32, height: u32, max_pixels: u64) -> f64 {
    let pixels = u64::from(width) * u64::from(height);
    if pixels <= max_pixels {
        1.0
    } else {
        (max_pixels as f64 / pixels as f64).sqrt()
    }
}

/// Scales `scene`'s image by `scale` per side (each side rounded, at least 1 pixel) keeping the
/// view: a perspective camera keeps its field of view; the course camera's `up`, whose length
/// is one pixel at the image plane, is divided by the actual ratio of heights.
pub(crate) fn scale_scene(scene: &mut Scene, scale: f64) -> SweepSize {
    let c = &mut scene.camera;
    let (full_width, full_height) = (c.width, c.height);
    let side = |n: u32| ((f64::from(n) * scale).round() as u32).max(1);
    let (width, height) = (side(full_width), side(full_height));
    if matches!(c.projection, Projection::Course) && height != full_height {
        c.up *= f64::from(full_height) / f64::from(height);
    }
    c.width = width;
    c.height = height;
    SweepSize {
        full_width,
        full_height,
        scale,
        width,
        height,
        region: None,
    }
}
