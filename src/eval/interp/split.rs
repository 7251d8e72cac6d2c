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
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use crate::diag::Diagnostic;

use crate::source::{FileId, SourceMap, Span};
use crate::syntax::ast::{Block, Expr, Generator};

use super::super::error::{EvalError, R};
use super::super::lower::Lowerer;
use super::super::lower::Sink;
use super::super::options::{EVAL_STACK_BYTES, EvalOptions};
use super::super::parts::{Helper, Mark, Part, Role, ScenePart, cut};
use super::Interp;

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
        super::super::replay(
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
    pub(crate) gens: &'e [Generator],
    /// The `if` filter.
    pub(crate) filter: Option<&'e Expr>,
    /// The body.
    pub(crate) body: &'e Block,
    /// The header (iteration frames of errors).
    pub(crate) header: Span,
    /// The whole statement (emission errors).
    pub(crate) span: Span,
}

impl Interp<'_> {
    /// Runs the outer iterations `steps` of `lp`, emitting into `lowerer`.
    fn loop_steps(
        &mut self,
        lp: &Loop,
        it: &super::super::value::Value,
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
        it: &super::super::value::Value,
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
                        .stack_size(EVAL_STACK_BYTES)
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
