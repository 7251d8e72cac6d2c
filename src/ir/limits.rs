//! Limits every stage shares, defined once: the language, both course front ends and the
//! renderer check against these constants (a course file asking for more gets a warning and
//! the cap; the language and a hand-built IR get an error).
