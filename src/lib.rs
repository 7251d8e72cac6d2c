//! rtc: a declarative scene-language compiler and Whitted ray tracer.
//!
//! Pipeline (data flows one way): source text → [`syntax`] (pest grammar, AST with spans) →
//! [`eval`] (names, types, loops, functions → [`ir::Scene`]) → [`opt`] (effects, bounds) → render.
//! The legacy course formats enter at the IR through [`compat`]. Diagnostics are plain data
//! ([`diag`]); only the binary prints them.
#![forbid(unsafe_code)]
// Diagnostics are returned by value on cold error paths; boxing them buys nothing measurable.
#![allow(clippy::result_large_err)]

pub mod check;
pub mod compat;
pub mod diag;
pub mod eval;
pub mod frontend;
pub mod geometry;
pub mod ir;
pub mod metrics;
pub mod opt;
pub mod render;
pub mod source;
pub mod syntax;
