//! Visiting a parsed file's statements: the ones the fast path read are built from its tape at
//! each visit, which keeps a generated file's AST out of memory; see [`File`].

use std::borrow::Cow;
use std::fmt;

use crate::syntax::ast::{File, Item, Stmt};
use crate::syntax::fast;

impl<'t> File<'t> {
    /// The statements in file order. A fast-path statement is built afresh (and owned) from
    /// its tape at each visit.
    pub(crate) fn stmts(&self) -> Stmts<'_, 't> {
        Stmts {
            file: self,
            next: 0,
            memo: fast::Memo::default(),
            reused: None,
        }
    }

    /// The statements pest read, in file order: every `fn` item is one of them (the fast path
    /// reads only `let` and expression lines), so hoisting needs no rebuilding.
    pub(crate) fn built_stmts(&self) -> &[Stmt] {
        &self.built
    }

    /// How many statements the file has (the tests').
    #[cfg(test)]
    pub(crate) fn len(&self) -> usize {
        self.items.len()
    }

    /// Every statement, built.
    pub(crate) fn into_stmts(self) -> Vec<Stmt> {
        self.stmts().map(Cow::into_owned).collect()
    }
}

/// The iterator of [`File::stmts`].
pub(crate) struct Stmts<'f, 't> {
    file: &'f File<'t>,
    next: usize,
    memo: fast::Memo<'t>,
    /// The last fast statement [`Stmts::next_ref`] built, whose nodes the next one reuses.
    reused: Option<Stmt>,
}

impl<'f> Stmts<'f, '_> {
    /// The next statement, borrowed: a fast-path statement is built into the nodes of the
    /// previous one when the two have the same shape, so visiting a generated file's lines
    /// allocates nothing (`next` builds each afresh).
    pub(crate) fn next_ref(&mut self) -> Option<&Stmt> {
        let item = *self.file.items.get(self.next)?;
        self.next += 1;
        Some(match item {
            Item::Built(i) => &self.file.built[i as usize],
            Item::Line { tape, at } => {
                let f = self.file;
                let t = (tape, &f.tapes[tape as usize]);
                match &mut self.reused {
                    Some(stmt) => {
                        fast::statement_into(stmt, f.file, f.text, t, at, &mut self.memo);
                        stmt
                    }
                    empty => empty.insert(fast::statement(f.file, f.text, t, at, &mut self.memo)),
                }
            }
        })
    }
}

impl<'f> Iterator for Stmts<'f, '_> {
    type Item = Cow<'f, Stmt>;

    fn next(&mut self) -> Option<Cow<'f, Stmt>> {
        let item = *self.file.items.get(self.next)?;
        self.next += 1;
        Some(match item {
            Item::Built(i) => Cow::Borrowed(&self.file.built[i as usize]),
            Item::Line { tape, at } => {
                let f = self.file;
                let t = (tape, &f.tapes[tape as usize]);
                Cow::Owned(fast::statement(f.file, f.text, t, at, &mut self.memo))
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
