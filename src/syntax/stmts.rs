//! Visiting a parsed file's statements: the ones the fast path read are read again from their
//! line at each visit (about 1 500 instructions for a sphere line), which keeps a generated
//! file's AST out of memory; see [`File`].

use std::borrow::Cow;
use std::fmt;

use crate::syntax::ast::{File, Item, Stmt};
use crate::syntax::fast;

impl<'t> File<'t> {
    /// The statements in file order. A fast-path statement is built afresh (and owned) at each
    /// visit; it equals the one the first reading built, since the same reader reads the same
    /// text.
    pub fn stmts(&self) -> Stmts<'_, 't> {
        Stmts {
            file: self,
            next: 0,
            memo: fast::Memo::default(),
        }
    }

    /// The statements pest read, in file order: every `fn` item is one of them (the fast path
    /// reads only `let` and expression lines), so hoisting needs no rebuilding.
    pub fn built_stmts(&self) -> &[Stmt] {
        &self.built
    }

    /// How many statements the file has.
    pub fn len(&self) -> usize {
        self.items.len()
    }

    /// True when the file has no statement.
    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// Every statement, built.
    pub fn into_stmts(self) -> Vec<Stmt> {
        self.stmts().map(Cow::into_owned).collect()
    }
}

/// The iterator of [`File::stmts`].
pub struct Stmts<'f, 't> {
    file: &'f File<'t>,
    next: usize,
    memo: fast::Memo<'t>,
}

impl<'f> Iterator for Stmts<'f, '_> {
    type Item = Cow<'f, Stmt>;

    fn next(&mut self) -> Option<Cow<'f, Stmt>> {
        let item = *self.file.items.get(self.next)?;
        self.next += 1;
        Some(match item {
            Item::Built(i) => Cow::Borrowed(&self.file.built[i as usize]),
            Item::Line(at) => {
                let f = self.file;
                // A file is only returned when it parsed without errors, so its input ended at
                // the end of the text, as it does here.
                let (stmt, _) =
                    fast::statement(f.file, f.text, at as usize, f.text.len(), &mut self.memo)
                        .expect("the fast path reads again a line it read before");
                Cow::Owned(stmt)
            }
        })
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = self.file.items.len() - self.next;
        (n, Some(n))
    }
}

impl fmt::Debug for File<'_> {
    /// Prints every statement built, so a file read by the fast path and one read by pest
    /// alone print the same (fast_tests.rs compares them so).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("File")
            .field("version", &self.version)
            .field("stmts", &self.stmts().collect::<Vec<_>>())
            .finish()
    }
}
