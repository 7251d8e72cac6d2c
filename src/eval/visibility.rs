//! The visibility flags of objects: `.no_shadow()`, `.no_image()` and `.no_reflection()`, after
//! POV-Ray's object modifiers of the same names. Each returns the object with one more kind of
//! ray passing through it.

use std::rc::Rc;

use super::args::{ArgVal, CallSite, Params};
use super::error::R;
use super::schema::{Group, Sig};
use super::value::{Obj, Value};
use crate::ir::Visibility;

/// The visibility methods of objects.
pub(crate) static METHODS: &[&Sig] = &[&NO_SHADOW, &NO_IMAGE, &NO_REFLECTION];

/// `.no_shadow()`.
static NO_SHADOW: Sig = Sig::new(
    "no_shadow",
    Group::Method,
    "The object casts no shadow: shadow rays pass through it (it is still seen, lit and reflected).",
    &[],
    "Object",
)
.examples(&["sphere(radius: 0.3).no_shadow()"]);

/// `.no_image()`.
static NO_IMAGE: Sig = Sig::new(
    "no_image",
    Group::Method,
    "The object is not in the image: camera rays, and rays refracted from them, pass through it; it still casts shadows and shows in reflections.",
    &[],
    "Object",
)
.examples(&["sphere(radius: 1).no_image()"]);

/// `.no_reflection()`.
static NO_REFLECTION: Sig = Sig::new(
    "no_reflection",
    Group::Method,
    "The object is not in reflections: rays that have been reflected pass through it; the camera still sees it.",
    &[],
    "Object",
)
.examples(&["sphere(radius: 1).no_reflection()"]);

/// Whether `name` is a visibility method.
pub(crate) fn is_method(name: &str) -> bool {
    METHODS.iter().any(|m| m.name == name)
}

/// `o.no_shadow()`, `o.no_image()` or `o.no_reflection()` (`site.name` tells which).
pub(crate) fn hide(mut o: Rc<Obj>, site: CallSite, args: Vec<ArgVal>) -> R<Value> {
    let (sig, flag) = match site.name {
        "no_shadow" => (&NO_SHADOW, Visibility::NO_SHADOW),
        "no_image" => (&NO_IMAGE, Visibility::NO_IMAGE),
        _ => (&NO_REFLECTION, Visibility::NO_REFLECTION),
    };
    // The schema refuses arguments with the usual diagnostics.
    Params::new(site, sig, args)?;
    let o2 = Rc::make_mut(&mut o);
    o2.visibility = o2.visibility.with(flag);
    Ok(Value::Object(o))
}
