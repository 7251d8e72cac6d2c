//! A small YAML document tree that keeps a source [`Span`] on every node, built from the
//! position-carrying events of `granit_parser` (the parser under serde-saphyr). serde-saphyr's own
//! deserializer loses positions of nested values, and every course diagnostic needs line:col.

use std::collections::HashMap;

use serde_saphyr::granit_parser::{Event, Parser, ScalarStyle, Span as YamlSpan, StructureStyle};

use crate::diag::{Diagnostic, Diagnostics};
use crate::ir::limits::Memory;
use crate::source::{FileId, Span};

/// Upper bound on nodes (aliases are expanded by copying), so an alias bomb cannot exhaust memory.
const MAX_NODES: usize = 1_000_000;

/// One YAML node with its span.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct YamlNode {
    /// What the node holds.
    pub(crate) kind: YamlKind,
    /// Where it was written.
    pub(crate) span: Span,
}

/// The three YAML node shapes.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum YamlKind {
    /// A scalar's text after escape processing; `quoted` is false for plain scalars.
    Scalar {
        /// The text.
        text: String,
        /// Written in quotes or as a block scalar (so never null, a number by YAML's rules only
        /// because the course reader was lenient).
        quoted: bool,
    },
    /// A sequence.
    Seq(Vec<YamlNode>),
    /// A mapping, in source order (duplicates kept; the reader reports them).
    Map(Vec<(YamlNode, YamlNode)>),
}

impl YamlNode {
    /// A short description of the node's shape for messages ("a list", "a map", "`abc`").
    pub(crate) fn describe(&self) -> String {
        match &self.kind {
            YamlKind::Scalar { text, .. } if text.is_empty() => "nothing".to_string(),
            YamlKind::Scalar { text, .. } => format!("`{}`", shorten(text)),
            YamlKind::Seq(items) => format!("a list of {}", items.len()),
            YamlKind::Map(_) => "a map".to_string(),
        }
    }

    /// The scalar text, if this is a scalar.
    pub(crate) fn scalar(&self) -> Option<&str> {
        match &self.kind {
            YamlKind::Scalar { text, .. } => Some(text),
            _ => None,
        }
    }
}

fn shorten(text: &str) -> String {
    let mut s: String = text.chars().take(40).collect();
    if s.len() < text.len() {
        s.push('…');
    }
    s
}

/// The first document of a YAML text, or `None` after a syntax error (reported in `diags`).
/// A second document is reported as a warning, as the course reader did.
/// Every node and scalar byte made, aliases' copies included, is charged to `memory`.
pub(crate) fn parse_first_document(
    text: &str,
    file: FileId,
    diags: &mut Diagnostics,
    memory: &mut Memory,
) -> Option<YamlNode> {
    let mut builder = Builder {
        text,
        file,
        stack: Vec::new(),
        anchors: HashMap::new(),
        nodes: 0,
        memory: *memory,
        root: None,
    };
    let mut documents = 0usize;
    for event in Parser::new_from_str(text) {
        let (event, span) = match event {
            Ok(pair) => pair,
            Err(e) => {
                let at = builder.offset(e.marker().byte_offset(), e.marker().index());
                let mut d = Diagnostic::error(
                    "rtc::yaml::syntax",
                    Span::new(file, at, at),
                    format!("invalid YAML: {}", e.info()),
                )
                .with_label("the YAML parser stopped here");
                if let Some(open) = unclosed_bracket(text.get(..at).unwrap_or("")) {
                    d = d
                        .with_secondary(
                            Span::new(file, open, open + 1),
                            "this bracket is never closed",
                        )
                        .with_help(
                            "close the list or map on the same line, e.g. `[200, 200, 1000]`",
                        );
                } else if text.contains('\t') {
                    d = d.with_help("YAML indentation must use spaces, not tabs");
                }
                diags.push(d);
                return None;
            }
        };
        match event {
            Event::DocumentStart(..) => {
                documents += 1;
                if documents == 2 {
                    let at = builder.span(span);
                    diags.push(
                        Diagnostic::warning(
                            "rtc::yaml::extra_document",
                            at,
                            "only the first YAML document is read",
                        )
                        .with_label("this document is ignored"),
                    );
                }
            }
            _ if documents >= 2 => {}
            other => {
                if let Err(d) = builder.event(other, span) {
                    diags.push(*d);
                    return None;
                }
            }
        }
    }
    *memory = builder.memory;
    builder.root
}

/// A collection being built: its items, its start span, its anchor, and whether it is a flow
/// collection (whose end event marks the closing bracket; a block one ends at its last item).
/// The byte offset of the innermost `[` or `{` still open at the end of `text`, ignoring comments
/// and quoted text (a best-effort hint for the most common slip in course files).
fn unclosed_bracket(text: &str) -> Option<usize> {
    let mut open = Vec::new();
    let mut quote = None;
    let mut comment = false;
    for (i, c) in text.char_indices() {
        match (c, quote) {
            ('\n', _) => comment = false,
            _ if comment => {}
            (q, Some(open_q)) if q == open_q => quote = None,
            (_, Some(_)) => {}
            ('"' | '\'', None) => quote = Some(c),
            ('#', None) => comment = true,
            ('[' | '{', None) => open.push(i),
            (']' | '}', None) => {
                open.pop();
            }
            _ => {}
        }
    }
    open.pop()
}

enum Open {
    Seq(Vec<YamlNode>, Span, usize, bool),
    Map(
        Vec<(YamlNode, YamlNode)>,
        Option<YamlNode>,
        Span,
        usize,
        bool,
    ),
}

struct Builder<'t> {
    text: &'t str,
    file: FileId,
    stack: Vec<Open>,
    /// Anchored nodes with their subtrees' node counts and bytes.
    anchors: HashMap<usize, (YamlNode, usize, u64)>,
    nodes: usize,
    /// The load's memory budget, charged for every node made.
    memory: Memory,
    root: Option<YamlNode>,
}

impl Builder<'_> {
    fn offset(&self, bytes: Option<usize>, chars: usize) -> usize {
        let at = match bytes {
            Some(b) => b,
            None => self
                .text
                .char_indices()
                .nth(chars)
                .map_or(self.text.len(), |(i, _)| i),
        };
        at.min(self.text.len())
    }

    fn span(&self, s: YamlSpan) -> Span {
        let start = self.offset(s.start.byte_offset(), s.start.index());
        let end = self.offset(s.end.byte_offset(), s.end.index());
        Span::new(self.file, start, end)
    }

    fn event(&mut self, event: Event<'_>, ys: YamlSpan) -> Result<(), Box<Diagnostic>> {
        let span = self.span(ys);
        match event {
            Event::Scalar(text, style, anchor, _) => {
                let quoted = !matches!(style, ScalarStyle::Plain);
                let node = YamlNode {
                    kind: YamlKind::Scalar {
                        text: text.into_owned(),
                        quoted,
                    },
                    span,
                };
                self.finish_node(node, anchor)?;
            }
            Event::SequenceStart(style, anchor, _) => {
                let flow = style == StructureStyle::Flow;
                self.stack.push(Open::Seq(Vec::new(), span, anchor, flow))
            }
            Event::MappingStart(style, anchor, _) => {
                let flow = style == StructureStyle::Flow;
                self.stack
                    .push(Open::Map(Vec::new(), None, span, anchor, flow))
            }
            Event::SequenceEnd => {
                if let Some(Open::Seq(items, start, anchor, flow)) = self.stack.pop() {
                    let end = match items.last() {
                        _ if flow => span,
                        Some(n) => n.span,
                        None => start,
                    };
                    let node = YamlNode {
                        kind: YamlKind::Seq(items),
                        span: start.join(end),
                    };
                    self.finish_node(node, anchor)?;
                }
            }
            Event::MappingEnd => {
                if let Some(Open::Map(entries, _, start, anchor, flow)) = self.stack.pop() {
                    let end = match entries.last() {
                        _ if flow => span,
                        Some((_, v)) => v.span,
                        None => start,
                    };
                    let node = YamlNode {
                        kind: YamlKind::Map(entries),
                        span: start.join(end),
                    };
                    self.finish_node(node, anchor)?;
                }
            }
            Event::Alias(id) => {
                let Some(&(_, size, bytes)) = self.anchors.get(&id) else {
                    return Err(Box::new(
                        Diagnostic::error("rtc::yaml::syntax", span, "unknown YAML alias")
                            .with_label("no anchor of this name before it"),
                    ));
                };
                // Budget the whole copied subtree before copying it (an alias bomb).
                self.spend(size, span)?;
                self.charge(bytes, span)?;
                let Some((target, ..)) = self.anchors.get(&id) else {
                    return Ok(());
                };
                let node = YamlNode {
                    kind: target.kind.clone(),
                    span,
                };
                self.place(node, 0)?;
            }
            _ => {}
        }
        Ok(())
    }

    fn spend(&mut self, nodes: usize, span: Span) -> Result<(), Box<Diagnostic>> {
        self.nodes = self.nodes.saturating_add(nodes);
        if self.nodes > MAX_NODES {
            return Err(Box::new(
                Diagnostic::error(
                    "rtc::yaml::too_large",
                    span,
                    "the YAML document is too large",
                )
                .with_label("expanding this node passes a million nodes"),
            ));
        }
        Ok(())
    }

    /// Charges `bytes` of nodes about to be made to the memory budget.
    fn charge(&mut self, bytes: u64, span: Span) -> Result<(), Box<Diagnostic>> {
        self.memory
            .charge(bytes)
            .map_err(|over| Box::new(over.diagnostic(span, "expanding this YAML node")))
    }

    fn finish_node(&mut self, node: YamlNode, anchor: usize) -> Result<(), Box<Diagnostic>> {
        self.spend(1, node.span)?;
        let own = match &node.kind {
            YamlKind::Scalar { text, .. } => NODE_BYTES + text.len() as u64,
            _ => NODE_BYTES,
        };
        self.charge(own, node.span)?;
        self.place(node, anchor)
    }

    /// Records an anchored node and adds a finished node to its parent (or makes it the root).
    fn place(&mut self, node: YamlNode, anchor: usize) -> Result<(), Box<Diagnostic>> {
        if anchor != 0 {
            // The anchor keeps its own copy for the aliases to clone: charged as well.
            let (count, bytes) = deep_size(&node);
            self.charge(bytes, node.span)?;
            self.anchors.insert(anchor, (node.clone(), count, bytes));
        }
        match self.stack.last_mut() {
            Some(Open::Seq(items, ..)) => items.push(node),
            Some(Open::Map(entries, pending, ..)) => match pending.take() {
                Some(key) => entries.push((key, node)),
                None => *pending = Some(node),
            },
            None => {
                if self.root.is_none() {
                    self.root = Some(node);
                }
            }
        }
        Ok(())
    }
}

/// Number of nodes in a subtree, for the alias-expansion budget.
/// Bytes one node is charged besides its scalar text.
const NODE_BYTES: u64 = std::mem::size_of::<YamlNode>() as u64;

/// The nodes under `node` (itself included) and the bytes they hold.
fn deep_size(node: &YamlNode) -> (usize, u64) {
    let add = |a: (usize, u64), b: (usize, u64)| (a.0 + b.0, a.1.saturating_add(b.1));
    match &node.kind {
        YamlKind::Scalar { text, .. } => (1, NODE_BYTES + text.len() as u64),
        YamlKind::Seq(items) => items.iter().map(deep_size).fold((1, NODE_BYTES), add),
        YamlKind::Map(entries) => entries
            .iter()
            .map(|(k, v)| add(deep_size(k), deep_size(v)))
            .fold((1, NODE_BYTES), add),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> (Option<YamlNode>, Diagnostics) {
        let mut diags = Diagnostics::default();
        let node = parse_first_document(text, FileId(0), &mut diags, &mut Memory::default());
        (node, diags)
    }

    #[test]
    fn keeps_positions_of_nested_scalars() {
        let text = "Eye: [1, 2, 3]\nLights:\n- position: [4,5,6]\n";
        let (node, diags) = parse(text);
        assert!(diags.items.is_empty());
        let YamlKind::Map(entries) = node.expect("a document").kind else {
            panic!("not a map")
        };
        let YamlKind::Seq(eye) = &entries[0].1.kind else {
            panic!("not a list")
        };
        let two = eye[1].span;
        assert_eq!(&text[two.start as usize..two.end as usize], "2");
        assert_eq!(entries[1].0.scalar(), Some("Lights"));
    }

    #[test]
    fn syntax_errors_become_diagnostics() {
        let (node, diags) = parse("Eye: [1, 2\nLights: x\n");
        assert!(node.is_none());
        assert_eq!(diags.items[0].code, "rtc::yaml::syntax");
    }

    #[test]
    fn alias_bombs_hit_the_node_budget() {
        let mut text = String::from("a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n");
        for i in 1..9 {
            let p = i - 1;
            text.push_str(&format!(
                "a{i}: &a{i} [*a{p}, *a{p}, *a{p}, *a{p}, *a{p}, *a{p}, *a{p}, *a{p}, *a{p}, *a{p}]\n"
            ));
        }
        let (node, diags) = parse(&text);
        assert!(node.is_none());
        assert_eq!(diags.items[0].code, "rtc::yaml::too_large");
    }

    #[test]
    fn second_document_warns() {
        let (node, diags) = parse("a: 1\n---\nb: 2\n");
        assert!(node.is_some());
        assert_eq!(diags.items[0].code, "rtc::yaml::extra_document");
    }
}
