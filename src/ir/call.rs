//! A shape as the language's constructor call that makes it (`Shape::call`): what `rtc
//! convert` writes, so the back end needs no arm per shape. A leaf of the IR.

use std::path::PathBuf;

use glam::DVec3;

/// A constructor call: the built-in's name and its named arguments, in the order written.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ShapeCall {
    /// The constructor (`sphere`, `ring`, ...).
    pub(crate) name: &'static str,
    /// The arguments by parameter name; parameters at their defaults are left out.
    pub(crate) args: Vec<(&'static str, Arg)>,
}

/// An argument value as the IR holds it.
#[derive(Clone, Debug, PartialEq)]
pub enum Arg {
    /// A number.
    Number(f64),
    /// A point or vector, written as given.
    Point(DVec3),
    /// A unit direction the constructor normalises: written as a vector whose unit vector is
    /// exactly this one.
    Direction(DVec3),
    /// A Boolean.
    Bool(bool),
    /// An asset's path (written relative to the converted file).
    Path(PathBuf),
    /// A list.
    List(Vec<Arg>),
    /// A record of named fields.
    Record(Vec<(&'static str, Arg)>),
}
