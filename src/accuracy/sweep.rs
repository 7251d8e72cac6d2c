//! The sweep: the scene's own setting, one ladder per used knob, then the joint product; each
//! distinct setting measured once, in that order, until done or cancelled.

use crate::diag::Diagnostic;
use crate::opt::Prepared;
use crate::render::{CANCELLED, Progress};

use super::knob::{Knob, Setting, joint_settings};
use super::measure::{MeasureOptions, Measurement, measure, render_once};
use super::reference::Reference;

/// Which sweep a point belongs to (a setting may belong to several).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Sweep {
    /// The scene's own setting.
    Scene,
    /// One knob's ladder.
    Ladder(Knob),
    /// The joint product.
    Joint,
}

impl Sweep {
    /// The name in tables and JSON: `scene`, the knob's key, `joint`.
    pub(crate) fn key(self) -> &'static str {
        match self {
            Sweep::Scene => "scene",
            Sweep::Ladder(k) => k.key(),
            Sweep::Joint => "joint",
        }
    }
}

/// A planned setting and the sweeps it belongs to.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Planned {
    /// The setting.
    setting: Setting,
    /// Its sweeps, in plan order.
    sweeps: Vec<Sweep>,
}

/// The distinct settings to measure, in order: the scene's own, the ladders of `knobs`, then
/// (with `joint`) the joint product.
pub(crate) fn plan(knobs: &[Knob], own: &Setting, joint: bool) -> Vec<Planned> {
    let mut out: Vec<Planned> = Vec::new();
    let mut add =
        |setting: Setting, sweep: Sweep| match out.iter_mut().find(|p| p.setting == setting) {
            Some(p) if !p.sweeps.contains(&sweep) => p.sweeps.push(sweep),
            Some(_) => {}
            None => out.push(Planned {
                setting,
                sweeps: vec![sweep],
            }),
        };
    add(*own, Sweep::Scene);
    for &k in knobs {
        for s in k.ladder(own) {
            add(s, Sweep::Ladder(k));
        }
    }
    if joint {
        for s in joint_settings(knobs, own) {
            add(s, Sweep::Joint);
        }
    }
    out
}

/// What the sweep reports while it runs, and how it is stopped.
pub trait SweepProgress: Sync {
    /// The sweep will make `renders` renders in all.
    fn begin(&self, _renders: u64) {}
    /// A setting is about to be measured.
    fn point(&self, _label: &str) {}
    /// One render is done.
    fn render_done(&self) {}
    /// Polled before and during each render: `true` stops the sweep, keeping what it measured.
    fn cancelled(&self) -> bool {
        false
    }
    /// The sweep ended (finished or cancelled).
    fn end(&self) {}
}

/// The sweep's progress seen as one render's: only cancellation passes through.
pub(crate) struct CancelOnly<'a>(pub(crate) &'a dyn SweepProgress);

impl Progress for CancelOnly<'_> {
    fn cancelled(&self) -> bool {
        self.0.cancelled()
    }
}

/// The measured points, in plan order, and whether the sweep ran to the end.
#[derive(Clone, Debug)]
pub(crate) struct Measured {
    /// Each measured setting with its sweeps.
    pub(crate) points: Vec<(Vec<Sweep>, Measurement)>,
    /// False when the sweep was cancelled (the points are those finished before).
    pub(crate) complete: bool,
}

/// Renders a setting how many times: `repeat` per seed, two seeds when the scene is random.
pub(crate) fn renders_per_point(random: bool, options: &MeasureOptions) -> u64 {
    u64::from(options.repeat.max(1)) * if random { 2 } else { 1 }
}

/// Measures every planned setting against `reference`, stopping early when `progress` cancels
/// (the caller has announced the renders with [`SweepProgress::begin`]).
/// `own_lights` is each light's own samples per edge.
pub(crate) fn run(
    scene: &mut Prepared,
    own_lights: &[[u32; 2]],
    planned: &[Planned],
    reference: &Reference,
    options: &MeasureOptions,
    progress: &dyn SweepProgress,
) -> Result<Measured, Diagnostic> {
    let reference = reference.view()?;
    let mut points = Vec::new();
    let mut complete = true;
    // One untimed render first, so the first point measured does not pay for cold caches and
    // page faults (the reference is not always rendered before: it may come from the cache).
    if let Some(first) = planned.first() {
        first.setting.apply(scene, own_lights)?;
        match render_once(scene, options.seeds[0], options, &CancelOnly(progress)) {
            Err(d) if d.code == CANCELLED => {
                progress.end();
                return Ok(Measured {
                    points,
                    complete: false,
                });
            }
            other => {
                other?;
            }
        }
    }
    for p in planned {
        if progress.cancelled() {
            complete = false;
            break;
        }
        progress.point(&p.setting.label());
        p.setting.apply(scene, own_lights)?;
        match measure(
            scene,
            p.setting,
            reference,
            options,
            &CancelOnly(progress),
            &|| progress.render_done(),
        ) {
            Ok(m) => points.push((p.sweeps.clone(), m)),
            Err(d) if d.code == CANCELLED => {
                complete = false;
                break;
            }
            Err(d) => return Err(d),
        }
    }
    progress.end();
    Ok(Measured { points, complete })
}
