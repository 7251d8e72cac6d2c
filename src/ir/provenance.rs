//! Where each object of an evaluated scene came from: the loop iterations and function calls
//! active when it was made (`rtc why`). A side table next to `Scene::objects`, filled only when
//! evaluation is asked for it (`EvalOptions::provenance`), so ordinary scenes carry nothing.
//!
//! Steps form a tree (each points at the step it ran inside), so a million objects made in one
//! loop share their outer steps; an object keeps the innermost step of each chain it has.

use crate::source::Span;

/// What a step of evaluation was.
#[derive(Clone, Debug, PartialEq)]
pub enum StepKind {
    /// One iteration of a `for`.
    Iteration {
        /// The loop's header (`for i in 0..5`).
        at: Span,
        /// Its variables' values in this iteration, e.g. `i = 3`.
        bindings: String,
    },
    /// A call of a user function.
    Call {
        /// The function's name (`<fn>` for a literal).
        name: String,
        /// The call.
        at: Span,
    },
}

/// One step: what it was and the step it ran inside.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// The enclosing step; [`Provenance::ROOT`] at the top level of the file.
    pub(crate) parent: u32,
    /// What it was.
    pub kind: StepKind,
}

/// The provenance side table of a scene: indexed like `Scene::objects`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Provenance {
    /// Every step recorded; index [`Provenance::ROOT`] is never a real step.
    pub(crate) steps: Vec<Step>,
    /// Per scene object, the innermost step of each chain it came from: first where it was made
    /// (the shape's call, or the last transform applied in another context), then the chains
    /// of the groups that placed it, outermost last. Empty: made at the top level.
    pub objects: Vec<Vec<u32>>,
}

impl Provenance {
    /// The step index meaning "no step": the file's top level.
    pub(crate) const ROOT: u32 = 0;

    /// The chain of steps from `step` outwards (innermost first).
    fn chain(&self, step: u32) -> Vec<&Step> {
        let mut out = Vec::new();
        let mut at = step;
        while at != Self::ROOT {
            let Some(s) = self.steps.get(at as usize) else {
                break;
            };
            out.push(s);
            at = s.parent;
        }
        out
    }

    /// Whether step `outer` is `step` or encloses it.
    pub(crate) fn encloses(&self, outer: u32, step: u32) -> bool {
        let mut at = step;
        loop {
            if at == outer {
                return true;
            }
            match self.steps.get(at as usize) {
                Some(s) if at != Self::ROOT => at = s.parent,
                _ => return false,
            }
        }
    }

    /// The chains object `object` came from (each innermost first); empty for an object made
    /// at the top level or unknown to the table.
    pub fn trace(&self, object: usize) -> Vec<Vec<&Step>> {
        self.objects
            .get(object)
            .map(|tops| tops.iter().map(|&t| self.chain(t)).collect())
            .unwrap_or_default()
    }
}
