//! Builds the AST from pest's parse tree, reporting the slips the grammar accepts on purpose
//! (`=` instead of `:` in records and named arguments).

use std::cell::RefCell;
use std::rc::Rc;

use pest::iterators::Pair;

use crate::diag::Diagnostic;
use crate::source::{FileId, Span};
use crate::syntax::ast::*;
use crate::syntax::grammar::Rule;
use crate::syntax::intern::Sym;

mod expr;

pub(crate) use expr::MAX_CHAIN;

/// Converts sRGB-encoded [0, 1] to linear light (the IEC 61966-2-1 curve; `libm::pow` so the
/// value is the same on every machine).
pub(crate) fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        libm::pow((c + 0.055) / 1.055, 2.4)
    }
}

/// Tree builder for one statement parsed at byte `base` of `file`.
pub(crate) struct Builder {
    /// The file being parsed.
    file: FileId,
    /// Offset of the parsed slice in the file.
    base: usize,
    /// Slips and warnings found while building (a `RefCell` because the Pratt parser's
    /// callbacks share the builder).
    diags: RefCell<Vec<Diagnostic>>,
}

type P<'i> = Pair<'i, Rule>;

impl Builder {
    /// A builder for the statement at `base`.
    pub(crate) fn new(file: FileId, base: usize) -> Builder {
        Builder {
            file,
            base,
            diags: RefCell::new(Vec::new()),
        }
    }

    /// The diagnostics found while building.
    pub(crate) fn finish(self) -> Vec<Diagnostic> {
        self.diags.into_inner()
    }

    fn push(&self, d: Diagnostic) {
        self.diags.borrow_mut().push(d);
    }

    fn span(&self, p: &P) -> Span {
        let s = p.as_span();
        Span::new(self.file, self.base + s.start(), self.base + s.end())
    }

    fn name(&self, p: &P) -> Name {
        Name {
            sym: Sym::new(p.as_str()),
            span: self.span(p),
        }
    }

    /// A statement pair (`import_stmt`, `let_stmt`, `fn_def` or `expr`).
    pub(crate) fn stmt(&self, p: P) -> Stmt {
        match p.as_rule() {
            Rule::import_stmt => Stmt::Import(Box::new(self.import(p))),
            Rule::let_stmt => Stmt::Let(self.let_stmt(p)),
            Rule::fn_def => Stmt::Fn(Rc::new(self.fn_def(p))),
            _ => Stmt::Expr(self.expr(p)),
        }
    }

    /// Warns when a statement that starts with `-` follows an expression or `let` that it could
    /// have continued: `-y` on its own line is a new statement (`- y` would subtract).
    /// `after_continuable`: whether the statement before is one ([`continuable`]).
    pub(crate) fn check_minus_line(&self, after_continuable: bool, p: &P) {
        if !p.as_str().starts_with('-') || !after_continuable {
            return;
        }
        let start = self.span(p).start as usize;
        let span = Span::new(self.file, start, start + 1);
        self.push(
            Diagnostic::warning(
                "rtc::syntax::ambiguous_minus",
                span,
                "this line starts a new statement; it does not subtract from the line above",
            )
            .with_label("a `-` with no space after it negates the value that follows")
            .with_help("to subtract, put a space after the `-`; to keep a new statement, write it in parentheses `(-...)`"),
        );
    }

    fn import(&self, p: P) -> Import {
        let span = self.span(&p);
        let mut it = p.into_inner();
        let src = it.next().expect("grammar: import source");
        let source_span = self.span(&src);
        let source = if src.as_rule() == Rule::string {
            ImportSource::File(self.plain_string(src))
        } else {
            ImportSource::Std(src.as_str().to_owned())
        };
        let mut alias = None;
        let mut names = Vec::new();
        for q in it {
            match q.as_rule() {
                Rule::ident => alias = Some(self.name(&q)),
                _ => names = q.into_inner().map(|n| self.name(&n)).collect(),
            }
        }
        Import {
            source,
            source_span,
            alias,
            names,
            span,
        }
    }

    fn plain_string(&self, p: P) -> String {
        let mut out = String::new();
        for part in p.into_inner() {
            match part.as_rule() {
                Rule::str_text => out.push_str(part.as_str()),
                Rule::str_escape => out.push(unescape(part.as_str())),
                _ => {
                    let s = self.span(&part);
                    self.push(
                        Diagnostic::error(
                            "rtc::syntax::unexpected",
                            s,
                            "interpolation is not allowed in an import path",
                        )
                        .with_label("not a fixed path")
                        .with_help("write the path as plain text"),
                    );
                }
            }
        }
        out
    }

    fn let_stmt(&self, p: P) -> Let {
        let span = self.span(&p);
        let mut public = false;
        let mut param = false;
        let mut name = None;
        let mut ty = None;
        let mut value = None;
        for q in p.into_inner() {
            match q.as_rule() {
                Rule::pub_kw => public = true,
                Rule::param_kw => param = true,
                Rule::ident => name = Some(self.name(&q)),
                Rule::type_ann => ty = Some(Box::new(self.type_ann(q))),
                _ => value = Some(self.expr(q)),
            }
        }
        Let {
            public,
            param,
            name: name.expect("grammar: let name"),
            ty,
            value: value.expect("grammar: let value"),
            span,
        }
    }

    fn type_ann(&self, p: P) -> TypeAnn {
        let span = self.span(&p);
        let mut it = p.into_inner();
        let name = self.name(&it.next().expect("grammar: type name"));
        // A `?` after the type (optional) is accepted and not recorded: nothing reads it.
        let arg = it
            .find(|q| q.as_rule() == Rule::type_ann)
            .map(|q| Box::new(self.type_ann(q)));
        TypeAnn { name, arg, span }
    }

    fn fn_def(&self, p: P) -> FnDef {
        let mut public = false;
        let mut name = None;
        let mut params = Vec::new();
        let mut ret = None;
        let mut body = None;
        for q in p.into_inner() {
            match q.as_rule() {
                Rule::pub_kw => public = true,
                Rule::ident => name = Some(self.name(&q)),
                Rule::params => params = self.params(q),
                Rule::type_ann => ret = Some(self.type_ann(q)),
                _ => body = Some(self.block(q)),
            }
        }
        FnDef {
            public,
            name: name.expect("grammar: fn name"),
            params,
            ret,
            body: body.expect("grammar: fn body"),
        }
    }

    fn params(&self, p: P) -> Vec<Param> {
        p.into_inner()
            .map(|q| {
                let mut it = q.into_inner();
                let name = self.name(&it.next().expect("grammar: param name"));
                let mut ty = None;
                let mut default = None;
                for r in it {
                    match r.as_rule() {
                        Rule::type_ann => ty = Some(self.type_ann(r)),
                        _ => default = Some(self.expr(r)),
                    }
                }
                Param { name, ty, default }
            })
            .collect()
    }

    fn block(&self, p: P) -> Block {
        let span = self.span(&p);
        let mut stmts: Vec<Stmt> = Vec::new();
        for q in p.into_inner() {
            self.check_minus_line(stmts.last().is_some_and(continuable), &q);
            stmts.push(self.stmt(q));
        }
        Block { stmts, span }
    }
}

/// Whether a line starting with `-` after `stmt` could have continued it: after an expression or
/// a `let`, not after an `import` or a `fn`.
pub(crate) fn continuable(stmt: &Stmt) -> bool {
    matches!(stmt, Stmt::Expr(_) | Stmt::Let(_))
}

fn unescape(s: &str) -> char {
    match s.as_bytes().get(1) {
        Some(b'n') => '\n',
        Some(b't') => '\t',
        Some(&c) => c as char,
        None => '\\',
    }
}
