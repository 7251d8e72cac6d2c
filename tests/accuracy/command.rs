//! `rtc accuracy` run as a command: a region sweep, the files it writes, the JSON report against
//! the hand-written tests/data/accuracy/report-shape.json, and a bad reference.

use std::process::Command;

use super::{AREA_LIT, GLOSSY, MIDDLE, POINT_LIT, scratch, write_scene};

#[test]
fn the_command_sweeps_a_region_and_says_so() {
    let dir = scratch("region-cli");
    let scene = write_scene(&dir, GLOSSY);
    let run = |region: &str| {
        Command::new(env!("CARGO_BIN_EXE_rtc"))
            .args([
                "accuracy",
                scene.to_str().unwrap(),
                "--no-joint",
                "--no-cache",
            ])
            .args(["--region", region, "--scale", "0.5", "--format", "json"])
            .arg("--out-dir")
            .arg(dir.join("out"))
            .output()
            .unwrap()
    };
    let ok = run(MIDDLE);
    let stderr = String::from_utf8_lossy(&ok.stderr);
    assert_eq!(ok.status.code(), Some(0), "{stderr}");
    let json: serde_json::Value = serde_json::from_slice(&ok.stdout).unwrap();
    // 12,6,8,8 at scale 0.5 of 32×24: 6,3,4,4 of 16×12.
    assert_eq!(
        json["size"]["region"],
        serde_json::json!({"x": 6, "y": 3, "width": 4, "height": 4})
    );
    assert_eq!(json["size"]["width"], 16);
    // The predicted full time scales by the full image's pixels over the region's (48).
    let p = &json["points"][0];
    let ratio = p["predicted_full_seconds"].as_f64().unwrap() / p["seconds"].as_f64().unwrap();
    assert!((ratio - 48.0).abs() < 1e-9, "{ratio}");

    let bad = run("30,20,4,8");
    let stderr = String::from_utf8_lossy(&bad.stderr);
    assert_eq!(bad.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("rtc::render::region"), "{stderr}");
    assert!(stderr.contains("does not fit the 32×24 image"), "{stderr}");
    let garbled = run("30x20");
    assert_eq!(garbled.status.code(), Some(2), "clap's usage error");
    assert!(String::from_utf8_lossy(&garbled.stderr).contains("X,Y,W,H"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Whether `value` has the shape `shape` (report-shape.json's notation: a string names the
/// allowed JSON types joined by `|`, an object lists exactly the keys, an array's one element
/// is every element's shape).
fn matches_shape(
    value: &serde_json::Value,
    shape: &serde_json::Value,
    at: &str,
) -> Result<(), String> {
    use serde_json::Value;
    match shape {
        Value::String(types) => {
            let kind = match value {
                Value::Null => "null",
                Value::Bool(_) => "bool",
                Value::Number(_) => "number",
                Value::String(_) => "string",
                Value::Array(_) => "array",
                Value::Object(_) => "object",
            };
            if types.split('|').any(|t| t == kind) {
                Ok(())
            } else {
                Err(format!("{at}: a {kind}, the schema says {types}"))
            }
        }
        // `{"$one_of": [A, B, ...]}`: the value has one of the shapes (a setting's sampling is
        // a grid or adaptive).
        Value::Object(fields) if fields.contains_key("$one_of") => {
            let alternatives = fields["$one_of"].as_array().map_or(&[][..], Vec::as_slice);
            if alternatives
                .iter()
                .any(|s| matches_shape(value, s, at).is_ok())
            {
                Ok(())
            } else {
                Err(format!(
                    "{at}: {value} has none of the shapes {alternatives:?}"
                ))
            }
        }
        Value::Object(fields) => {
            let Value::Object(got) = value else {
                return Err(format!("{at}: not an object"));
            };
            let want: Vec<&String> = fields.keys().collect();
            let have: Vec<&String> = got.keys().collect();
            if want != have {
                return Err(format!("{at}: keys {have:?}, the schema says {want:?}"));
            }
            for (k, s) in fields {
                matches_shape(&got[k], s, &format!("{at}.{k}"))?;
            }
            Ok(())
        }
        Value::Array(one) => {
            let Value::Array(items) = value else {
                return Err(format!("{at}: not an array"));
            };
            if items.is_empty() {
                return Err(format!("{at}: empty, so its shape is not checked"));
            }
            items
                .iter()
                .enumerate()
                .try_for_each(|(i, v)| matches_shape(v, &one[0], &format!("{at}[{i}]")))
        }
        _ => Err(format!("{at}: the schema file has a {shape}")),
    }
}

#[test]
fn the_command_writes_the_report_the_plot_and_the_map_and_json_has_the_documented_shape() {
    let dir = scratch("cli");
    let scene = write_scene(&dir, AREA_LIT);
    let out = dir.join("out");
    let accuracy = |extra: &[&str]| {
        let run = Command::new(env!("CARGO_BIN_EXE_rtc"))
            .args(["accuracy", scene.to_str().unwrap(), "--no-joint"])
            .args(["--threads", "2"])
            .args(extra)
            .arg("--out-dir")
            .arg(&out)
            .env("RTC_CACHE_DIR", dir.join("cache"))
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&run.stderr).into_owned();
        assert_eq!(run.status.code(), Some(0), "{stderr}");
        String::from_utf8_lossy(&run.stdout).into_owned()
    };
    // The first run renders and caches the reference and prints the table.
    let text = accuracy(&[]);
    assert!(text.contains("swept at 40×30\n"), "{text}");
    assert!(
        text.contains("light samples") && text.contains('*'),
        "{text}"
    );
    // One EXR per seed, each with its checksum file.
    let cached: Vec<String> = std::fs::read_dir(dir.join("cache"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(
        cached.iter().filter(|n| n.ends_with(".exr")).count(),
        2,
        "{cached:?}"
    );
    assert_eq!(
        cached.iter().filter(|n| n.ends_with(".exr.sha256")).count(),
        2,
        "{cached:?}"
    );
    // The second reads the cache (so `reference.files` is not empty) and prints JSON.
    let json = accuracy(&["--format", "json", "--target-error", "1", "--time", "1h"]);
    let doc: serde_json::Value = serde_json::from_str(&json).expect("JSON on stdout");
    let shape: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string("tests/data/accuracy/report-shape.json").unwrap(),
    )
    .unwrap();
    matches_shape(&doc, &shape, "$").unwrap();
    assert_eq!(doc["schema"], "rtc-accuracy/1");
    assert_eq!(doc["reference"]["source"], "cache");
    let on_disk: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap();
    assert_eq!(on_disk, doc);
    // Both goals are met by some point: every point is within an error of 1 and an hour.
    for r in doc["recommendations"].as_array().unwrap() {
        let block = r["render_block"].as_str().unwrap();
        assert!(block.starts_with("render { supersampling: "), "{block}");
    }
    let svg = std::fs::read_to_string(out.join("plot.svg")).unwrap();
    assert!(svg.contains("light samples"), "one curve per knob");
    assert!(
        svg.contains("scene&apos;s setting (grid 1, depth 0)"),
        "the scene's own setting"
    );
    let map = image::open(out.join("flip-map.png")).unwrap();
    assert_eq!((map.width(), map.height()), (40, 30));
    // A reduced size is reported.
    let half = accuracy(&["--scale", "0.5"]);
    assert!(
        half.contains("swept at 20×15 (scale 0.500 of 40×30)"),
        "{half}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_reference_of_the_wrong_size_is_a_clear_error() {
    let dir = scratch("badref");
    let scene = write_scene(&dir, POINT_LIT);
    let png = dir.join("small.png");
    image::RgbImage::new(4, 4).save(&png).unwrap();
    let run = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["accuracy", scene.to_str().unwrap(), "--reference"])
        .arg(&png)
        .arg("--out-dir")
        .arg(dir.join("out"))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("rtc::accuracy::reference_size"), "{stderr}");
    assert!(stderr.contains("40×30"), "{stderr}");
    let _ = std::fs::remove_dir_all(&dir);
}
