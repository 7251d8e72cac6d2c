//! Integrators: what a camera ray contributes to each film channel, one type per render mode
//! with its own state. Adding a mode is a variant of `ir::RenderMode`, a file here and a line
//! in [`Integrator::new`], [`Integrator::channels`] and [`Integrator::sample`].

pub(crate) mod depth;
mod normal;
mod path;
mod uv;
pub mod whitted;

use crate::diag::Diagnostic;
use crate::geometry::Ray;
use crate::ir::{Color, Integrator as Method, RenderMode, Visibility};
use crate::opt::Prepared;

use super::context::Ctx;
use super::film::Channel;
use super::path::Path;
use super::record::{NoRecord, Recorder};
use super::view::FirstRays;
use depth::DepthImage;
use normal::NormalImage;
use path::PathTracer;
use uv::UvImage;
use whitted::Whitted;

/// The integrator of a render (a closed set, dispatched by `match`).
pub(crate) enum Integrator<'a> {
    /// Shaded colour: Whitted recursion with a shading model.
    Whitted(Whitted<'a>),
    /// Shaded colour with global illumination: the path tracer (boxed: its tables make it
    /// far larger than the others).
    Path(Box<PathTracer<'a>>),
    /// The first hit's normal as a colour.
    Normal(NormalImage<'a>),
    /// The first hit's distance as grey.
    Depth(DepthImage<'a>),
    /// The first hit's surface coordinates as a colour.
    Uv(UvImage<'a>),
}

impl<'a> Integrator<'a> {
    /// The integrator for `scene`'s mode. Image-wide passes run here, before any pixel (the
    /// depth range of an automatic depth image, over the camera samples of `first`).
    pub(crate) fn new(
        scene: &'a Prepared,
        first: &FirstRays<'_>,
        pool: &rayon::ThreadPool,
    ) -> Result<Integrator<'a>, Diagnostic> {
        Ok(match scene.settings().mode {
            RenderMode::Shaded => match scene.settings().integrator {
                Method::Whitted => Integrator::Whitted(Whitted::new(scene)),
                Method::Path(p) => Integrator::Path(Box::new(PathTracer::new(scene, p))),
            },
            RenderMode::Normal => Integrator::Normal(NormalImage::new(scene)),
            RenderMode::Uv => Integrator::Uv(UvImage::new(scene)),
            RenderMode::Depth(range) => {
                Integrator::Depth(DepthImage::new(scene, range, first, pool)?)
            }
        })
    }

    /// The film channels it fills, in the order of [`Integrator::sample`]'s output.
    pub(crate) fn channels(&self) -> &'static [Channel] {
        match self {
            Integrator::Whitted(_)
            | Integrator::Path(_)
            | Integrator::Normal(_)
            | Integrator::Depth(_)
            | Integrator::Uv(_) => &[Channel::Color],
        }
    }

    /// The Whitted integrator when it can trace a pixel's samples side by side
    /// ([`Whitted::trace_batch`]).
    pub(crate) fn batch(&self) -> Option<&Whitted<'a>> {
        match self {
            Integrator::Whitted(w) if w.batches() => Some(w),
            _ => None,
        }
    }

    /// One camera ray's value for each channel, into `out`.
    pub(crate) fn sample(&self, ray: &Ray, ctx: &mut Ctx, out: &mut [Color]) {
        self.sample_with(ray, ctx, out, &mut NoRecord);
    }

    /// [`Integrator::sample`], telling `rec` what the ray meets (`rtc why`). The first-hit
    /// images report their camera ray and its hit.
    pub(crate) fn sample_with<R: Recorder>(
        &self,
        ray: &Ray,
        ctx: &mut Ctx,
        out: &mut [Color],
        rec: &mut R,
    ) {
        if super::panorama::is_blind(ray) {
            // A fisheye's pixel outside its circle: black, nothing traced (POV-Ray's rule).
            out.fill(Color::ZERO);
            return;
        }
        out[0] = match self {
            Integrator::Whitted(w) => w.trace_with(ray, Path::CAMERA, ctx, rec),
            Integrator::Path(p) => first_hit(p.scene(), ray, rec, |r| p.trace(r, ctx)),
            Integrator::Normal(n) => first_hit(n.scene(), ray, rec, |r| n.color(r)),
            Integrator::Depth(d) => first_hit(d.scene(), ray, rec, |r| d.color(r)),
            Integrator::Uv(u) => first_hit(u.scene(), ray, rec, |r| u.color(r)),
        };
    }
}

/// A first-hit image's value of `ray`, with the ray and its hit told to `rec`.
fn first_hit<R: Recorder>(
    scene: &Prepared,
    ray: &Ray,
    rec: &mut R,
    color: impl FnOnce(&Ray) -> Color,
) -> Color {
    if R::ON {
        rec.ray(ray, &Path::CAMERA);
        if let Some(hit) = scene.seen_hit(ray, 0.0, f64::INFINITY, Visibility::NO_IMAGE) {
            rec.hit(&hit);
        }
    }
    let c = color(ray);
    if R::ON {
        rec.done(c);
    }
    c
}
