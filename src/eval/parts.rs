//! The state of splitting a scene file's long top-level loops over threads (`split.rs` runs
//! it): this thread's role, the state a loop begins in ([`Mark`]) and what a helper made
//! ([`Part`]). Data only: it knows nothing of the interpreter.

use std::ops::Range;
use std::path::Path;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use crate::diag::Diagnostic;
use crate::ir;
use crate::source::{FileId, SourceMap};

use super::options::{EvalOptions, LoopParts};

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
    pub(super) file: FileId,
    /// When evaluation began.
    pub(super) began: Instant,
    /// What a replay spends on loops this thread split, beyond what this thread spent on them.
    pub(super) debt: Duration,
}

/// A helper's assignment and what it made.
pub(crate) struct Helper {
    /// The scene file's top-level statement (counted from 0) whose loop is split.
    pub(super) stmt: usize,
    /// The outer iterations this helper evaluates.
    pub(super) steps: Range<u64>,
    /// Every file the main thread had read when it split: imports are replayed from these texts,
    /// not read again (a file edited meanwhile would make another scene).
    pub(super) texts: SourceMap,
    /// Set when the main thread no longer needs the part (it stopped at an error).
    pub(super) cancel: Arc<AtomicBool>,
    /// Indices in the findings of the warnings `Interp::warn` recorded (once per place).
    pub(super) warnings: Vec<usize>,
    /// The part, once evaluated.
    pub(super) part: Option<Part>,
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
    pub(super) made: u64,
    pub(super) loop_iters: u64,
    pub(super) memory: u64,
    pub(super) diags: usize,
    pub(super) objects: usize,
    pub(super) lights: usize,
    pub(super) cameras: usize,
    pub(super) renders: usize,
    pub(super) materials: usize,
    pub(super) textures: usize,
}

/// What a helper's iterations made, as IR.
pub(crate) struct Part {
    /// The state the replay reached the loop in.
    pub(super) start: Mark,
    /// What was emitted (material and texture ids in the helper's numbering).
    pub(super) scene: ScenePart,
    /// Findings, each with whether it came through `Interp::warn`.
    pub(super) diags: Vec<(Diagnostic, bool)>,
    /// Loop iterations run.
    pub(super) iterations: u64,
    /// Bytes charged to the memory budget.
    pub(super) memory: u64,
    /// Material and texture values made.
    pub(super) made: u64,
    /// The part stopped at an error or emitted a `render` block: not to be used.
    pub(super) unusable: bool,
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
pub(super) fn cut(
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
