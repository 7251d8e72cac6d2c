//! Recording where objects come from (`EvalOptions::provenance`, for `rtc why`): the
//! evaluator enters a step for each `for` iteration and user call, and every object value
//! remembers its origin, the chains active when it was made and placed. Off by default: the
//! evaluator then holds `None` and checks it at each iteration and call, nothing more.

use crate::ir::provenance::{Provenance, Step, StepKind};

/// The steps and origins recorded so far.
pub(crate) struct Builder {
    /// The steps (index 0 unused: the top level).
    table: Provenance,
    /// The innermost active step.
    top: u32,
    /// Per origin, the innermost step of each chain (origin 0: the top level, no chain).
    origins: Vec<Vec<u32>>,
}

impl Default for Builder {
    fn default() -> Builder {
        Builder {
            table: Provenance {
                steps: vec![Step {
                    parent: Provenance::ROOT,
                    kind: StepKind::Call {
                        name: String::new(),
                        at: crate::source::Span::default(),
                    },
                }],
                objects: Vec::new(),
            },
            top: Provenance::ROOT,
            origins: vec![Vec::new()],
        }
    }
}

impl Builder {
    /// Enters a step inside the current one; returns what [`Builder::leave`] restores.
    pub(crate) fn enter(&mut self, kind: StepKind) -> u32 {
        let saved = self.top;
        self.table.steps.push(Step {
            parent: saved,
            kind,
        });
        self.top = (self.table.steps.len() - 1) as u32;
        saved
    }

    /// Leaves the step entered when [`Builder::enter`] returned `saved`.
    pub(crate) fn leave(&mut self, saved: u32) {
        self.top = saved;
    }

    /// The origin of an object made now.
    pub(crate) fn origin(&mut self) -> u32 {
        if self.top == Provenance::ROOT {
            return 0;
        }
        // Objects made in one step (a loop body making several) share their origin.
        if self.origins.last().is_some_and(|o| o[..] == [self.top]) {
            return (self.origins.len() - 1) as u32;
        }
        self.origins.push(vec![self.top]);
        (self.origins.len() - 1) as u32
    }

    /// The origin of an object derived now (moved, given a material) from one of origin
    /// `from`: unchanged when the current step is already on one of its chains, else with the
    /// current chain added (made in one place, placed in another).
    pub(crate) fn derive(&mut self, from: u32) -> u32 {
        let tops = self.origins.get(from as usize).cloned().unwrap_or_default();
        if self.top == Provenance::ROOT || tops.iter().any(|&t| self.table.encloses(self.top, t)) {
            return from;
        }
        let mut more = tops;
        more.push(self.top);
        self.origins.push(more);
        (self.origins.len() - 1) as u32
    }

    /// The side table for the scene's objects, given each object's origins (its own first,
    /// then those of the groups that placed it, innermost group first).
    pub(crate) fn finish(mut self, objects: Vec<Vec<u32>>) -> Provenance {
        self.table.objects = objects
            .into_iter()
            .map(|origins| {
                let mut tops: Vec<u32> = Vec::new();
                for o in origins {
                    for &t in self.origins.get(o as usize).map_or(&[][..], |v| &v[..]) {
                        // A chain already inside a kept one adds nothing.
                        if !tops.iter().any(|&k| self.table.encloses(t, k)) {
                            tops.push(t);
                        }
                    }
                }
                tops
            })
            .collect();
        self.table
    }
}

#[cfg(test)]
mod tests {
    use std::rc::Rc;

    use glam::DAffine3;

    use super::*;
    use crate::eval::value::{Mat, Obj, ObjShape};
    use crate::source::Span;

    /// An object value as it was before it had an origin and visibility flags.
    #[allow(dead_code)]
    struct Bare {
        shape: ObjShape,
        transform: DAffine3,
        material: Option<Rc<Mat>>,
        motion: Option<crate::ir::Motion>,
        span: Span,
    }

    #[test]
    fn the_origin_and_the_flags_take_one_word_of_the_object_value() {
        // The origin alone fitted in the padding; with the one-byte visibility flags beside it
        // the value grew by one word (8 of 424 bytes), not more.
        assert_eq!(std::mem::size_of::<Obj>(), std::mem::size_of::<Bare>() + 8);
    }

    fn call(name: &str) -> StepKind {
        StepKind::Call {
            name: name.to_string(),
            at: Span::default(),
        }
    }

    #[test]
    fn origins_follow_the_steps() {
        let mut b = Builder::default();
        assert_eq!(b.origin(), 0, "the top level has no chain");
        let outer = b.enter(call("f"));
        let made = b.origin();
        assert_eq!(b.origin(), made, "objects made in one step share an origin");
        // Moved inside the same call: nothing new.
        assert_eq!(b.derive(made), made);
        b.leave(outer);
        // Moved at the top level: still only where it was made.
        assert_eq!(b.derive(made), made);
        let lp = b.enter(call("g"));
        let placed = b.derive(made);
        assert_ne!(placed, made, "made in `f`, placed in `g`");
        b.leave(lp);
        let p = b.finish(vec![vec![placed], vec![made, placed]]);
        let names = |o: usize| -> Vec<String> {
            p.trace(o)
                .iter()
                .map(|c| match &c[0].kind {
                    StepKind::Call { name, .. } => name.clone(),
                    StepKind::Iteration { bindings, .. } => bindings.clone(),
                })
                .collect()
        };
        assert_eq!(names(0), ["f", "g"]);
        assert_eq!(names(1), ["f", "g"], "a chain is kept once");
    }
}
