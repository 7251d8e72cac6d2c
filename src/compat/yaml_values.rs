//! Typed reads from [`YamlNode`]s with precise diagnostics: numbers, integers, booleans, triples, and a
//! map view that tracks which keys were read (unread keys become warnings, as in pbrt).

use glam::DVec3;

use crate::compat::course;
use crate::compat::yaml_tree::{YamlKind, YamlNode};
use crate::diag::{Diagnostic, Diagnostics, did_you_mean};
use crate::source::Span;

/// The keys of one YAML map, with the ones already read marked.
pub(crate) struct MapView<'n> {
    entries: &'n [(YamlNode, YamlNode)],
    used: Vec<bool>,
    /// Span of the whole map, for missing-key errors.
    span: Span,
}

/// A key that was found: its span and value.
pub(crate) struct Entry<'n> {
    /// The key as written.
    pub(crate) key: &'n YamlNode,
    /// The value.
    pub(crate) value: &'n YamlNode,
}

impl<'n> MapView<'n> {
    /// Views a map node; anything else is reported (`what` names the expected map).
    pub(crate) fn new(
        node: &'n YamlNode,
        what: &str,
        diags: &mut Diagnostics,
    ) -> Option<MapView<'n>> {
        let YamlKind::Map(entries) = &node.kind else {
            diags.push(
                Diagnostic::error(
                    "rtc::yaml::type",
                    node.span,
                    format!(
                        "expected {what} (a map of `key: value` lines), found {}",
                        node.describe()
                    ),
                )
                .with_label("not a map"),
            );
            return None;
        };
        let mut used = vec![false; entries.len()];
        for (i, (k, _)) in entries.iter().enumerate() {
            let Some(name) = k.scalar() else { continue };
            if let Some((first, _)) = entries[..i].iter().find(|(p, _)| p.scalar() == Some(name)) {
                // Reported here; the reader uses the first occurrence.
                used[i] = true;
                diags.push(
                    Diagnostic::error(
                        "rtc::yaml::duplicate_key",
                        k.span,
                        format!("key `{name}` appears twice"),
                    )
                    .with_label("second occurrence")
                    .with_secondary(first.span, "first occurrence")
                    .with_help("delete one of the two"),
                );
            }
        }
        Some(MapView {
            entries,
            used,
            span: node.span,
        })
    }

    /// Finds a key by its official spelling `names[0]` or an accepted alternative `names[1..]`.
    /// A case-insensitive match is accepted with a spelling warning.
    pub(crate) fn get(&mut self, names: &[&str], diags: &mut Diagnostics) -> Option<Entry<'n>> {
        let entries = self.entries;
        for (i, (k, v)) in entries.iter().enumerate() {
            if self.used[i] {
                continue;
            }
            let Some(key) = k.scalar() else { continue };
            if names.contains(&key) {
                self.used[i] = true;
                return Some(Entry { key: k, value: v });
            }
        }
        for (i, (k, v)) in entries.iter().enumerate() {
            if self.used[i] {
                continue;
            }
            let Some(key) = k.scalar() else { continue };
            if names.iter().any(|n| n.eq_ignore_ascii_case(key)) {
                let name = names[0];
                self.used[i] = true;
                diags.push(
                    Diagnostic::warning(
                        "rtc::yaml::spelling",
                        k.span,
                        format!("`{key}` read as `{name}`"),
                    )
                    .with_label("non-standard spelling")
                    .with_help(format!("write `{name}`")),
                );
                return Some(Entry { key: k, value: v });
            }
        }
        None
    }

    /// Like [`MapView::get`], but a missing key is an error with `example` as the help.
    pub(crate) fn require(
        &mut self,
        names: &[&str],
        owner: &str,
        example: &str,
        diags: &mut Diagnostics,
    ) -> Option<Entry<'n>> {
        let found = self.get(names, diags);
        if found.is_none() {
            diags.push(
                Diagnostic::error(
                    "rtc::yaml::missing_key",
                    self.head(),
                    format!("{owner} has no `{}`", names[0]),
                )
                .with_label(format!("`{}` is missing here", names[0]))
                .with_help(format!("add `{example}`")),
            );
        }
        found
    }

    /// The first line of the map (where a missing-key error points).
    pub(crate) fn head(&self) -> Span {
        match self.entries.first() {
            Some((k, _)) => k.span,
            None => self.span,
        }
    }

    /// The span of a key's value (exact spelling), without marking it read.
    pub(crate) fn span_of(&self, name: &str) -> Option<Span> {
        self.entries
            .iter()
            .find(|(k, _)| k.scalar() == Some(name))
            .map(|(_, v)| v.span)
    }

    /// Marks a key as read without using it.
    pub(crate) fn ignore(&mut self, name: &str) {
        for (i, (k, _)) in self.entries.iter().enumerate() {
            if k.scalar().is_some_and(|s| s.eq_ignore_ascii_case(name)) {
                self.used[i] = true;
            }
        }
    }

    /// Warns about every key that was not read; `known` feeds did-you-mean.
    pub(crate) fn finish(self, owner: &str, known: &[&str], diags: &mut Diagnostics) {
        for (i, (k, _)) in self.entries.iter().enumerate() {
            if self.used[i] {
                continue;
            }
            let name = k.scalar().unwrap_or("?");
            let mut d = Diagnostic::warning(
                "rtc::yaml::unknown_key",
                k.span,
                format!("unknown key `{name}` in {owner}"),
            )
            .with_label("ignored");
            if let Some(g) = did_you_mean(name, known.iter().copied()) {
                d = d.with_help(format!("did you mean `{g}`?"));
            }
            diags.push(d);
        }
    }
}

/// A number (any scalar style; the course reader converted quoted text too).
pub(crate) fn number(node: &YamlNode, what: &str, diags: &mut Diagnostics) -> Option<f64> {
    let not_a_number = |diags: &mut Diagnostics| {
        diags.push(
            Diagnostic::error(
                "rtc::yaml::type",
                node.span,
                format!("expected a number for {what}, found {}", node.describe()),
            )
            .with_label("not a number"),
        );
        None
    };
    let Some(text) = node.scalar() else {
        return not_a_number(diags);
    };
    let t = text.trim();
    let value = match t.to_ascii_lowercase().as_str() {
        ".nan" => Some(f64::NAN),
        ".inf" | "+.inf" => Some(f64::INFINITY),
        "-.inf" => Some(f64::NEG_INFINITY),
        _ => t.parse::<f64>().ok(),
    };
    let Some(value) = value else {
        return not_a_number(diags);
    };
    course::check_number(t, value, node.span, what, diags)
}

/// A number that must be 0 or more (coefficients).
pub(crate) fn non_negative(node: &YamlNode, what: &str, diags: &mut Diagnostics) -> Option<f64> {
    let v = number(node, what, diags)?;
    if v < 0.0 {
        diags.push(course::out_of_range(
            node.span,
            node.scalar().unwrap_or("").trim(),
            what,
            "0 or more",
        ));
        return None;
    }
    Some(v)
}

/// A number that must be greater than 0 (radii, sizes).
pub(crate) fn positive(node: &YamlNode, what: &str, diags: &mut Diagnostics) -> Option<f64> {
    let v = number(node, what, diags)?;
    if v <= 0.0 {
        diags.push(course::out_of_range(
            node.span,
            node.scalar().unwrap_or("").trim(),
            what,
            "greater than 0",
        ));
        return None;
    }
    Some(v)
}

/// A whole number in `min..=max`.
pub(crate) fn integer(
    node: &YamlNode,
    what: &str,
    min: u32,
    max: u32,
    diags: &mut Diagnostics,
) -> Option<u32> {
    let v = number(node, what, diags)?;
    let text = node.scalar().unwrap_or("").trim();
    if v.fract() != 0.0 {
        diags.push(
            Diagnostic::error(
                "rtc::yaml::type",
                node.span,
                format!("expected a whole number for {what}, found `{text}`"),
            )
            .with_label("not a whole number")
            .with_help(format!("write `{}`", v.round())),
        );
        return None;
    }
    if v < f64::from(min) || v > f64::from(max) {
        diags.push(course::out_of_range(
            node.span,
            text,
            what,
            &if max == u32::MAX {
                format!("at least {min}")
            } else {
                format!("between {min} and {max}")
            },
        ));
        return None;
    }
    Some(v as u32)
}

/// `true`/`false` (also `yes`/`no`/`on`/`off`, any case, as YAML 1.1 readers took them).
pub(crate) fn boolean(node: &YamlNode, what: &str, diags: &mut Diagnostics) -> Option<bool> {
    let text = node.scalar().map(|t| t.trim().to_ascii_lowercase());
    match text.as_deref() {
        Some("true" | "yes" | "on") => Some(true),
        Some("false" | "no" | "off") => Some(false),
        _ => {
            diags.push(
                Diagnostic::error(
                    "rtc::yaml::type",
                    node.span,
                    format!(
                        "expected `true` or `false` for {what}, found {}",
                        node.describe()
                    ),
                )
                .with_label("not a boolean")
                .with_help(format!("write `{what}: true` or `{what}: false`")),
            );
            None
        }
    }
}

/// What a triple stands for, which decides the help on a wrong length.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Triple {
    /// `[x, y, z]`.
    Point,
    /// `[r, g, b]`, components 0 or more.
    Color,
}

/// A list of exactly three numbers.
pub(crate) fn triple(
    node: &YamlNode,
    what: &str,
    kind: Triple,
    diags: &mut Diagnostics,
) -> Option<DVec3> {
    let YamlKind::Seq(items) = &node.kind else {
        let example = if kind == Triple::Color {
            "[1, 0.5, 0]"
        } else {
            "[0, 0, 0]"
        };
        diags.push(
            Diagnostic::error(
                "rtc::yaml::type",
                node.span,
                format!(
                    "expected a list of three numbers for {what}, found {}",
                    node.describe()
                ),
            )
            .with_label("not a list")
            .with_help(format!("write it as `{example}`")),
        );
        return None;
    };
    if items.len() != 3 {
        let help = match kind {
            Triple::Color => "a colour has three components: [r, g, b]",
            Triple::Point => "a point or direction has three coordinates: [x, y, z]",
        };
        diags.push(
            Diagnostic::error(
                "rtc::yaml::arity",
                node.span,
                format!("{what} has {} components, expected 3", items.len()),
            )
            .with_label(format!("{} numbers", items.len()))
            .with_help(help),
        );
        return None;
    }
    let mut v = [0.0; 3];
    let mut ok = true;
    for (slot, item) in v.iter_mut().zip(items) {
        let read = if kind == Triple::Color {
            non_negative(item, &format!("a component of {what}"), diags)
        } else {
            number(item, &format!("a coordinate of {what}"), diags)
        };
        match read {
            Some(x) => *slot = x,
            None => ok = false,
        }
    }
    ok.then(|| DVec3::from_array(v))
}

/// A scalar string.
pub(crate) fn string<'n>(
    node: &'n YamlNode,
    what: &str,
    diags: &mut Diagnostics,
) -> Option<&'n str> {
    match node.scalar() {
        Some(t) if !t.trim().is_empty() => Some(t.trim()),
        _ => {
            diags.push(
                Diagnostic::error(
                    "rtc::yaml::type",
                    node.span,
                    format!("expected a name for {what}, found {}", node.describe()),
                )
                .with_label("not a name"),
            );
            None
        }
    }
}
