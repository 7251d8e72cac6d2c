//! Recording where objects come from (`EvalOptions::provenance`, for `rtc why`): the
//! evaluator enters a step for each `for` iteration and user call, and every object value
//! remembers its origin, the chains active when it was made and placed. Off by default: the
//! evaluator then holds `None` and checks it at each iteration and call, nothing more.

use crate::ir::provenance::{Provenance, Step, StepKind};

/// The steps and origins recorded so far.
pub struct Builder {
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
    pub fn enter(&mut self, kind: StepKind) -> u32 {
        let saved = self.top;
        self.table.steps.push(Step {
            parent: saved,
            kind,
        });
        self.top = (self.table.steps.len() - 1) as u32;
        saved
    }

    /// Leaves the step entered when [`Builder::enter`] returned `saved`.
    pub fn leave(&mut self, saved: u32) {
        self.top = saved;
    }

    /// The origin of an object made now.
    pub fn origin(&mut self) -> u32 {
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
    pub fn derive(&mut self, from: u32) -> u32 {
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
    pub fn finish(mut self, objects: Vec<Vec<u32>>) -> Provenance {
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
