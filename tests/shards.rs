//! Sharded renders merge back into the single render byte for byte (issue 15), for any number
//! of shards, on scenes whose pixels depend on randomness (area lights, a lens) and on their
//! neighbours (adaptive supersampling); `rtc merge` refuses missing, duplicated and foreign parts.
//! The golden image here is the single-process render itself: the rule is "merged = single".

use std::path::{Path, PathBuf};
use std::process::Command;

use rtc::eval::{EvalOptions, load_source};
use rtc::ir::Scene;
use rtc::opt::fingerprint;
use rtc::render::merge::merge;
use rtc::render::part::Part;
use rtc::render::shard::Shard;
use rtc::render::{RenderOptions, render_scene};
use rtc::source::SourceMap;

/// A small scene with every neighbour- and randomness-dependent feature: an area light, a
/// lens, and the given sampling.
fn scene(sampling: &str) -> Scene {
    let text = format!(
        r#"rtc 1
camera {{ eye: [0, 2, 6], center: [0, 0.5, 0], fov: 40deg, resolution: [53, 41], aperture: 0.08, focus: 6 }}
render {{ supersampling: {sampling}, max_depth: 2, flare: flare }}
area_light {{ corner: [-1, 5, -1], u: [2, 0, 0], v: [0, 0, 2], samples: 2 }}
point_light {{ position: [3, 4, 5], color: rgb(0.3, 0.3, 0.3) }}
plane(point: [0, 0, 0], normal: Y).material(material {{ color: rgb(0.8, 0.8, 0.8), reflect: 0.2 }})
sphere(center: [0, 0.6, 0], radius: 0.6).material(material {{ color: rgb(0.9, 0.2, 0.2) }})
sphere(center: [1.2, 0.3, 1], radius: 0.3).material(material {{ color: rgb(0.2, 0.3, 0.9), reflect: 0.5 }})
"#
    );
    let mut sources = SourceMap::new();
    let loaded = load_source(
        Path::new("shards.rtc"),
        &text,
        &mut sources,
        &EvalOptions::default(),
    );
    assert!(!loaded.diagnostics.has_errors(), "{:?}", loaded.diagnostics);
    loaded.scene.expect("scene")
}

fn opts(shard: Option<Shard>) -> RenderOptions {
    RenderOptions {
        threads: 2,
        shard,
        ..Default::default()
    }
}

/// Every shard of `n`, through the part file format and back.
fn parts(scene: &Scene, n: u32) -> Vec<(PathBuf, Part)> {
    let fp = fingerprint::scene(scene);
    (0..n)
        .map(|k| {
            let s = Shard::new(k, n).unwrap();
            let film = render_scene(scene, &opts(Some(s))).expect("shard renders");
            let bytes = Part::of_film(&film, s, fp.clone(), "settings".into()).to_bytes();
            let path = PathBuf::from(format!("p{k}"));
            let part = Part::from_bytes(&bytes, &path).expect("part reads back");
            (path, part)
        })
        .collect()
}

#[test]
fn merged_shards_equal_the_single_render_for_grid_and_adaptive_sampling() {
    for sampling in ["2", "adaptive(min: 1, max: 3, threshold: 0.02)"] {
        let scene = scene(sampling);
        let single = render_scene(&scene, &opts(None)).unwrap().to_image();
        for n in [1, 2, 3, 7, 16] {
            let merged = merge(&parts(&scene, n)).expect("merges").to_image();
            assert!(
                merged.as_raw() == single.as_raw(),
                "{sampling}, {n} shards: merged differs from the single render"
            );
        }
    }
}

#[test]
fn merge_refuses_missing_duplicate_and_foreign_parts() {
    let scene = scene("1");
    let mut three = parts(&scene, 3);
    let mut missing = three.clone();
    missing.remove(1);
    let e = merge(&missing).unwrap_err();
    assert_eq!(e.code, "rtc::merge::missing");
    assert!(
        e.message.contains("1 of 3 shards missing: 1"),
        "{}",
        e.message
    );

    let mut duplicate = three.clone();
    duplicate[2] = duplicate[0].clone();
    assert_eq!(merge(&duplicate).unwrap_err().code, "rtc::merge::overlap");

    let edited = self::scene("2");
    let other = parts(&edited, 3);
    three[1] = other[1].clone();
    let e = merge(&three).unwrap_err();
    assert_eq!(e.code, "rtc::merge::mismatch");
    assert!(e.message.contains("different scenes"), "{}", e.message);

    let cut_in_two = parts(&scene, 2);
    let mut mixed = parts(&scene, 3);
    mixed[0] = cut_in_two[0].clone();
    assert_eq!(merge(&mixed).unwrap_err().code, "rtc::merge::mismatch");
}

#[test]
fn a_damaged_part_is_refused() {
    let scene = scene("1");
    let s = Shard::new(0, 2).unwrap();
    let film = render_scene(&scene, &opts(Some(s))).unwrap();
    let bytes = Part::of_film(&film, s, "a".into(), "b".into()).to_bytes();
    let p = Path::new("x.rtcpart");
    let truncated = &bytes[..bytes.len() - 5];
    assert_eq!(
        Part::from_bytes(truncated, p).unwrap_err().code,
        "rtc::merge::malformed"
    );
    let mut flipped = bytes.clone();
    let last = flipped.len() - 1;
    flipped[last] ^= 1;
    assert_eq!(
        Part::from_bytes(&flipped, p).unwrap_err().code,
        "rtc::merge::malformed"
    );
    assert_eq!(
        Part::from_bytes(b"PNG", p).unwrap_err().code,
        "rtc::merge::malformed"
    );
}

fn rtc() -> Command {
    Command::new(env!("CARGO_BIN_EXE_rtc"))
}

/// The command line end to end: `--shard auto` under both schedulers' variables, `rtc merge`,
/// and a part of an edited scene refused with exit 1.
#[test]
fn the_command_line_shards_from_the_environment_and_merges() {
    let dir = std::env::temp_dir().join(format!("rtc-shards-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene_file = dir.join("s.rtc");
    let text = r#"rtc 1
camera { eye: [0, 1, 4], center: [0, 0, 0], resolution: [24, 40] }
point_light { position: [2, 3, 4] }
sphere(radius: 1).material(material { color: rgb(0.7, 0.5, 0.2) })
"#;
    std::fs::write(&scene_file, text).unwrap();
    let single = dir.join("single.png");
    assert!(
        rtc()
            .arg("render")
            .arg(&scene_file)
            .arg("-o")
            .arg(&single)
            .status()
            .unwrap()
            .success()
    );
    // Slurm: ids 4..=6 (min 4, count 3); Kubernetes: index 2 with --shards 3.
    let p = |k: u32| dir.join(format!("p{k}.rtcpart"));
    for (k, env) in [
        (
            0,
            vec![
                ("SLURM_ARRAY_TASK_ID", "4"),
                ("SLURM_ARRAY_TASK_MIN", "4"),
                ("SLURM_ARRAY_TASK_COUNT", "3"),
            ],
        ),
        (
            1,
            vec![
                ("SLURM_ARRAY_TASK_ID", "5"),
                ("SLURM_ARRAY_TASK_MIN", "4"),
                ("SLURM_ARRAY_TASK_COUNT", "3"),
            ],
        ),
        (2, vec![("JOB_COMPLETION_INDEX", "2")]),
    ] {
        let mut c = rtc();
        c.arg("render")
            .arg(&scene_file)
            .args(["--shard", "auto", "--shards", "3", "-o"])
            .arg(p(k));
        c.env_remove("SLURM_ARRAY_TASK_ID")
            .env_remove("JOB_COMPLETION_INDEX");
        for (key, v) in env {
            c.env(key, v);
        }
        let out = c.output().unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let merged = dir.join("merged.png");
    let out = rtc()
        .arg("merge")
        .args([p(2), p(0), p(1)])
        .arg("-o")
        .arg(&merged)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(
        std::fs::read(&single).unwrap(),
        std::fs::read(&merged).unwrap()
    );

    // Edit the scene, re-render shard 1 only: merge refuses and keeps the old image.
    std::fs::write(&scene_file, text.replace("0.7, 0.5", "0.2, 0.5")).unwrap();
    let out = rtc()
        .arg("render")
        .arg(&scene_file)
        .args(["--shard", "1/3", "-o"])
        .arg(p(1))
        .output()
        .unwrap();
    assert!(out.status.success());
    let before = std::fs::read(&merged).unwrap();
    let out = rtc()
        .arg("merge")
        .args([p(0), p(1), p(2)])
        .arg("-o")
        .arg(&merged)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("rtc::merge::mismatch") && err.contains("scenes"),
        "{err}"
    );
    assert_eq!(
        std::fs::read(&merged).unwrap(),
        before,
        "a refused merge writes nothing"
    );

    // A shard that does not exist is a usage error (exit 2).
    let out = rtc()
        .arg("render")
        .arg(&scene_file)
        .args(["--shard", "3/3"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&dir);
}

/// The documented recipes say what the code reads: the Kubernetes Indexed Job passes
/// `--shard auto` with `--shards` equal to its completions (Kubernetes exports no count) and a
/// per-index part name; the Slurm array script uses `--shard auto`. (No cluster is reachable
/// here for Kubernetes: this checks the manifest's structure; tests/slurm/run.sh runs Slurm.)
#[test]
fn the_scheduler_recipes_match_the_command_line() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/examples");
    let text = std::fs::read_to_string(root.join("kubernetes/render-indexed-job.yaml")).unwrap();
    let job: serde_json::Value = serde_saphyr::from_str(&text).expect("the manifest is YAML");
    assert_eq!(job["apiVersion"], "batch/v1");
    assert_eq!(job["kind"], "Job");
    let spec = &job["spec"];
    assert_eq!(spec["completionMode"], "Indexed");
    let completions = spec["completions"].as_u64().expect("completions");
    let pod = &spec["template"]["spec"];
    assert_eq!(pod["restartPolicy"], "Never");
    let args: Vec<&str> = pod["containers"][0]["args"]
        .as_array()
        .expect("args")
        .iter()
        .filter_map(|a| a.as_str())
        .collect();
    let after = |flag: &str| args.iter().position(|a| *a == flag).map(|i| args[i + 1]);
    assert_eq!(args[0], "render");
    assert_eq!(after("--shard"), Some("auto"));
    assert_eq!(after("--shards"), Some(completions.to_string().as_str()));
    assert!(after("-o").unwrap().contains("$(JOB_COMPLETION_INDEX)"));
    let env = &pod["containers"][0]["env"][0];
    assert_eq!(env["name"], "JOB_COMPLETION_INDEX");
    let containerfile = std::fs::read_to_string(root.join("kubernetes/Containerfile")).unwrap();
    assert!(containerfile.contains("cargo build --release --locked"));
    assert!(containerfile.contains("ENTRYPOINT [\"/usr/local/bin/rtc\"]"));
    let slurm = std::fs::read_to_string(root.join("slurm/render-array.sh")).unwrap();
    assert!(slurm.contains("--shard auto") && slurm.contains("SLURM_ARRAY_TASK_ID"));
}
