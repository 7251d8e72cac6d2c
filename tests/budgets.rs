//! Budgets a hostile file cannot break (issue 10): the image's memory, texture pixels, mesh file
//! bytes, evaluation, and `--time-limit`. Each overrun is an error at the place in the scene that
//! asked for it (file:line:column), with a label and a concrete fix, exit code 1, and no image
//! written over an existing one. `rtc check` and `rtc render` refuse the same scenes.

mod cli_support;

use std::path::{Path, PathBuf};
use std::process::Output;

use cli_support::{rtc, scratch};

use rtc::eval::{EvalOptions, load_source};
use rtc::ir::limits::{MAX_IMAGE_BYTES, MAX_MESH_FILE_BYTES, MAX_TEXTURE_PIXELS, image_bytes};
use rtc::source::SourceMap;

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Writes `text` as `scene.rtc` in `dir` and returns its path.
fn scene_file(dir: &Path, text: &str) -> PathBuf {
    let path = dir.join("scene.rtc");
    std::fs::write(&path, text).unwrap();
    path
}

/// Asserts `rtc check` and `rtc render` both fail with `code` at `at` (file:line:column), with a
/// help line, and that the render left the existing output alone.
fn both_refuse(dir: &Path, scene: &Path, code: &str, at: &str) -> String {
    let s = scene.to_str().unwrap();
    let check = rtc(&["check", s]);
    let out = dir.join("out.png");
    std::fs::write(&out, b"precious").unwrap();
    let render = rtc(&["render", s, "-o", out.to_str().unwrap()]);
    for (what, run) in [("check", &check), ("render", &render)] {
        let text = stderr(run);
        assert_eq!(run.status.code(), Some(1), "{what}: {text}");
        assert!(text.contains(code), "{what}: {text}");
        assert!(text.contains(&format!("{s}:{at}")), "{what}: {text}");
        assert!(text.contains("help:"), "{what}: {text}");
    }
    assert_eq!(std::fs::read(&out).unwrap(), b"precious");
    stderr(&check)
}

#[test]
fn the_image_size_follows_the_memory_the_render_needs() {
    // The rule: 24 bytes of film per pixel (twice under adaptive sampling) plus 3 of image.
    assert_eq!(image_bytes(1, 1, false), 27);
    assert_eq!(image_bytes(1, 1, true), 51);
    assert!(image_bytes(16384, 16384, false) > MAX_IMAGE_BYTES);
    assert!(image_bytes(12000, 12000, false) <= MAX_IMAGE_BYTES);
    assert!(image_bytes(12000, 12000, true) > MAX_IMAGE_BYTES);
    assert_eq!(image_bytes(u32::MAX, u32::MAX, true), u64::MAX);

    let dir = scratch("image");
    let camera = |side: u32, sampling: &str| {
        format!(
            "rtc 1\ncamera {{ eye: [0, 0, 5], center: [0, 0, 0], up: Y, resolution: [{side}, {side}] }}\n\
             render {{ supersampling: {sampling} }}\npoint_light {{ position: [5, 5, 5] }}\nsphere()\n"
        )
    };
    let huge = scene_file(&dir, &camera(16384, "1"));
    let text = both_refuse(&dir, &huge, "rtc::render::limit", "2:1");
    assert!(text.contains("render at most 12"), "{text}");

    // 12000×12000 fits on a grid, not with adaptive sampling's second pass.
    let grid = scene_file(&dir, &camera(12000, "1"));
    let run = rtc(&["check", grid.to_str().unwrap()]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    let adaptive = scene_file(&dir, &camera(12000, "adaptive(min: 1, max: 4)"));
    both_refuse(&dir, &adaptive, "rtc::render::limit", "2:1");
}

/// A PNG whose IHDR chunk claims `w`×`h` RGB pixels, followed by empty IDAT and IEND chunks.
fn png_header(w: u32, h: u32) -> Vec<u8> {
    let mut ihdr = b"IHDR".to_vec();
    ihdr.extend_from_slice(&w.to_be_bytes());
    ihdr.extend_from_slice(&h.to_be_bytes());
    ihdr.extend_from_slice(&[8, 2, 0, 0, 0]);
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    for chunk in [ihdr, b"IDAT".to_vec(), b"IEND".to_vec()] {
        png.extend_from_slice(&(chunk.len() as u32 - 4).to_be_bytes());
        png.extend_from_slice(&chunk);
        png.extend_from_slice(&crc32(&chunk).to_be_bytes());
    }
    png
}

/// CRC-32 (IEEE), as PNG chunks carry it.
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = u32::MAX;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

#[test]
fn a_texture_claiming_too_many_pixels_is_refused_before_decoding() {
    let dir = scratch("texture");
    // 9000×9000 is past 2^26 pixels; the file is 57 bytes.
    const { assert!(9000u64 * 9000 > MAX_TEXTURE_PIXELS) };
    std::fs::write(dir.join("huge.png"), png_header(9000, 9000)).unwrap();
    let scene = scene_file(
        &dir,
        "rtc 1\npoint_light { position: [5, 5, 5] }\n\
         sphere().material(material { texture: image(\"huge.png\") })\n\
         camera { eye: [0, 0, 5], center: [0, 0, 0] }\n",
    );
    let text = both_refuse(&dir, &scene, "rtc::texture::too_large", "3:");
    assert!(text.contains("9000×9000"), "{text}");
    assert!(text.contains("8192×8192"), "{text}");
}

#[test]
fn a_mesh_file_past_the_byte_budget_is_refused_before_reading() {
    let dir = scratch("mesh");
    // A sparse file: its length is past the budget, its blocks are never written.
    let big = std::fs::File::create(dir.join("big.obj")).unwrap();
    big.set_len(MAX_MESH_FILE_BYTES + 1).unwrap();
    let scene = scene_file(
        &dir,
        "rtc 1\npoint_light { position: [5, 5, 5] }\nmesh(\"big.obj\")\n\
         camera { eye: [0, 0, 5], center: [0, 0, 0] }\n",
    );
    let text = both_refuse(&dir, &scene, "rtc::mesh::too_large", "3:1");
    assert!(
        text.contains(&format!("{} bytes", MAX_MESH_FILE_BYTES + 1)),
        "{text}"
    );
    std::fs::remove_file(dir.join("big.obj")).unwrap();
}

#[test]
fn every_evaluation_budget_points_at_the_culprit_with_a_label_and_a_fix() {
    let small = EvalOptions {
        max_loop_iterations: 1000,
        max_recursion_depth: 16,
        max_objects: 50,
        max_list_len: 100,
        max_string_len: 1000,
        ..EvalOptions::default()
    };
    let cases = [
        ("rtc::budget::loop", "rtc 1\nfor i in 0..2000 { }\n"),
        (
            "rtc::budget::list",
            "rtc 1\nlet l = for i in 0..500 { i }\n",
        ),
        (
            "rtc::budget::objects",
            "rtc 1\nfor i in 0..60 { sphere() }\n",
        ),
        (
            "rtc::budget::recursion",
            "rtc 1\nfn f(n: Int) { f(n + 1) }\nf(0)\n",
        ),
        (
            "rtc::budget::string",
            "rtc 1\nfn d(s: String, n: Int) -> String { if n == 0 { s } else { d(s + s, n - 1) } }\n\
             let s = d(\"ab\", 20)\n",
        ),
    ];
    for (code, text) in cases {
        let mut sources = SourceMap::new();
        let loaded = load_source(Path::new("budget.rtc"), text, &mut sources, &small);
        let d = loaded
            .diagnostics
            .items
            .iter()
            .find(|d| d.code == code)
            .unwrap_or_else(|| panic!("{code}: {:?}", loaded.diagnostics.items));
        let span = d.span.unwrap_or_else(|| panic!("{code} has no place"));
        let (line, _) = sources.get(span.file).line_col(span.start as usize);
        assert!(line >= 2, "{code} points at line {line}");
        assert!(d.label.is_some(), "{code} has no label");
        assert!(d.help.is_some(), "{code} has no fix");
        assert!(loaded.scene.is_none(), "{code} still gave a scene");
    }
}

#[test]
fn the_time_limit_stops_the_render_and_keeps_the_old_image() {
    let dir = scratch("time");
    let scene = scene_file(
        &dir,
        "rtc 1\ncamera { eye: [0, 0, 5], center: [0, 0, 0], up: Y, resolution: [64, 48] }\n\
         point_light { position: [5, 5, 5] }\nsphere()\n",
    );
    let s = scene.to_str().unwrap();
    let out = dir.join("out.png");
    std::fs::write(&out, b"precious").unwrap();
    let o = out.to_str().unwrap();
    // A limit of 0 s has passed before the first band of rows: the render always stops.
    let run = rtc(&["render", s, "-o", o, "--time-limit", "0"]);
    let text = stderr(&run);
    assert_eq!(run.status.code(), Some(1), "{text}");
    assert!(text.contains("rtc::render::time_limit"), "{text}");
    assert!(text.contains(&format!("{s}:2:1")), "{text}");
    assert!(text.contains("64×48"), "{text}");
    assert!(text.contains("--time-limit"), "{text}");
    assert_eq!(std::fs::read(&out).unwrap(), b"precious");
    let leftovers = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().ends_with(".tmp"))
        .count();
    assert_eq!(leftovers, 0, "temporary files left behind");

    // A generous limit changes nothing.
    let run = rtc(&["render", s, "-o", o, "--time-limit", "600"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    assert!(std::fs::read(&out).unwrap().starts_with(b"\x89PNG"));

    // A limit that is not a number of seconds is a usage error.
    for bad in ["-1", "soon", "inf"] {
        let run = rtc(&["render", s, "-o", o, "--time-limit", bad]);
        assert_eq!(run.status.code(), Some(2), "{bad}: {}", stderr(&run));
    }
}

/// Calls count against the loop budget as loop iterations do: a recursion that branches into
/// two calls at every level stays within the depth budget and would run for ever otherwise.
#[test]
fn a_branching_recursion_meets_the_loop_budget() {
    let small = EvalOptions {
        max_loop_iterations: 10_000,
        ..EvalOptions::default()
    };
    let text = "rtc 1\nfn f(n: Int) -> Int { if n == 0 { 1 } else { f(n - 1) + f(n - 1) } }\nlet x = f(60)\n";
    let mut sources = SourceMap::new();
    let loaded = load_source(Path::new("doubling.rtc"), text, &mut sources, &small);
    let d = loaded
        .diagnostics
        .items
        .iter()
        .find(|d| d.code == "rtc::budget::loop")
        .unwrap_or_else(|| panic!("{:?}", loaded.diagnostics.items));
    assert!(
        d.label.as_deref().is_some_and(|l| l.contains("calls")),
        "{d:?}"
    );
}

/// `--time-limit` covers the evaluation too: a scene still evaluating when the time is up
/// stops there, at the loop, instead of evaluating to the end and stopping at the first band
/// of rows.
#[test]
fn the_time_limit_stops_a_long_evaluation_where_it_is() {
    let dir = scratch("time-eval");
    let scene = scene_file(
        &dir,
        "rtc 1\ncamera { eye: [0, 0, 5], center: [0, 0, 0], up: Y, resolution: [8, 6] }\n\
         point_light { position: [5, 5, 5] }\nfor i in 0..40000000 { }\nsphere()\n",
    );
    let s = scene.to_str().unwrap();
    let out = dir.join("out.png");
    let run = rtc(&[
        "render",
        s,
        "-o",
        out.to_str().unwrap(),
        "--time-limit",
        "0.2",
    ]);
    let text = stderr(&run);
    assert_eq!(run.status.code(), Some(1), "{text}");
    assert!(text.contains("rtc::render::time_limit"), "{text}");
    assert!(text.contains(&format!("{s}:4:")), "at the loop: {text}");
    assert!(!out.exists());
}
