//! The command line as a user meets it: exit codes, output naming, no clobbering, `--stats`.

mod cli_support;

use std::path::Path;

use cli_support::{rtc, scratch};

#[test]
fn unknown_extension_and_missing_file_are_io_errors() {
    assert_eq!(rtc(&["check", "Cargo.toml"]).status.code(), Some(2));
    assert_eq!(rtc(&["check", "no/such/scene.rtc"]).status.code(), Some(2));
    assert_eq!(
        rtc(&["render", "no/such/scene.yaml"]).status.code(),
        Some(2)
    );
    assert_eq!(rtc(&["check"]).status.code(), Some(2), "usage error");
}

#[test]
fn a_failed_render_leaves_an_existing_image_alone() {
    let dir = scratch("clobber");
    let scene = dir.join("bad.rtc");
    std::fs::write(&scene, "rtc 1\nsphere(center: [0, 0, 0], radius: -1)\n").unwrap();
    let out = dir.join("bad.png");
    std::fs::write(&out, b"precious").unwrap();
    let run = rtc(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(
        run.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert_eq!(std::fs::read(&out).unwrap(), b"precious");
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().ends_with(".tmp"))
        .collect();
    assert!(leftovers.is_empty(), "temporary files left behind");
}

#[test]
fn unknown_output_format_is_refused_without_writing() {
    let dir = scratch("format");
    let out = dir.join("scene.gif");
    let run = rtc(&[
        "render",
        "tests/data/course/yaml/scene01.yaml",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(2));
    assert!(!Path::new(&out).exists());
    assert!(String::from_utf8_lossy(&run.stderr).contains("*.png"));
}

#[test]
fn render_writes_ppm_and_reports_stats() {
    let dir = scratch("ppm");
    let out = dir.join("scene01.ppm");
    let run = rtc(&[
        "render",
        "tests/data/course/in/rt1.in",
        "-o",
        out.to_str().unwrap(),
        "--stats",
        "--threads",
        "1",
    ]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(0), "{stderr}");
    // 400×400 course image: one camera ray per pixel, no supersampling in rt1.
    assert!(stderr.contains("160000 camera"), "{stderr}");
    assert!(stderr.contains("first ray at"), "{stderr}");
    let bytes = std::fs::read(&out).unwrap();
    let header = b"P6\n400 400\n255\n";
    assert_eq!(&bytes[..header.len()], header);
    assert_eq!(bytes.len(), header.len() + 400 * 400 * 3);
}

#[test]
fn deny_warnings_turns_a_warning_into_failure() {
    let dir = scratch("deny");
    let scene = dir.join("dark.rtc");
    std::fs::write(
        &scene,
        "rtc 1\ncamera { eye: [0, 0, 5], center: [0, 0, 0] }\nsphere(center: [0, 0, 0], radius: 1)\n",
    )
    .unwrap();
    let path = scene.to_str().unwrap();
    let plain = rtc(&["check", path, "--format", "short"]);
    let text = String::from_utf8_lossy(&plain.stderr);
    assert_eq!(plain.status.code(), Some(0), "{text}");
    assert!(text.contains("rtc::scene::no_lights"), "{text}");
    assert_eq!(
        rtc(&["check", path, "--deny", "warnings"]).status.code(),
        Some(1)
    );
}

#[test]
fn diagnostics_go_to_stderr_and_json_to_stdout() {
    let dir = scratch("streams");
    let scene = dir.join("bad.rtc");
    std::fs::write(&scene, "rtc 1\nsphere(radius: -1)\n").unwrap();
    let path = scene.to_str().unwrap();
    for format in ["human", "short"] {
        let run = rtc(&["check", path, "--format", format]);
        assert_eq!(run.status.code(), Some(1));
        assert!(run.stdout.is_empty(), "{format}: stdout must stay empty");
        let err = String::from_utf8_lossy(&run.stderr);
        assert!(err.contains("rtc::param::out_of_range"), "{format}: {err}");
    }
    let run = rtc(&["check", path, "--format", "json"]);
    assert_eq!(run.status.code(), Some(1));
    assert!(run.stderr.is_empty(), "json: stderr must stay empty");
    let doc: serde_json::Value = serde_json::from_slice(&run.stdout).expect("JSON on stdout");
    assert_eq!(doc["diagnostics"][0]["code"], "rtc::param::out_of_range");
    assert_eq!(doc["ok"], false);
}

#[test]
fn a_library_module_is_checked_as_a_library() {
    let run = rtc(&["check", "stdlib/materials.rtc"]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains("ok: library module exporting"), "{stderr}");
    assert!(
        !stderr.contains("camera"),
        "no missing-camera error: {stderr}"
    );
    // A library that emits is reported as an import would see it.
    let dir = scratch("library");
    let lib = dir.join("lib.rtc");
    std::fs::write(
        &lib,
        "rtc 1\npub fn ball() { sphere() }\npub let bad: Int = \"x\"\n",
    )
    .unwrap();
    let run = rtc(&["check", lib.to_str().unwrap(), "--format", "short"]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("lib.rtc:3:"),
        "the error is located: {stderr}"
    );
    assert!(!stderr.contains("camera"), "{stderr}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_directory_is_checked_file_by_file_with_one_summary() {
    let dir = scratch("dir");
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    std::fs::write(dir.join("lib.rtc"), "rtc 1\npub let r = 1\n").unwrap();
    std::fs::write(
        dir.join("sub/scene.rtc"),
        "rtc 1\ncamera { eye: [0, 0, 5], center: [0, 0, 0] }\npoint_light { position: [0, 5, 5] }\nsphere()\n",
    )
    .unwrap();
    std::fs::write(dir.join("sub/broken.rtc"), "rtc 1\nsphere(radius: )\n").unwrap();
    std::fs::write(dir.join("notes.txt"), "not a scene").unwrap();
    let run = rtc(&["check", dir.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("checked 3 files below") && stderr.contains("2 ok (1 library), 1 failed"),
        "{stderr}"
    );
    assert!(stderr.contains("broken.rtc: 1 error"), "{stderr}");
    let json = rtc(&["check", dir.to_str().unwrap(), "--format", "json"]);
    let doc: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    assert_eq!(doc["files"].as_array().map(Vec::len), Some(3));
    assert_eq!(doc["ok"], false);
    std::fs::remove_file(dir.join("sub/broken.rtc")).unwrap();
    assert_eq!(
        rtc(&["check", dir.to_str().unwrap()]).status.code(),
        Some(0)
    );
}
