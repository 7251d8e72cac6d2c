//! Arbitrary output variables (AOVs): per-pixel facts about the first surface each camera
//! sample hits (distance, normal, surface colour, object), for compositing and denoising.
//!
//! They are a pass of their own over the first sampling grid, run only when asked for
//! (`RenderOptions::aovs`), so a render without them does no extra work and keeps its bytes.
//! The samples are the colour pass's first-grid samples (same positions, lens points and
//! times), so the layers line up with the image; adaptive refinement does not refine them.

use crate::geometry::Ray;
use crate::ir::{Color, Visibility};
use crate::num::Norm;
use crate::opt::Prepared;

use super::film::{Channel, Stats};
use super::integrator::whitted::Whitted;
use super::progress::Progress;
use super::region::Region;
use super::sampler::Grid;
use super::shard::Rows;
use super::tiles;
use super::view::View;
use crate::diag::Diagnostic;

/// Most distinct objects counted in one pixel's vote (a 16×16 grid has 256 samples).
const MAX_VOTES: usize = 256;

/// The AOV layers asked for, in order, over the `rows` of the image `region`: one value per
/// pixel and channel, interleaved per pixel like [`tiles::run`]'s output.
#[allow(clippy::too_many_arguments)]
pub(crate) fn render(
    scene: &Prepared,
    view: &View,
    grid: Grid,
    aovs: &[Channel],
    region: Region,
    rows: Rows,
    pool: &rayon::ThreadPool,
    progress: &dyn Progress,
) -> Result<(Vec<Color>, Stats), Diagnostic> {
    let whitted = Whitted::new(scene);
    let (w, h) = (region.width, region.height);
    tiles::run(pool, w, h, aovs.len(), rows, progress, |x, y, ctx, out| {
        let (x, y) = (region.x + x, region.y + y);
        let mut pixel = PixelAovs::default();
        for k in 0..grid.len() {
            let ray = view.camera_sample(x, y, k, (k, grid.len()), grid.offset(k), ctx);
            pixel.add(scene, &whitted, &ray);
        }
        for (o, c) in out.iter_mut().zip(aovs) {
            *o = pixel.value(*c, grid.len());
        }
    })
}

/// One pixel's sums over its samples.
struct PixelAovs {
    hits: u32,
    distance: f64,
    normal: Color,
    albedo: Color,
    /// (object index + 1, samples that hit it); 0 is the background.
    votes: Vec<(u32, u32)>,
}

impl Default for PixelAovs {
    fn default() -> PixelAovs {
        PixelAovs {
            hits: 0,
            distance: 0.0,
            normal: Color::ZERO,
            albedo: Color::ZERO,
            votes: Vec::new(),
        }
    }
}

impl PixelAovs {
    /// Adds one camera sample: what its ray hits first.
    fn add(&mut self, scene: &Prepared, whitted: &Whitted<'_>, ray: &Ray) {
        let Some(hit) = scene.seen_hit(ray, 0.0, f64::INFINITY, Visibility::NO_IMAGE) else {
            self.vote(0);
            return;
        };
        let stored = scene.material(hit.material);
        let mixed;
        let mat = match stored.mix {
            Some(_) => {
                mixed = super::mix::resolve(scene, &hit, scene.world().frame(&hit), stored);
                &mixed
            }
            None => stored,
        };
        let facing = if hit.normal.dot(ray.dir) > 0.0 {
            -hit.normal
        } else {
            hit.normal
        };
        self.hits += 1;
        self.distance += hit.t * ray.dir.norm();
        self.normal += whitted.bumped(&hit, facing, mat);
        self.albedo += whitted.base_color(&hit, mat);
        self.vote(scene.world().object(&hit) + 1);
    }

    fn vote(&mut self, id: u32) {
        if let Some((_, n)) = self.votes.iter_mut().find(|(v, _)| *v == id) {
            *n += 1;
        } else if self.votes.len() < MAX_VOTES {
            self.votes.push((id, 1));
        }
    }

    /// The pixel's value of `channel` over `samples` samples.
    fn value(&self, channel: Channel, samples: u32) -> Color {
        let n = f64::from(samples);
        match channel {
            Channel::Color => Color::ZERO,
            Channel::Depth if self.hits == 0 => Color::new(f64::INFINITY, 0.0, 0.0),
            Channel::Depth => Color::new(self.distance / f64::from(self.hits), 0.0, 0.0),
            Channel::Normal => self.normal / n,
            Channel::Alpha => Color::new(f64::from(self.hits) / n, 0.0, 0.0),
            Channel::Albedo => self.albedo / n,
            // The most samples win; among equals the first seen (the votes keep sample order).
            Channel::Object => {
                let best = self
                    .votes
                    .iter()
                    .fold((0, 0), |b, &(id, c)| if c > b.1 { (id, c) } else { b });
                Color::new(f64::from(best.0), 0.0, 0.0)
            }
        }
    }
}
