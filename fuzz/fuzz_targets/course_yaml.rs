//! Course YAML text (UTF-8, or Latin-1 as the CLI decodes it), read as if it sat next to the
//! course scenes so that texture and model paths from the seeds resolve: read, lint, validate,
//! render 4×4.
#![no_main]

use libfuzzer_sys::fuzz_target;
use rtc::source::SourceMap;

fuzz_target!(|data: &[u8]| {
    let text = rtc_fuzz::decode_text(data);
    let mut sources = SourceMap::new();
    let path = rtc_fuzz::repo().join("tests/data/course/yaml/fuzz.yaml");
    let loaded = rtc::compat::load_yaml_source(&path, &text, &mut sources);
    rtc_fuzz::after_load(loaded, &sources, true);
});
