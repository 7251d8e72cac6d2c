//! Interned identifiers: a name is a `u32`, so scope lookups compare integers, not strings.

use std::cell::RefCell;
use std::collections::{HashMap, HashSet};
use std::fmt;
use std::sync::{Mutex, OnceLock};

/// An interned identifier.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Sym(u32);

#[derive(Default)]
struct Interner {
    ids: HashMap<&'static str, Sym>,
    names: Vec<&'static str>,
}

thread_local! {
    static INTERNER: RefCell<Interner> = RefCell::new(Interner::default());
}

impl Sym {
    /// Interns `name` (numbered per thread; its text is stored once per process).
    pub(crate) fn new(name: &str) -> Sym {
        INTERNER.with(|i| {
            let mut i = i.borrow_mut();
            if let Some(&s) = i.ids.get(name) {
                return s;
            }
            let leaked = text_for(name);
            let s = Sym(i.names.len() as u32);
            i.names.push(leaked);
            i.ids.insert(leaked, s);
            s
        })
    }

    /// The name's text.
    pub(crate) fn as_str(self) -> &'static str {
        INTERNER.with(|i| i.borrow().names[self.0 as usize])
    }
}

/// The one `'static` copy of `name` in the process. Every evaluation runs on a thread of its own
/// with a fresh interner, so leaking a copy per thread would grow without end in a process that
/// evaluates many scenes; each distinct name is leaked once instead.
fn text_for(name: &str) -> &'static str {
    static TEXTS: OnceLock<Mutex<HashSet<&'static str>>> = OnceLock::new();
    let mut texts = TEXTS
        .get_or_init(Default::default)
        .lock()
        .unwrap_or_else(|e| e.into_inner());
    match texts.get(name) {
        Some(t) => t,
        None => {
            let t: &'static str = Box::leak(name.to_owned().into_boxed_str());
            texts.insert(t);
            t
        }
    }
}

impl fmt::Debug for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`{}`", self.as_str())
    }
}

impl fmt::Display for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}
