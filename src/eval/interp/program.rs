//! Module-level evaluation: hoisted `fn` items, `let`, imports (cached, cycle-checked), emission,
//! and recovery at statement boundaries.

use std::path::PathBuf;
use std::rc::Rc;

use crate::diag::Diagnostic;

use crate::syntax::ast::{ExprKind, File, Import, ImportSource, Name, Stmt};

use super::super::error::{EvalError, R, error, suggest};
use super::super::lower::{Lowerer, emittable};
use super::super::modules::{Binding, Module, STDLIB, Scope, identity, resolve, stdlib};
use super::super::value::{Closure, Value};
use super::Interp;

impl Interp<'_> {
    /// Records a statement's error (poisoned errors were reported already).
    fn record_error(&mut self, e: EvalError) {
        if let EvalError::Diag(d) = e {
            self.diags.push(*d);
        }
    }

    fn bind_module(&mut self, name: Name, value: Value, public: bool, poisoned: bool) {
        let mut items = self.scope.items.borrow_mut();
        if let Some(prev) = items.get(&name.sym) {
            let d = error(
                "rtc::name::duplicate",
                name.span,
                format!("`{}` is already defined", name.sym),
            )
            .with_label("second definition")
            .with_secondary(prev.span, "first definition")
            .with_help(format!(
                "rename one of them; names cannot be rebound (`let {}` is immutable)",
                name.sym
            ));
            drop(items);
            self.diags.push(d);
            return;
        }
        items.insert(
            name.sym,
            Binding {
                value,
                public,
                span: name.span,
                poisoned,
            },
        );
    }

    /// Evaluates a module's statements. `scene` receives emitted values; `None` for libraries,
    /// where emitting is an error.
    pub(crate) fn run_module(&mut self, file: &File<'_>, mut scene: Option<&mut Lowerer>) {
        // Every `fn` item is a statement pest built (the fast path reads none).
        for st in file.built_stmts() {
            if let Stmt::Fn(def) = st {
                let c = Closure {
                    def: def.clone(),
                    captured: Vec::new(),
                    module: self.scope.clone(),
                };
                self.bind_module(def.name, Value::Fn(Rc::new(c)), def.public, false);
            }
        }
        // A generated file's statements are read one at a time here, each dropped after use.
        let mut stmts = file.stmts();
        let mut index = 0;
        while let Some(st) = stmts.next_ref() {
            let stmt = index;
            index += 1;
            match st {
                Stmt::Fn(_) => {}
                Stmt::Import(im) => {
                    if let Err(e) = self.import(im) {
                        self.record_error(e);
                        for n in im.alias.iter().chain(im.names.iter()) {
                            self.bind_module(*n, Value::Unit, false, true);
                        }
                    }
                }
                Stmt::Let(l) => {
                    let value = match (l.param, scene.is_some()) {
                        (false, _) => self.eval(&l.value),
                        (true, true) => self.param_value(l),
                        (true, false) => Err(super::super::params::misplaced(l).into()),
                    };
                    let r = value.and_then(|v| match &l.ty {
                        Some(t) => super::super::types::check_ann(self, t, v, l.value.span),
                        None => Ok(v),
                    });
                    match r {
                        Ok(v) => self.bind_module(l.name, v, l.public, false),
                        Err(e) => {
                            self.record_error(e);
                            self.bind_module(l.name, Value::Unit, l.public, true);
                        }
                    }
                }
                Stmt::Expr(e) => {
                    if let (Some(l), ExprKind::For(..)) = (scene.as_deref_mut(), &e.kind) {
                        if let Err(err) = self.emit_for(e, stmt, l) {
                            self.record_error(err);
                        }
                        if self.split.done() {
                            // A helper's replay ends with its part of the loop.
                            return;
                        }
                        continue;
                    }
                    let v = match self.eval(e) {
                        Ok(v) => v,
                        Err(err) => {
                            self.record_error(err);
                            continue;
                        }
                    };
                    match scene.as_deref_mut() {
                        Some(l) => {
                            if let Err(d) = l.emit(&v, &self.object_budget(), e.span) {
                                self.diags.push(d);
                            }
                        }
                        None if emittable(&v) => {
                            let name = self.scope.name.clone();
                            self.diags.push(
                                error("rtc::module::emits", e.span, format!("the library module `{name}` emits {}", super::super::value::a_type(v.type_name())))
                                    .with_label("imported files may not add to the scene")
                                    .with_help("wrap it in a function, e.g. `pub fn make() { ... }`, and call that from the scene"),
                            );
                        }
                        None if matches!(v, Value::Unit) => {}
                        None => self.diags.push(
                            error(
                                "rtc::value::discarded",
                                e.span,
                                format!("this `{}` is discarded", v.type_name()),
                            )
                            .with_label("this value goes nowhere")
                            .with_help("bind it with `pub let name = ...`, or remove it"),
                        ),
                    }
                }
            }
        }
    }

    fn import(&mut self, im: &Import) -> R<()> {
        let module = self.load_module(im)?;
        if im.names.is_empty() {
            let alias = im.alias.unwrap_or_else(|| {
                // `std.materials` → `materials`, `"./lib/props.rtc"` → `props`: drop the file
                // extension before splitting, or the alias of every file would be `rtc`.
                let name = module.name.trim_end_matches(".rtc");
                let last = name.rsplit(['.', '/', '\\']).next().unwrap_or(name);
                Name {
                    sym: crate::syntax::intern::Sym::new(last),
                    span: im.source_span,
                }
            });
            self.bind_module(alias, Value::Module(module), false, false);
            return Ok(());
        }
        for n in &im.names {
            match super::super::members::member(
                self,
                Value::Module(module.clone()),
                *n,
                im.source_span,
            ) {
                Ok(v) => self.bind_module(*n, v, false, false),
                Err(e) => {
                    self.record_error(e);
                    self.bind_module(*n, Value::Unit, false, true);
                }
            }
        }
        Ok(())
    }

    fn load_module(&mut self, im: &Import) -> R<Rc<Module>> {
        let span = im.source_span;
        let (key, path, display, text) = match &im.source {
            ImportSource::Std(path) => {
                let Some(name) = path.strip_prefix("std.") else {
                    return Err(error("rtc::module::unknown", span, format!("unknown module `{path}`"))
                        .with_label("not a standard module")
                        .with_help(format!("standard modules start with `std.`; for a file write `import \"./{path}.rtc\"`"))
                        .into());
                };
                let Some(text) = stdlib(name) else {
                    let names: Vec<String> =
                        STDLIB.iter().map(|(n, _)| format!("std.{n}")).collect();
                    let help = suggest(path, names.iter().map(String::as_str))
                        .unwrap_or_else(|| format!("available: {}", names.join(", ")));
                    return Err(error(
                        "rtc::module::unknown",
                        span,
                        format!("unknown module `{path}`"),
                    )
                    .with_label("no such standard module")
                    .with_help(help)
                    .into());
                };
                let key = PathBuf::from(format!("<std>/{name}"));
                (key.clone(), key, path.clone(), Some(text.to_owned()))
            }
            ImportSource::File(rel) => {
                // `path` as the user would write it (messages, relative imports); `key` the
                // canonical file, which tells modules apart.
                let p = resolve(&self.scope.dir, rel);
                (identity(&p), p.clone(), p.display().to_string(), None)
            }
        };
        if let Some(pos) = self.loading.iter().position(|(k, _)| *k == key) {
            let mut chain: Vec<String> =
                self.loading[pos..].iter().map(|(k, _)| short(k)).collect();
            chain.push(short(&key));
            return Err(error("rtc::module::cycle", span, "import cycle")
                .with_label(format!(
                    "this import closes the cycle {}",
                    chain.join(" → ")
                ))
                .with_help(
                    "move what both files need into a third module that neither imports back",
                )
                .into());
        }
        if let Some(m) = self.modules.get(&key) {
            return Ok(m.clone());
        }
        self.import_budget(span)?;
        let text = match text.or_else(|| self.split.replayed_text(&path)) {
            Some(t) => t,
            None => read_module(&path).map_err(|e| {
                error(
                    "rtc::module::not_found",
                    span,
                    format!("cannot read module `{display}`"),
                )
                .with_label(if e.kind() == std::io::ErrorKind::NotFound {
                    "no such file".to_owned()
                } else {
                    e.to_string()
                })
                .with_help(format!(
                    "check the path; it is relative to `{}`",
                    self.sources.get(self.scope.file).path.display()
                ))
            })?,
        };
        let file = self.sources.add(
            if key.starts_with("<std>") {
                PathBuf::from(format!("std/{}.rtc", &display[4..]))
            } else {
                path.clone()
            },
            text,
        );
        let text = self.sources.get(file).text.clone();
        let (ast, diags) = crate::syntax::parse(file, &text);
        let had_errors = diags.iter().any(Diagnostic::is_error);
        self.diags.extend(diags);
        let Some(ast) = ast.filter(|_| !had_errors) else {
            return Err(EvalError::Poisoned);
        };
        let dir = path.parent().map(PathBuf::from).unwrap_or_default();
        let scope = Rc::new(Scope::new(file, dir, display.clone()));
        self.loading.push((key.clone(), span));
        let saved_scope = std::mem::replace(&mut self.scope, scope.clone());
        let saved_locals = std::mem::take(&mut self.locals);
        let saved_base = std::mem::replace(&mut self.frame_base, 0);
        self.run_module(&ast, None);
        self.scope = saved_scope;
        self.locals = saved_locals;
        self.frame_base = saved_base;
        self.loading.pop();
        let m = Rc::new(Module {
            name: display,
            scope,
        });
        self.modules.insert(key, m.clone());
        Ok(m)
    }
}

/// The text of an imported file: a regular file within the source budget, in UTF-8.
fn read_module(path: &std::path::Path) -> std::io::Result<String> {
    let bytes = crate::source::read_regular(path, crate::source::MAX_SOURCE_BYTES)?;
    String::from_utf8(bytes).map_err(|_| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            "the file is not UTF-8 text",
        )
    })
}

impl Interp<'_> {
    /// Refuses a new import beyond the budgets of §24: distinct files imported, and imports
    /// nested in imports (each level holds a part of the evaluation's stack).
    fn import_budget(&self, span: crate::source::Span) -> R<()> {
        let depth = self.loading.len().saturating_sub(1);
        if depth >= self.opts.max_import_depth as usize {
            return Err(error(
                "rtc::budget::imports",
                span,
                format!("imports nested deeper than {}", self.opts.max_import_depth),
            )
            .with_label("this import exceeds the nesting budget")
            .with_help(
                "import the modules this chain needs from the scene file, not through each other",
            )
            .into());
        }
        // Every module read so far (standard ones too) and those being read but the scene.
        let files = self.modules.len() + depth;
        if files >= self.opts.max_imports as usize {
            return Err(error(
                "rtc::budget::imports",
                span,
                format!("more than {} modules imported", self.opts.max_imports),
            )
            .with_label("this import exceeds the budget of imported files")
            .with_help("merge small modules into fewer files")
            .into());
        }
        Ok(())
    }
}

fn short(p: &std::path::Path) -> String {
    p.file_name().map_or_else(
        || p.display().to_string(),
        |f| f.to_string_lossy().into_owned(),
    )
}
