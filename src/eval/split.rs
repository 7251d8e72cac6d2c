//! A long top-level `for` of a scene file evaluated in parts on several threads, merged into
//! exactly what one thread would have made.
//!
//! The evaluator's values are `Rc`s and cannot cross threads, but a scene's evaluation is a pure
//! function of its files and options: no binding is ever rebound, `random` is keyed, and nothing
//! an iteration of a top-level loop makes is visible to another iteration or after the loop (it
//! goes to the scene). So a helper thread replays the scene file from its start up to the loop,
//! evaluates a range of the loop's outer iterations, and hands back what they emitted as IR,
//! which has no `Rc`s. The main thread evaluates its own share meanwhile and then appends the
//! helpers' parts in order, renumbering their materials and textures, merging their warnings
//! with its own (each warning once per place) and adding their loop iterations and values made to
//! its counts.
//!
//! A replay must reach the loop in the state the main thread reached it in ([`Mark`]: values
//! made, iterations, findings, and emitted objects, lights, materials and textures so far). A
//! part that does not, or that stopped at an error, ran into a budget, or emitted a `render`
//! block is not used: the main thread evaluates the rest of the loop itself, and makes the same
//! error at the same iteration one thread would have made. Splitting changes how long an
//! evaluation takes, never what it makes.
//!
//! Whether a loop is split is decided while it runs (`cut`): once its first iterations have
//! taken long enough to say that the rest outlasts a helper's replay of the file up to the loop.

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use crate::diag::Diagnostic;
use crate::ir;
use crate::source::{FileId, SourceMap, Span};
use crate::syntax::ast::{Block, Expr, Generator};

use super::EvalOptions;
use super::blocks::Sink;
use super::error::{EvalError, R};
use super::interp::Interp;
use super::lower::Lowerer;

/// How an evaluation may spread a scene file's long top-level `for` loops over threads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LoopParts {
    /// Split a loop over up to `threads` threads (0: one per core) once its first iterations say
    /// that it pays.
    Auto {
        /// Most threads, the evaluating one included (0: the machine's cores).
        threads: usize,
    },
    /// Evaluate on one thread.
    Serial,
    /// Split every top-level loop of the scene file into this many parts from its first
    /// iteration, however short it is (for tests of the merge).
    Always(usize),
}

impl Default for LoopParts {
    fn default() -> LoopParts {
        LoopParts::Auto { threads: 0 }
    }
}

/// Most threads a loop is split over.
const MOST_PARTS: usize = 8;
/// A loop runs alone at least this long before splitting is considered (timing noise).
const LOOK_AT_LEAST: Duration = Duration::from_millis(4);
/// What a split must save to be worth its threads: their start and the merge's copying.
const WORTH: Duration = Duration::from_millis(8);

/// This thread's part in splitting loops.
pub(crate) enum Role {
    /// The evaluation does not split (provenance, `LoopParts::Serial`, one core).
    Off,
    /// The evaluation of record: it may split the scene file's loops.
    Main(Box<Main>),
    /// A replay that evaluates one part of one loop.
    Helper(Box<Helper>),
}

/// What the main thread knows to have its scene file replayed.
pub(crate) struct Main {
    /// The scene file in the source map (the files before it were there when evaluation began).
    file: FileId,
    /// When evaluation began.
    began: Instant,
    /// What a replay spends on loops this thread split, beyond what this thread spent on them.
    debt: Duration,
}

/// A helper's assignment and what it made.
pub(crate) struct Helper {
    /// The scene file's top-level statement (counted from 0) whose loop is split.
    stmt: usize,
    /// The outer iterations this helper evaluates.
    steps: Range<u64>,
    /// Every file the main thread had read when it split: imports are replayed from these texts,
    /// not read again (a file edited meanwhile would make another scene).
    texts: SourceMap,
    /// Set when the main thread no longer needs the part (it stopped at an error).
    cancel: Arc<AtomicBool>,
    /// Indices in the findings of the warnings `Interp::warn` recorded (once per place).
    warnings: Vec<usize>,
    /// The part, once evaluated.
    part: Option<Part>,
}

impl Role {
    /// The role of a new evaluation of the scene file `file` at `path`.
    pub(crate) fn main(options: &EvalOptions, file: FileId) -> Role {
        let threads = match options.loop_parts {
            LoopParts::Serial => 1,
            LoopParts::Always(n) => n,
            LoopParts::Auto { threads } => parts_for(threads),
        };
        if threads < 2 || options.provenance {
            return Role::Off;
        }
        Role::Main(Box::new(Main {
            file,
            began: Instant::now(),
            debt: Duration::ZERO,
        }))
    }

    /// Records that finding `index` came through `Interp::warn` (a helper's warnings are
    /// deduplicated against the main thread's when merged).
    pub(super) fn note_warning(&mut self, index: usize) {
        if let Role::Helper(h) = self {
            h.warnings.push(index);
        }
    }

    /// For a helper, the text of `path` as the main thread read it.
    pub(super) fn replayed_text(&self, path: &Path) -> Option<String> {
        let Role::Helper(h) = self else { return None };
        let id = h.texts.find(path)?;
        Some(h.texts.get(id).text.as_str().to_owned())
    }

    /// For a helper, the statement whose loop it evaluates a part of.
    pub(super) fn helper_stmt(&self) -> Option<usize> {
        match self {
            Role::Helper(h) => Some(h.stmt),
            _ => None,
        }
    }

    /// Whether this is a helper that has evaluated its part (its replay stops there).
    pub(super) fn done(&self) -> bool {
        matches!(self, Role::Helper(h) if h.part.is_some())
    }

    /// A helper's part, once evaluated.
    pub(crate) fn take_part(&mut self) -> Option<Part> {
        match self {
            Role::Helper(h) => h.part.take(),
            _ => None,
        }
    }
}

/// Threads for `LoopParts::Auto { threads }`.
fn parts_for(threads: usize) -> usize {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let n = if threads == 0 { cores } else { threads };
    n.min(MOST_PARTS)
}

/// The evaluation's state where a loop begins: a replay that reaches the loop in another state
/// is not the same evaluation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Mark {
    made: u64,
    loop_iters: u64,
    memory: u64,
    diags: usize,
    objects: usize,
    lights: usize,
    cameras: usize,
    renders: usize,
    materials: usize,
    textures: usize,
}

impl Mark {
    fn of(it: &Interp, l: &Lowerer) -> Mark {
        Mark {
            made: it.made,
            loop_iters: it.loop_iters,
            memory: it.memory.get(),
            diags: it.diags.len(),
            objects: l.objects.len(),
            lights: l.lights.len(),
            cameras: l.cameras.len(),
            renders: l.renders.len(),
            materials: l.materials.len(),
            textures: l.textures.len(),
        }
    }
}

/// What a helper's iterations made, as IR.
pub(crate) struct Part {
    /// The state the replay reached the loop in.
    start: Mark,
    /// What was emitted (material and texture ids in the helper's numbering).
    scene: ScenePart,
    /// Findings, each with whether it came through `Interp::warn`.
    diags: Vec<(Diagnostic, bool)>,
    /// Loop iterations run.
    iterations: u64,
    /// Bytes charged to the memory budget.
    memory: u64,
    /// Material and texture values made.
    made: u64,
    /// The part stopped at an error or emitted a `render` block: not to be used.
    unusable: bool,
}

/// The scene side of a [`Part`].
pub(crate) struct ScenePart {
    /// Objects emitted.
    pub(super) objects: Vec<ir::Object>,
    /// Lights emitted.
    pub(super) lights: Vec<ir::Light>,
    /// Cameras emitted.
    pub(super) cameras: Vec<ir::Camera>,
    /// New materials, each with its value's number (`Mat::made`).
    pub(super) materials: Vec<(u64, ir::Material)>,
    /// New textures, each with its value's number (`Tex::made`).
    pub(super) textures: Vec<(u64, ir::Texture)>,
}

/// How to cut the outer iterations `done..n` a loop has left after running `done` of them in
/// `spent`: this thread's share first, then each helper's. `None`: go on alone for now.
/// `replay` is what a helper spends to reach the loop.
fn cut(
    parts: LoopParts,
    n: u64,
    done: u64,
    spent: Duration,
    replay: Duration,
) -> Option<Vec<Range<u64>>> {
    let left = n - done;
    let (k, helper_share) = match parts {
        LoopParts::Serial => return None,
        LoopParts::Always(k) => {
            let k = (k.min(MOST_PARTS) as u64).min(left);
            (k, left / k.max(1))
        }
        LoopParts::Auto { threads } => {
            if done == 0 || spent < LOOK_AT_LEAST {
                return None;
            }
            let k = (parts_for(threads) as u64).min(left);
            let per = spent.as_secs_f64() / done as f64;
            let rest = per * left as f64;
            let replay = replay.as_secs_f64();
            // This thread takes `replay` more than each helper, so all end together.
            let share = ((rest - replay) / k as f64 / per).floor();
            let saved = rest - (share * per + replay);
            if k < 2 || share < 1.0 || saved < WORTH.as_secs_f64() {
                return None;
            }
            (k, share as u64)
        }
    };
    if k < 2 || helper_share == 0 {
        return None;
    }
    let own = left - helper_share * (k - 1);
    let helpers = (0..k - 1).map(|h| {
        let from = done + own + h * helper_share;
        from..from + helper_share
    });
    Some(std::iter::once(done..done + own).chain(helpers).collect())
}

/// What a helper thread needs.
struct Job {
    path: PathBuf,
    text: Arc<String>,
    before: SourceMap,
    texts: SourceMap,
    stmt: usize,
    steps: Range<u64>,
    cancel: Arc<AtomicBool>,
}

impl Job {
    /// Replays the scene file up to the loop and evaluates the part.
    fn run(self, options: &EvalOptions) -> Option<Part> {
        let mut sources = self.before;
        let helper = Helper {
            stmt: self.stmt,
            steps: self.steps,
            texts: self.texts,
            cancel: self.cancel,
            warnings: Vec::new(),
            part: None,
        };
        super::replay(
            &self.path,
            self.text.as_str().to_owned(),
            &mut sources,
            options,
            helper,
        )
    }
}

/// A loop's syntax, as `emit_for` found it.
pub(super) struct Loop<'e> {
    /// The generators, outermost first.
    pub gens: &'e [Generator],
    /// The `if` filter.
    pub filter: Option<&'e Expr>,
    /// The body.
    pub body: &'e Block,
    /// The header (iteration frames of errors).
    pub header: Span,
    /// The whole statement (emission errors).
    pub span: Span,
}

impl Interp<'_> {
    /// Runs the outer iterations `steps` of `lp`, emitting into `lowerer`.
    fn loop_steps(
        &mut self,
        lp: &Loop,
        it: &super::value::Value,
        steps: Range<u64>,
        lowerer: &mut Lowerer,
    ) -> R<()> {
        let mut sink = Sink::Emit(lowerer, lp.span);
        self.for_steps(
            lp.gens, 0, it, steps, lp.filter, lp.body, lp.header, &mut sink,
        )
    }

    /// Evaluates the scene file's top-level loop `lp` (statement `stmt`) on the main thread,
    /// splitting it over helpers once that pays.
    pub(super) fn emit_split_for(
        &mut self,
        lp: &Loop,
        stmt: usize,
        lowerer: &mut Lowerer,
    ) -> R<()> {
        let start = Mark::of(self, lowerer);
        let g = &lp.gens[0];
        let it = self.eval(&g.iter)?;
        let n = self.loop_len(&it, g)?;
        let Role::Main(main) = &self.split else {
            return self.loop_steps(lp, &it, 0..n, lowerer);
        };
        let (file, replay) = (main.file, main.began.elapsed() + main.debt);
        let began = Instant::now();
        let mut done = 0;
        let cuts = loop {
            if let Some(cuts) = cut(self.opts.loop_parts, n, done, began.elapsed(), replay) {
                break cuts;
            }
            if done == n {
                return Ok(());
            }
            self.loop_steps(lp, &it, done..done + 1, lowerer)?;
            done += 1;
        };
        let alone = began.elapsed();

        let helped: u64 = cuts[1..].iter().map(|c| c.end - c.start).sum();
        self.split_loop(lp, stmt, file, &it, &start, &cuts, lowerer)?;
        // A later loop's helpers replay this one on one thread.
        if let Role::Main(main) = &mut self.split {
            let per = alone.as_secs_f64() / done.max(1) as f64;
            main.debt += Duration::from_secs_f64(per * helped as f64);
        }
        Ok(())
    }

    /// Runs `cuts[0]` here and the other cuts on helper threads, then takes the helpers'
    /// parts in order; from the first part that cannot be used on, this thread evaluates the
    /// rest of the loop itself.
    #[allow(clippy::too_many_arguments)]
    fn split_loop(
        &mut self,
        lp: &Loop,
        stmt: usize,
        file: FileId,
        it: &super::value::Value,
        start: &Mark,
        cuts: &[Range<u64>],
        lowerer: &mut Lowerer,
    ) -> R<()> {
        let path = self.sources.get(file).path.clone();
        let text = self.sources.get(file).text.clone();
        let before = self.sources.prefix(file.0 as usize);
        let texts = self.sources.clone();
        let cancel = Arc::new(AtomicBool::new(false));
        let options = self.opts;
        let end = cuts.last().map_or(0, |c| c.end);
        std::thread::scope(|s| {
            let helpers: Vec<_> = cuts[1..]
                .iter()
                .map(|steps| {
                    let job = Job {
                        path: path.clone(),
                        text: text.clone(),
                        before: before.clone(),
                        texts: texts.clone(),
                        stmt,
                        steps: steps.clone(),
                        cancel: cancel.clone(),
                    };
                    std::thread::Builder::new()
                        .name("rtc-eval-part".into())
                        .stack_size(super::EVAL_STACK_BYTES)
                        .spawn_scoped(s, move || job.run(options))
                        .ok()
                })
                .collect();
            if let Err(e) = self.loop_steps(lp, it, cuts[0].clone(), lowerer) {
                cancel.store(true, Ordering::Relaxed);
                return Err(e);
            }
            let mut redo = None;
            for (helper, steps) in helpers.into_iter().zip(&cuts[1..]) {
                let part = helper.and_then(|h| h.join().ok()).flatten();

                if redo.is_some() {
                    continue;
                }
                match part {
                    Some(p) if self.fits(&p, start, lowerer) => self.absorb(p, start, lowerer),
                    _ => redo = Some(steps.start),
                }
            }

            match redo {
                Some(from) => self.loop_steps(lp, it, from..end, lowerer),
                None => Ok(()),
            }
        })
    }

    /// Whether a helper's part is what this thread would have made next.
    fn fits(&self, p: &Part, start: &Mark, lowerer: &Lowerer) -> bool {
        !p.unusable
            && p.start == *start
            && self.loop_iters + p.iterations <= self.opts.max_loop_iterations
            && (lowerer.objects.len() + p.scene.objects.len()) as u64 <= self.opts.max_objects
            && self.memory_fits(p, lowerer)
    }

    /// Whether a helper's values and objects fit the memory budget after this thread's.
    fn memory_fits(&self, p: &Part, lowerer: &Lowerer) -> bool {
        let mut budget = self.object_budget();
        let objects = lowerer.objects.len() + p.scene.objects.len();
        budget.memory.charge(p.memory).is_ok()
            && budget.check_memory(objects, Span::default()).is_ok()
    }

    /// Appends a helper's part as if this thread had evaluated it.
    fn absorb(&mut self, p: Part, start: &Mark, lowerer: &mut Lowerer) {
        for (d, through_warn) in p.diags {
            let again = through_warn && d.span.is_some_and(|s| !self.warned.insert((d.code, s)));
            if !again {
                self.diags.push(d);
            }
        }
        self.loop_iters += p.iterations;
        self.memory.set(self.memory.get() + p.memory);
        self.made += p.made;
        lowerer.absorb(p.scene, start.made, start.materials, start.textures);
    }

    /// On a helper: evaluates its part of the loop `lp` and keeps it for the main thread.
    pub(super) fn emit_part(&mut self, lp: &Loop, lowerer: &mut Lowerer) {
        let start = Mark::of(self, lowerer);
        let Role::Helper(h) = &self.split else { return };
        let (steps, cancel) = (h.steps.clone(), h.cancel.clone());
        let r = self.eval_part(lp, steps, &cancel, lowerer);
        let unusable = r.is_err()
            || lowerer.renders.len() > start.renders
            || self.diags[start.diags..].iter().any(Diagnostic::is_error);
        let Role::Helper(h) = &mut self.split else {
            return;
        };
        let diags = self
            .diags
            .drain(start.diags..)
            .enumerate()
            .map(|(i, d)| (d, h.warnings.binary_search(&(start.diags + i)).is_ok()))
            .collect();
        let scene = ScenePart {
            objects: lowerer.objects.split_off(start.objects),
            lights: lowerer.lights.split_off(start.lights),
            cameras: lowerer
                .cameras
                .drain(start.cameras..)
                .map(|c| (*c).clone())
                .collect(),
            materials: lowerer.material_keys[start.materials..]
                .iter()
                .copied()
                .zip(lowerer.materials.drain(start.materials..))
                .collect(),
            textures: lowerer.texture_keys[start.textures..]
                .iter()
                .copied()
                .zip(lowerer.textures.drain(start.textures..))
                .collect(),
        };
        h.part = Some(Part {
            start,
            scene,
            diags,
            iterations: self.loop_iters - start.loop_iters,
            memory: self.memory.get() - start.memory,
            made: self.made - start.made,
            unusable,
        });
    }

    fn eval_part(
        &mut self,
        lp: &Loop,
        steps: Range<u64>,
        cancel: &AtomicBool,
        lowerer: &mut Lowerer,
    ) -> R<()> {
        let g = &lp.gens[0];
        // The main thread evaluated the loop's iterable once and counted its steps and bytes;
        // this replay of it must not count them again in the part.
        let counted = (self.loop_iters, self.memory.get());
        let it = self.eval(&g.iter)?;
        (self.loop_iters, _) = counted;
        self.memory.set(counted.1);
        if steps.end > self.loop_len(&it, g)? {
            return Err(EvalError::Poisoned);
        }
        for i in steps {
            if cancel.load(Ordering::Relaxed) {
                return Err(EvalError::Poisoned);
            }
            self.loop_steps(lp, &it, i..i + 1, lowerer)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ms(n: u64) -> Duration {
        Duration::from_millis(n)
    }

    #[test]
    fn forced_cuts_cover_the_loop_in_order() {
        let cuts = cut(LoopParts::Always(3), 10, 0, ms(0), ms(0)).unwrap();
        assert_eq!(cuts, vec![0..4, 4..7, 7..10]);
        // Never more parts than iterations, and one iteration is not split.
        assert_eq!(
            cut(LoopParts::Always(8), 3, 0, ms(0), ms(0)).unwrap(),
            vec![0..1, 1..2, 2..3]
        );
        assert!(cut(LoopParts::Always(4), 1, 0, ms(0), ms(0)).is_none());
        assert!(cut(LoopParts::Serial, 100, 0, ms(0), ms(0)).is_none());
    }

    #[test]
    fn a_loop_is_split_only_when_the_rest_outlasts_a_replay() {
        let auto = LoopParts::Auto { threads: 2 };
        // 10 of 1000 iterations in 10 ms: ~990 ms left, a 5 ms replay: split, and the helper's
        // share is smaller by the replay.
        let cuts = cut(auto, 1000, 10, ms(10), ms(5)).unwrap();
        assert_eq!(cuts.len(), 2);
        assert_eq!(cuts[0].start, 10);
        assert_eq!(cuts[1].end, 1000);
        assert_eq!(cuts[0].end, cuts[1].start);
        let (own, helper) = (cuts[0].end - 10, cuts[1].end - cuts[1].start);
        assert!(own > helper && own - helper <= 6, "{own} {helper}");
        // Too early to tell, too little left, or a replay as long as the rest: alone.
        assert!(cut(auto, 1000, 1, ms(1), ms(5)).is_none());
        assert!(cut(auto, 1000, 995, ms(100), ms(5)).is_none());
        assert!(cut(auto, 1000, 10, ms(10), ms(2000)).is_none());
        assert!(cut(LoopParts::Auto { threads: 1 }, 1000, 10, ms(10), ms(0)).is_none());
    }
}
