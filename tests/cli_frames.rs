//! Animation and parameters on the command line: `--frame`, `--frames`, `--fps`, `--set`.

use std::path::PathBuf;
use std::process::{Command, Output};

fn rtc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the rtc binary runs")
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rtc-frames-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

const BALL: &str = "rtc 1.1
param size = 1.0
camera { eye: [0, 0, 10], center: [0, 0, 0], resolution: [40, 24] }
point_light { position: [5, 5, 10] }
sphere(radius: size).translate([frame * 0.4 - 1 + time, 0, 0])
";

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn frame_n_of_frames_equals_frame_n() {
    let dir = scratch("equal");
    let scene = dir.join("ball.rtc");
    std::fs::write(&scene, BALL).unwrap();
    let pattern = dir.join("f_####.png");
    let run = rtc(&[
        "render",
        scene.to_str().unwrap(),
        "--frames",
        "0..=4:2",
        "-o",
        pattern.to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    let single = dir.join("single.png");
    let run = rtc(&[
        "render",
        scene.to_str().unwrap(),
        "--frame",
        "2",
        "-o",
        single.to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    let f2 = std::fs::read(dir.join("f_0002.png")).unwrap();
    assert_eq!(f2, std::fs::read(&single).unwrap());
    let f0 = std::fs::read(dir.join("f_0000.png")).unwrap();
    assert_ne!(f0, f2, "the ball moves between frames");
    assert!(dir.join("f_0004.png").exists());
    assert!(!dir.join("f_0001.png").exists(), "the step skips frame 1");
    // `{frame}` numbers without padding; the default name is the scene's with `_####`.
    let run = rtc(&["render", scene.to_str().unwrap(), "--frames", "1..2"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    assert!(dir.join("ball_0001.png").exists());
}

#[test]
fn frames_need_a_numbered_output_and_a_valid_range() {
    let dir = scratch("usage");
    let scene = dir.join("ball.rtc");
    std::fs::write(&scene, BALL).unwrap();
    let out = dir.join("one.png");
    let run = rtc(&[
        "render",
        scene.to_str().unwrap(),
        "--frames",
        "0..3",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(2));
    assert!(stderr(&run).contains("####"), "{}", stderr(&run));
    assert!(!out.exists());
    let run = rtc(&["render", scene.to_str().unwrap(), "--frames", "5..2"]);
    assert_eq!(run.status.code(), Some(2));
    let run = rtc(&["render", scene.to_str().unwrap(), "--fps", "0"]);
    assert_eq!(run.status.code(), Some(2));
}

#[test]
fn fps_sets_time() {
    let dir = scratch("fps");
    let scene = dir.join("t.rtc");
    std::fs::write(
        &scene,
        "rtc 1.1\nassert(time == frame / 24)\ncamera { eye: [0, 0, 5] }\n",
    )
    .unwrap();
    let run = rtc(&["check", scene.to_str().unwrap(), "--frame", "12"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    std::fs::write(
        &scene,
        "rtc 1.1\nassert(time == 0.5)\ncamera { eye: [0, 0, 5] }\n",
    )
    .unwrap();
    let run = rtc(&[
        "check",
        scene.to_str().unwrap(),
        "--frame",
        "15",
        "--fps",
        "30",
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
}

#[test]
fn set_overrides_a_param_and_refuses_unknown_names() {
    let dir = scratch("set");
    let scene = dir.join("ball.rtc");
    std::fs::write(&scene, BALL).unwrap();
    let small = dir.join("small.png");
    let big = dir.join("big.png");
    let run = rtc(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        small.to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    let run = rtc(&[
        "render",
        scene.to_str().unwrap(),
        "--set",
        "size=2",
        "-o",
        big.to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    assert_ne!(std::fs::read(&small).unwrap(), std::fs::read(&big).unwrap());
    // `-D` is the same option; the override equals writing the value in the file.
    let edited = dir.join("edited.rtc");
    std::fs::write(
        &edited,
        BALL.replace("param size = 1.0", "param size = 2.0"),
    )
    .unwrap();
    let same = dir.join("same.png");
    let run = rtc(&[
        "render",
        edited.to_str().unwrap(),
        "-o",
        same.to_str().unwrap(),
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    assert_eq!(std::fs::read(&same).unwrap(), std::fs::read(&big).unwrap());
    let run = rtc(&["check", scene.to_str().unwrap(), "-D", "size=2"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));

    let run = rtc(&["check", scene.to_str().unwrap(), "--set", "sise=2"]);
    assert_eq!(run.status.code(), Some(1));
    let err = stderr(&run);
    assert!(
        err.contains("rtc::param::unknown") && err.contains("`size`"),
        "{err}"
    );
    let run = rtc(&["check", scene.to_str().unwrap(), "--set", "size=\"big\""]);
    assert_eq!(run.status.code(), Some(1));
    assert!(
        stderr(&run).contains("rtc::param::type"),
        "{}",
        stderr(&run)
    );
    let run = rtc(&["check", scene.to_str().unwrap(), "--set", "size"]);
    assert_eq!(run.status.code(), Some(2));
}

/// Issue 34: `--set label=spiral` for a `String` parameter says the value needs quotes (a bare
/// word was read as a name, and the help offered an import), and the quoted form works.
#[test]
fn a_bare_word_for_a_string_parameter_needs_quotes() {
    let dir = scratch("set-string");
    let scene = dir.join("label.rtc");
    std::fs::write(
        &scene,
        "rtc 1.1\nparam label = \"grid\"\ncamera { eye: [0, 0, 5] }\npoint_light { position: [2, 5, 5] }\nsphere(radius: 1)\nprint(label)\n",
    )
    .unwrap();
    let run = rtc(&["check", scene.to_str().unwrap(), "--set", "label=spiral"]);
    assert_eq!(run.status.code(), Some(1));
    let err = stderr(&run);
    assert!(
        err.contains("rtc::param::unquoted")
            && err.contains("a `String` value needs quotes")
            && err.contains("--set label='\"spiral\"'")
            && !err.contains("import"),
        "{err}"
    );
    let run = rtc(&[
        "check",
        scene.to_str().unwrap(),
        "--set",
        "label=\"spiral\"",
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
}
