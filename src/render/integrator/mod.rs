//! Integrators: what a camera ray contributes to each film channel, one type per render mode
//! with its own state. Adding a mode is a variant of `ir::RenderMode`, a file here and a line
//! in [`Integrator::new`], [`Integrator::channels`] and [`Integrator::sample`].

pub mod depth;
pub mod gloss;
pub mod normal;
pub mod whitted;

use crate::diag::Diagnostic;
use crate::geometry::Ray;
use crate::ir::{Color, RenderMode};
use crate::opt::Prepared;

use super::View;
use super::film::Channel;
use super::sampler::Grid;
use super::shading::Ctx;
use depth::DepthImage;
use normal::NormalImage;
use whitted::{Path, Whitted};

/// The integrator of a render (a closed set, dispatched by `match`).
pub enum Integrator<'a> {
    /// Shaded colour: Whitted recursion with a shading model.
    Whitted(Whitted<'a>),
    /// The first hit's normal as a colour.
    Normal(NormalImage<'a>),
    /// The first hit's distance as grey.
    Depth(DepthImage<'a>),
}

impl<'a> Integrator<'a> {
    /// The integrator for `scene`'s mode. Image-wide passes run here, before any pixel (the
    /// depth range of an automatic depth image, over the camera samples of `first`).
    pub fn new(
        scene: &'a Prepared,
        view: &View<'_>,
        first: Grid,
        pool: &rayon::ThreadPool,
    ) -> Result<Integrator<'a>, Diagnostic> {
        Ok(match scene.settings().mode {
            RenderMode::Shaded => Integrator::Whitted(Whitted::new(scene)),
            RenderMode::Normal => Integrator::Normal(NormalImage::new(scene)),
            RenderMode::Depth(range) => {
                Integrator::Depth(DepthImage::new(scene, range, view, first, pool)?)
            }
        })
    }

    /// The film channels it fills, in the order of [`Integrator::sample`]'s output.
    pub fn channels(&self) -> &'static [Channel] {
        match self {
            Integrator::Whitted(_) | Integrator::Normal(_) | Integrator::Depth(_) => {
                &[Channel::Color]
            }
        }
    }

    /// One camera ray's value for each channel, into `out`.
    pub fn sample(&self, ray: &Ray, ctx: &mut Ctx, out: &mut [Color]) {
        out[0] = match self {
            Integrator::Whitted(w) => w.trace(ray, Path::CAMERA, ctx),
            Integrator::Normal(n) => n.color(ray),
            Integrator::Depth(d) => d.color(ray),
        };
    }
}
