//! Legacy course `.in` text (UTF-8, or Latin-1 as the CLI decodes it): read, lint, validate,
//! render 4×4.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rtc::source::SourceMap;

fuzz_target!(|data: &[u8]| {
    let text = rtc_fuzz::decode_text(data);
    let mut sources = SourceMap::new();
    let path = rtc_fuzz::repo().join("tests/data/course/in/fuzz.in");
    let loaded = rtc::compat::load_in_source(&path, &text, &mut sources);
    rtc_fuzz::after_load(loaded, &sources, true);
});
