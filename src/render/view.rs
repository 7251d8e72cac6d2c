//! The view: what turns a pixel's sample into a camera ray — the camera, the sample's random
//! numbers (lens, shutter time) and the light cells it takes. At the bottom of the render
//! room: the pixel driver ([`super::pixel`]) and image-wide passes use it; it knows no
//! integrator.

use crate::geometry::Ray;
use crate::opt::Prepared;

use super::camera::{self, Camera, MovingCamera};
use super::context::{BATCH, Ctx};
use super::deal::LightShare;
use super::sampler::{Grid, Rng};

/// The camera rays of an image's first samples, as an image-wide pass traces them before any
/// pixel: what an integrator needs of the view, and no more.
pub(crate) struct FirstRays<'v> {
    /// The image's width and height in pixels.
    pub(crate) size: (u32, u32),
    /// Samples per pixel.
    pub(crate) samples: u32,
    /// The camera ray of sample `k` at pixel (x, y) (a pure function of its arguments).
    pub(crate) ray: &'v (dyn Fn(u32, u32, u32) -> Ray + Sync),
}

/// What turns a pixel sample into a camera ray.
pub(crate) struct View {
    /// Primary rays.
    pub(crate) camera: Camera,
    /// Whether anything draws random numbers (a lens or an area light).
    pub(crate) random: bool,
    /// The scene's seed.
    pub(crate) seed: u64,
    /// Whether camera samples spread over the open shutter (something moves while it is open).
    motion_blur: bool,
    /// The camera's motion while the shutter is open, if it moves.
    moving_camera: Option<MovingCamera>,
    /// Whether area-light cells are dealt out over a pixel's samples.
    pub(crate) spread_lights: bool,
}

/// The random stream of a camera sample's time (apart from the lens's 0 and the lights').
const TIME_STREAM: u32 = 0xffff_fffe;

impl View {
    /// The view of a prepared scene.
    pub(crate) fn new(scene: &Prepared) -> View {
        View {
            camera: Camera::new(scene.camera()),
            random: scene.random(),
            seed: scene.settings().seed,
            spread_lights: scene.settings().light_samples == crate::ir::LightSampling::Spread,
            motion_blur: scene.effects().motion_blur,
            moving_camera: MovingCamera::of(scene.camera()),
        }
    }

    /// The lens sample of camera sample `index` of pixel (x, y), (½, ½) without a lens.
    fn lens(&self, x: u32, y: u32, index: u32) -> (f64, f64) {
        if self.camera.has_lens() {
            Rng::new(x, y, index, self.seed).get2(0)
        } else {
            (0.5, 0.5)
        }
    }

    /// The camera ray of one sample: at shutter open, or with motion blur at a time drawn from
    /// the sample's own stream (Owen-scrambled Sobol' over the pixel's samples, so the times
    /// are stratified across the shutter and decorrelated from the sub-pixel positions).
    fn ray(&self, x: u32, y: u32, sx: f64, sy: f64, lens: (f64, f64), rng: &Rng) -> Ray {
        if !self.motion_blur {
            return self.camera.ray(x, y, sx, sy, lens);
        }
        let time = rng.get2(TIME_STREAM).0;
        let camera = match &self.moving_camera {
            Some(m) => m.at(time),
            None => self.camera,
        };
        camera.ray(x, y, sx, sy, lens).at_time(time)
    }

    /// Sets `ctx` up for camera sample number `index` of pixel (x, y), the `slot.0`-th of
    /// `slot.1` samples of its grid, at sub-pixel `offset`, and returns its ray.
    #[inline]
    pub(crate) fn camera_sample(
        &self,
        x: u32,
        y: u32,
        index: u32,
        slot: (u32, u32),
        (sx, sy): (f64, f64),
        ctx: &mut Ctx,
    ) -> Ray {
        // Only lenses and area lights draw random numbers; skip keying them otherwise.
        if self.random {
            ctx.rng = Rng::new(x, y, index, self.seed);
        }
        if self.spread_lights {
            ctx.lights = LightShare {
                slot: slot.0,
                size: slot.1,
            };
        }
        let lens = if self.camera.has_lens() {
            ctx.rng.get2(0)
        } else {
            (0.5, 0.5)
        };
        let ray = self.ray(x, y, sx, sy, lens, &ctx.rng);
        ctx.stats.camera_rays += 1;
        ray
    }

    /// Whether camera rays are plain pinhole rays, nothing set up per sample.
    pub(crate) fn pinhole(&self) -> bool {
        !self.random
            && !self.spread_lights
            && !self.motion_blur
            && !self.camera.has_lens()
            && self.camera.is_planar()
            && BATCH <= camera::PINHOLE_BATCH
    }

    /// The camera ray of sample `k` of `grid` at pixel (x, y), keyed by the pixel, the sample
    /// and the seed alone (no per-tile state): what image-wide passes trace before the pixels.
    pub(crate) fn sample_ray(&self, x: u32, y: u32, k: u32, grid: Grid) -> Ray {
        let (sx, sy) = grid.offset(k);
        let rng = Rng::new(x, y, k, self.seed);
        self.ray(x, y, sx, sy, self.lens(x, y, k), &rng)
    }

    /// The rays of the first `grid` of every pixel, for an integrator's image-wide pass.
    pub(crate) fn first_rays<'v>(
        &self,
        grid: Grid,
        ray: &'v (dyn Fn(u32, u32, u32) -> Ray + Sync),
    ) -> FirstRays<'v> {
        FirstRays {
            size: (self.camera.width(), self.camera.height()),
            samples: grid.len(),
            ray,
        }
    }
}
