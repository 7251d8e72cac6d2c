//! Interned identifiers: a name is a `u32`, so scope lookups compare integers, not strings.

use std::cell::RefCell;
use std::collections::HashMap;
use std::fmt;

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
    /// Interns `name` (each distinct name is stored once per thread, for the life of the thread).
    pub fn new(name: &str) -> Sym {
        INTERNER.with(|i| {
            let mut i = i.borrow_mut();
            if let Some(&s) = i.ids.get(name) {
                return s;
            }
            let leaked: &'static str = Box::leak(name.to_owned().into_boxed_str());
            let s = Sym(i.names.len() as u32);
            i.names.push(leaked);
            i.ids.insert(leaked, s);
            s
        })
    }

    /// The name's text.
    pub fn as_str(self) -> &'static str {
        INTERNER.with(|i| i.borrow().names[self.0 as usize])
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
