//! The generated pest parser of `grammar/rtc.pest` and its `Rule`s, in a file of their own so
//! that the files reading parse trees import the grammar, not the syntax room's façade.

/// The generated pest parser.
#[derive(pest_derive::Parser)]
#[grammar = "../grammar/rtc.pest"]
pub(crate) struct RtcParser;
