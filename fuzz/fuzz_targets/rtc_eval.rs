//! `.rtc` text: parse, evaluate (with small budgets), lint, validate, render 4×4.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rtc::source::SourceMap;

fuzz_target!(|data: &[u8]| {
    // The CLI refuses files that are not UTF-8 before parsing, so only text gets further.
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let mut sources = SourceMap::new();
    let path = rtc_fuzz::repo().join("scenes/fuzz.rtc");
    let loaded = rtc::eval::load_source(&path, text, &mut sources, &rtc_fuzz::eval_options());
    rtc_fuzz::after_load(loaded, &sources, false);
});
