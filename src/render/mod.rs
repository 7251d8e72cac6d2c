//! The renderer: [`Prepared`] scene → [`Film`] → 8-bit image. It reads only the prepared scene
//! (never the IR's shapes) and prints nothing: progress and cancellation go through the
//! [`Progress`] callback its caller implements.
//!
//! Pipeline: [`tiles`] runs bands of rows on all cores; per pixel the [`sampler`] places the
//! samples and the [`camera`] makes their rays; the mode's [`integrator`] turns each ray into a
//! value per film channel (Whitted recursion with a [`shading`] model for shaded images, the
//! first hit for normal and depth images); the [`film`] averages and quantises (after the
//! [`flare`] post stage, when asked); [`output`] writes PNG or PPM atomically.
//!
//! Conventions (each reproduces the course references, see tests/golden.rs):
//! - Pixel (x, y) is sampled at offsets ((i+½)/f, (j+½)/f) of an f×f grid (f = 1: the centre);
//!   the course camera maps them as COURSE.md §2.4 ([`camera`]).
//! - Samples are averaged unclamped; the film clamps each channel to [0, 1] and stores
//!   `trunc(255·c)` ([`film`]).
//! - Phong per COURSE.md §2.5 with the ambient term per light (or once, by setting); a shadowed
//!   light keeps its ambient term; lights behind the surface (N·L ≤ 0) add nothing.
//! - `I = local + reflect·trace(R) + refract·trace(T)`, up to `max_depth` bounces; total internal
//!   reflection moves the refracted share to R ([`integrator::whitted`]).
//! - Secondary and shadow rays start just outside the hit point's floating-point error bound, on
//!   the side they leave to; shadow rays are aimed at the light from there ([`offset`]).
//! - Depth images: white at the nearest, black at the farthest hit of the image (or a fixed range).
//! - Random numbers (lens, area lights) are keyed by (pixel, sample, seed) ([`sampler`]), so the
//!   bytes do not depend on the thread count, and a pixel's value does not depend on which tile
//!   computed it (image-wide passes such as the depth range run before the pixels).

pub mod adaptive;
pub mod aov;
pub mod bump;
pub mod camera;
pub mod explain;
pub mod exr;
pub mod film;
pub mod flare;
pub mod integrator;
pub mod merge;
pub mod offset;
pub mod output;
pub mod part;
pub mod progress;
pub mod progressive;
pub mod record;
pub mod region;
pub mod sampler;
pub mod shading;
pub mod shard;
pub mod texture;
pub mod tiles;

use glam::DVec3;

use crate::diag::{Diagnostic, Diagnostics, Severity};
use crate::geometry::Ray;
use crate::ir::{Color, Scene};
use crate::opt::Prepared;
use camera::{Camera, MovingCamera};
use film::Film;
use integrator::Integrator;
use sampler::{Grid, PixelSampler, Rng};
use shading::{BATCH, Ctx, LightShare};
use shard::{Rows, Shard};

pub use film::{Channel, Stats};
pub use progress::{CANCELLED, Progress, Silent};
pub use region::Region;

/// Options that are not part of the scene.
#[derive(Clone, Debug, Default)]
pub struct RenderOptions {
    /// Worker threads; 0 means all cores.
    pub threads: usize,
    /// Render only this shard's rows (the other rows of the film stay zero); `None`: all.
    pub shard: Option<Shard>,
    /// AOV layers to add to the film after the colour (`Channel::AOVS`; empty: none).
    pub aovs: Vec<Channel>,
}

/// A rendered 8-bit RGB image.
pub type Image = image::RgbImage;

/// Prepares and renders a scene without progress reports: the whole pipeline in one call
/// (tests, benchmarks). Fails with every problem preparing found, or the render's one error.
pub fn render_scene(scene: &Scene, options: &RenderOptions) -> Result<Film, Diagnostics> {
    let prepared = crate::opt::prepare(scene)?;
    render(&prepared, options, &Silent).map_err(|d| Diagnostics { items: vec![d] })
}

/// [`render_scene`], quantised to 8-bit RGB.
pub fn render_image(scene: &Scene, options: &RenderOptions) -> Result<Image, Diagnostics> {
    render_scene(scene, options).map(|f| f.to_image())
}

/// Renders a prepared scene to a floating-point film (with statistics).
///
/// Supersampling averages the unclamped samples; the film clamps the average when it quantises.
/// Against the 4×4 reference `scene01-zoom-ss-reflect-lights-shadows.png` this gives a mean error
/// of 0.054 levels, clamping each sample first 0.057 (and 6.94 vs 6.95 on the texture scene).
pub fn render(
    scene: &Prepared,
    options: &RenderOptions,
    progress: &dyn Progress,
) -> Result<Film, Diagnostic> {
    render_region(scene, options, None, progress)
}

/// [`render`] of a sub-rectangle of the image only (`None`: the whole image): the film is the
/// region's size and each of its pixels equals the whole render's, except that adaptive
/// refinement compares a border pixel only with neighbours inside the region and the lens
/// flare (a post stage over the whole image) is not applied. Errors when the region does not
/// fit the image or comes with a shard.
pub fn render_region(
    scene: &Prepared,
    options: &RenderOptions,
    region: Option<Region>,
    progress: &dyn Progress,
) -> Result<Film, Diagnostic> {
    let pool = tiles::pool(options.threads)?;
    let sampler = PixelSampler::new(scene.settings().sampling);
    let view = View::new(scene);
    let integrator = Integrator::new(scene, &view, sampler.first, &pool)?;
    let channels = integrator.channels();
    let (full_w, full_h) = (view.camera.width(), view.camera.height());
    if let Some(r) = region {
        r.check(full_w, full_h)?;
        if options.shard.is_some() {
            return Err(Diagnostic::new(
                Severity::Error,
                region::REGION,
                None,
                "a region cannot be rendered in shards",
            )
            .with_help("render the region in one process, or shard the whole image"));
        }
    }
    let r = region.unwrap_or(Region {
        x: 0,
        y: 0,
        width: full_w,
        height: full_h,
    });
    let (w, h) = (r.width, r.height);
    // A shard's first pass covers a one-row halo when adaptive refinement will read it.
    let (first_rows, own_rows) = match options.shard {
        None => (Rows::All, Rows::All),
        Some(s) if sampler.refine.is_some() => (Rows::WithHalo(s), Rows::Of(s)),
        Some(s) => (Rows::Of(s), Rows::Of(s)),
    };
    let refine_rows = if sampler.refine.is_some() {
        own_rows.count(h)
    } else {
        0
    };
    let aov_rows = if options.aovs.is_empty() {
        0
    } else {
        own_rows.count(h)
    };
    progress.start(first_rows.count(h) + refine_rows + aov_rows);
    let first = sampler.first;
    let n = channels.len();
    let span = view.span(&integrator, n);
    let (mut values, mut stats) = tiles::run_spans(
        &pool,
        (w, h),
        n,
        span,
        first_rows,
        progress,
        |x, y, ctx, out| view.average_span(&integrator, (first, n), r.x + x, r.y + y, ctx, out),
    )?;
    if let Some((fine, threshold)) = sampler.refine {
        // Adaptive sampling: a pixel takes the finer grid where `adaptive::Criterion` says
        // (contrast to a 4-neighbour, or in a scene without random numbers a predicted change
        // of 8-bit level). Both passes are pure per pixel.
        let criterion = adaptive::Criterion::new(first, fine, threshold, scene.settings().encoding)
            .with_noise(view.random);
        let coarse = &values;
        let at = |x: u32, y: u32| coarse[(y as usize * w as usize + x as usize) * n];
        let (refined, more) = tiles::run(&pool, w, h, n, own_rows, progress, |x, y, ctx, out| {
            let here = (y as usize * w as usize + x as usize) * n;
            if !criterion.refines(at, x, y, w, h) {
                out.copy_from_slice(&coarse[here..here + n]);
                return;
            }
            ctx.stats.refined_pixels += 1;
            let (x, y) = (r.x + x, r.y + y);
            view.average(&integrator, fine, refine_start(fine), x, y, ctx, out);
        })?;
        values = refined;
        stats.add(&more);
    }
    if let (true, Some(f), None) = (scene.effects().flare, scene.settings().flare, region) {
        // A post stage over the whole image (shaded mode: colour is the only channel).
        let sources = flare::sources(scene, &view.camera, &f, &mut stats);
        flare::apply(&sources, &f, w, h, n, &mut values);
    }
    let mut film = Film::new(w, h, channels, values, stats, scene.settings().encoding);
    if !options.aovs.is_empty() {
        let (values, _) = aov::render(
            scene,
            &view,
            first,
            &options.aovs,
            r,
            own_rows,
            &pool,
            progress,
        )?;
        let n = options.aovs.len();
        for (i, c) in options.aovs.iter().enumerate() {
            film.push_channel(*c, values.iter().skip(i).step_by(n).copied().collect());
        }
    }
    progress.finish();
    Ok(film)
}

/// The first sample number of a refined pixel's finer grid: past the first grid's numbers (so
/// random decisions differ) and aligned to the grid's size rounded up to a power of two, so the
/// grid's lens and light points are a whole stratified block of the Sobol' sequence (a block
/// starting right after the first grid, at 1 for a 1×1 first grid, loses that stratification:
/// docs/accuracy-study.md measured RMSE 0.0182 against 0.0160 on showcase).
pub fn refine_start(fine: Grid) -> u32 {
    fine.len().next_power_of_two()
}

/// What turns a pixel sample into a camera ray.
pub struct View<'a> {
    /// The scene.
    pub scene: &'a Prepared,
    /// Primary rays.
    pub camera: Camera,
    /// Whether anything draws random numbers (a lens or an area light).
    pub random: bool,
    /// The scene's seed.
    pub seed: u64,
    /// Whether camera samples spread over the open shutter (something moves while it is open).
    pub motion_blur: bool,
    /// The camera's motion while the shutter is open, if it moves.
    pub moving_camera: Option<MovingCamera>,
    /// Whether area-light cells are dealt out over a pixel's samples.
    pub spread_lights: bool,
}

/// The random stream of a camera sample's time (apart from the lens's 0 and the lights').
const TIME_STREAM: u32 = 0xffff_fffe;

/// The per-axis grid offsets [`View::average_span`] keeps at hand (a 16×16 grid's); finer
/// grids compute theirs sample by sample.
const AXIS_OFFSETS: usize = 16;

impl View<'_> {
    /// The view of a prepared scene.
    pub fn new(scene: &Prepared) -> View<'_> {
        View {
            scene,
            camera: Camera::new(scene.camera()),
            random: scene.random(),
            seed: scene.settings().seed,
            spread_lights: scene.settings().light_samples == crate::ir::LightSampling::Spread,
            motion_blur: scene.effects().motion_blur,
            moving_camera: MovingCamera::of(scene.camera()),
        }
    }

    /// The lens sample of camera sample `index` of pixel (x, y), (½, ½) without a lens.
    pub fn lens(&self, x: u32, y: u32, index: u32) -> (f64, f64) {
        if self.camera.has_lens() {
            Rng::new(x, y, index, self.seed).get2(0)
        } else {
            (0.5, 0.5)
        }
    }

    /// The camera ray of one sample: at shutter open, or with motion blur at a time drawn from
    /// the sample's own stream (Owen-scrambled Sobol' over the pixel's samples, so the times
    /// are stratified across the shutter and decorrelated from the sub-pixel positions).
    pub fn ray(&self, x: u32, y: u32, sx: f64, sy: f64, lens: (f64, f64), rng: &Rng) -> Ray {
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
    pub fn camera_sample(
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

    /// How many pixels of a row [`View::average_span`] takes at once for `channels` per pixel:
    /// a packet's worth when a scene the Whitted packets trace has plain pinhole camera rays
    /// (their samples then fill whole packets across pixels: a 3×3 grid's nine samples alone
    /// would leave seven of sixteen lanes idle), else one.
    pub fn span(&self, integrator: &Integrator<'_>, channels: usize) -> usize {
        if channels == 1 && integrator.batch().is_some() && self.pinhole() {
            BATCH
        } else {
            1
        }
    }

    /// Whether camera rays are plain pinhole rays, nothing set up per sample.
    fn pinhole(&self) -> bool {
        !self.random
            && !self.spread_lights
            && !self.motion_blur
            && !self.camera.has_lens()
            && BATCH <= camera::PINHOLE_BATCH
    }

    /// [`View::average`] of the pixels from (x0, y) rightwards, `channels` values each in
    /// `out`: when [`View::span`] is more than one, the samples of all of them, pixel after
    /// pixel, traced in packets of [`BATCH`] (each pixel's value bit for bit the one `average`
    /// gives it: its samples summed in the same order), else pixel by pixel.
    pub fn average_span(
        &self,
        integrator: &Integrator<'_>,
        (grid, channels): (Grid, usize),
        x0: u32,
        y: u32,
        ctx: &mut Ctx,
        out: &mut [Color],
    ) {
        let w = integrator
            .batch()
            .filter(|_| self.span(integrator, channels) > 1 && out.len() <= BATCH);
        let Some(w) = w else {
            for (k, px) in out.chunks_exact_mut(channels).enumerate() {
                self.average(integrator, grid, 0, x0 + k as u32, y, ctx, px);
            }
            return;
        };
        let per_pixel = grid.len();
        let mut sums = [Color::ZERO; BATCH];
        let mut colors = [Color::ZERO; BATCH];
        // The grid's offsets along one axis once per span, `Grid::offset`'s (i + ½)/f, not two
        // divisions of each kind per sample (a table of every sample's pair was a 4 kB
        // `memset` per span, 2% of the duck's render).
        let factor = grid.factor();
        let mut axis = [0.0; AXIS_OFFSETS];
        for (i, a) in axis.iter_mut().enumerate().take(factor as usize) {
            *a = grid.offset(i as u32).0;
        }
        let offset = |(column, row): (u32, u32)| match factor as usize <= AXIS_OFFSETS {
            true => (axis[column as usize], axis[row as usize]),
            false => grid.offset(row * factor + column),
        };
        // Each packet's samples: (pixel of the span, the sample's column and row in the grid),
        // pixel after pixel.
        let mut samples = [(0usize, (0u32, 0u32)); BATCH];
        let (mut pixel, mut cell) = (0, (0, 0));
        while pixel < out.len() {
            let mut m = 0;
            while m < BATCH && pixel < out.len() {
                samples[m] = (pixel, cell);
                m += 1;
                cell.0 += 1;
                if cell.0 == factor {
                    cell = (0, cell.1 + 1);
                    if cell.1 == factor {
                        (pixel, cell) = (pixel + 1, (0, 0));
                    }
                }
            }
            let at = |j: usize| (x0 + samples[j].0 as u32, offset(samples[j].1));
            let rays = self.camera.pinhole_packet(y, at, m);
            ctx.stats.camera_rays += m as u64;
            w.trace_lanes(&rays, m, ctx, &mut colors[..m]);
            for (&(p, _), c) in samples[..m].iter().zip(&colors[..m]) {
                sums[p] += *c;
            }
        }
        for (o, s) in out.iter_mut().zip(&sums) {
            *o = *s / f64::from(per_pixel);
        }
    }

    /// The mean of the integrator's (unclamped) values over the samples of `grid`, per channel,
    /// into `out`; sample numbers start at `first_index`.
    #[allow(clippy::too_many_arguments)]
    fn average(
        &self,
        integrator: &Integrator<'_>,
        grid: Grid,
        first_index: u32,
        x: u32,
        y: u32,
        ctx: &mut Ctx,
        out: &mut [Color],
    ) {
        out.fill(Color::ZERO);
        // One sample a pixel has no other ray to overlap with: the batch would only add its
        // staging (measured: +15% render time on the 1-sample 100k-sphere scene).
        if let (Some(w), [out], true) = (integrator.batch(), &mut *out, grid.len() > 1) {
            // The samples in batches, summed in the same order as one by one below.
            let mut rays = [Ray::new(DVec3::ZERO, DVec3::ZERO); BATCH];
            let mut colors = [Color::ZERO; BATCH];
            // What `camera_sample` does then is only the ray (and its count).
            let pinhole = self.pinhole();
            let mut k = 0;
            while k < grid.len() {
                let m = (grid.len() - k).min(BATCH as u32);
                if pinhole {
                    // Nothing to set up per sample: the rays of the batch at once.
                    let mut offsets = [(0.0, 0.0); BATCH];
                    for (j, o) in (k..k + m).zip(&mut offsets) {
                        *o = grid.offset(j);
                    }
                    let m = m as usize;
                    self.camera
                        .pinhole_rays(x, y, &offsets[..m], &mut rays[..m]);
                    ctx.stats.camera_rays += m as u64;
                } else {
                    for (j, ray) in (k..k + m).zip(&mut rays) {
                        *ray = self.camera_sample(
                            x,
                            y,
                            first_index + j,
                            (j, grid.len()),
                            grid.offset(j),
                            ctx,
                        );
                    }
                }
                let m = m as usize;
                w.trace_batch(&rays[..m], ctx, &mut colors[..m]);
                for c in &colors[..m] {
                    *out += *c;
                }
                k += m as u32;
            }
            *out /= f64::from(grid.len());
            return;
        }
        let mut sample = [Color::ZERO; film::MAX_CHANNELS];
        let sample = &mut sample[..out.len()];
        for k in 0..grid.len() {
            let ray =
                self.camera_sample(x, y, first_index + k, (k, grid.len()), grid.offset(k), ctx);
            integrator.sample(&ray, ctx, sample);
            for (o, s) in out.iter_mut().zip(sample.iter()) {
                *o += *s;
            }
        }
        let n = f64::from(grid.len());
        for o in out.iter_mut() {
            *o /= n;
        }
    }
}
