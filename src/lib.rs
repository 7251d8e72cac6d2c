//! rtc: a declarative scene-language compiler and Whitted ray tracer.
//!
//! Pipeline (data flows one way; docs/architecture.md has the boundaries and who may import
//! whom, `tests/architecture.rs` enforces it): source text → [`syntax`] (AST with spans) →
//! [`eval`] (→ [`ir::Scene`]); the course formats reach the same IR through [`compat`];
//! [`loader`] picks the front end by extension. [`opt::prepare`] turns the IR into a
//! [`opt::Prepared`] scene (validation, [`assets`], instancing, materials, the [`geometry`]
//! world); [`render::render`] turns that into a [`render::film::Film`]; [`check::check`] is
//! `rtc check`; [`convert`] is the back end that writes an IR as rtc source (`rtc convert`);
//! [`accuracy`] measures what each quality knob costs and buys (`rtc accuracy`).
//! Diagnostics are plain data ([`diag`]); the library prints nothing.
#![forbid(unsafe_code)]
// Diagnostics are returned by value on cold error paths; boxing them buys nothing measurable.
#![allow(clippy::result_large_err)]

pub mod accuracy;
pub mod assets;
pub mod check;
pub mod compat;
pub mod convert;
pub mod diag;
pub mod eval;
pub mod geometry;
pub mod ir;
pub(crate) mod lanes;
pub mod loader;
pub mod metrics;
pub mod num;
pub mod opt;
pub mod pattern;
pub mod render;
pub mod source;
pub mod syntax;
