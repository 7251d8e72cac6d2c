//! Hostile inputs (issue 35), what rtc writes and serves: temporary files, files formatted in
//! place, the output of a render, merged parts, the accuracy cache, the watch server. No case
//! may write where it should not or trust what it reads back. What rtc reads is in
//! `hostile.rs`.

mod hostile_support;

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Duration;

use hostile_support::*;

use rtc::eval::{EvalOptions, load_source};
use rtc::source::SourceMap;

// ---- 6. the temporary file of an atomic write ------------------------------------------------

/// A symlink planted at the name the old temporary file had (`.NAME.PID.tmp`, PID this
/// process) to a victim file: the write goes to a fresh file of a random name, created
/// exclusively, and the victim is untouched.
#[cfg(unix)]
#[test]
fn a_planted_symlink_at_a_temporary_name_is_never_followed() {
    let dir = scratch("temp-symlink");
    let victim = write(&dir.join("victim.txt"), "precious");
    let planted = dir.join(format!(".out.png.{}.tmp", std::process::id()));
    symlink(victim.to_str().unwrap(), &planted);
    let out = dir.join("out.png");
    for _ in 0..3 {
        rtc::render::output::write_atomically(&out, b"image bytes").unwrap();
    }
    assert_eq!(std::fs::read(&victim).unwrap(), b"precious");
    assert_eq!(std::fs::read(&out).unwrap(), b"image bytes");
    // Only the output, the victim and the planted link: no temporary file left behind.
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names.len(), 3, "{names:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 14. a signal during a write ------------------------------------------------------------

/// `rtc render -o out.png` in `dir` with `env`, its output streams closed.
fn spawn_render(dir: &Path, args: &[&str], env: &[(&str, &str)]) -> std::process::Child {
    Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["render", "s.rtc", "-o", "out.png"])
        .args(args)
        .envs(env.iter().copied())
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap()
}

/// SIGTERM, SIGINT or SIGHUP while the image's temporary file exists and is not yet renamed
/// (held open by `RTC_TEST_WRITE_PAUSE_MS`): the process ends with 130, the temporary file is
/// removed and the existing image is untouched. Before, the signal ended the process without
/// destructors and `tempfile` never removed `.out.png.XXXXXX.tmp`.
#[cfg(unix)]
#[test]
fn a_signal_between_the_temporary_file_and_the_rename_leaves_no_file() {
    let dir = scratch("signal-in-write");
    write(&dir.join("s.rtc"), SCENE);
    let out = write(&dir.join("out.png"), "the old image");
    let pause = [(rtc::render::output::WRITE_PAUSE_VAR, "60000")];
    for name in ["TERM", "INT", "HUP"] {
        let mut child = spawn_render(&dir, &[], &pause);
        let start = std::time::Instant::now();
        while !dot_files(&dir).iter().any(|n| n.starts_with(".out.png.")) {
            assert!(
                start.elapsed() < Duration::from_secs(60),
                "no temporary file appeared"
            );
            std::thread::sleep(Duration::from_millis(5));
        }
        signal(child.id(), name);
        let status = wait_guarded(&mut child);
        assert_eq!(status.code(), Some(130), "SIG{name}: {status:?}");
        assert_eq!(dot_files(&dir), Vec::<String>::new(), "SIG{name}");
        assert_eq!(std::fs::read(&out).unwrap(), b"the old image", "SIG{name}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// SIGTERM at several moments of a render that takes a while: never a temporary file left, and
/// the old image is either untouched or (the render won the race) replaced by a whole new one.
#[cfg(unix)]
#[test]
fn a_signal_at_any_moment_of_a_render_leaves_no_temporary_file() {
    let dir = scratch("signal-any-moment");
    let slow = SCENE.replace("[8, 6]", "[600, 400]") + "render { supersampling: 8 }\n";
    write(&dir.join("s.rtc"), &slow);
    let out = write(&dir.join("out.png"), "the old image");
    for after_ms in [0, 30, 100, 300, 1000, 3000] {
        std::fs::write(&out, "the old image").unwrap();
        let mut child = spawn_render(&dir, &["--threads", "1"], &[]);
        std::thread::sleep(Duration::from_millis(after_ms));
        // The process may have ended already; kill(1) then fails, which is no defect.
        let _ = Command::new("kill")
            .args(["-TERM", &child.id().to_string()])
            .status();
        let status = wait_guarded(&mut child);
        assert_eq!(dot_files(&dir), Vec::<String>::new(), "after {after_ms} ms");
        let bytes = std::fs::read(&out).unwrap();
        if status.success() {
            assert!(
                image::load_from_memory(&bytes).is_ok(),
                "after {after_ms} ms"
            );
        } else {
            assert_eq!(bytes, b"the old image", "after {after_ms} ms: {status:?}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 9. `rtc fmt` in place -------------------------------------------------------------------

#[cfg(unix)]
#[test]
fn fmt_in_place_keeps_permissions_and_writes_through_a_symlink() {
    use std::os::unix::fs::PermissionsExt;
    let dir = scratch("fmt-in-place");
    let messy = "rtc 1\nlet   x =   1\nassert(x==1)\n";
    let file = write(&dir.join("real.rtc"), messy);
    std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o600)).unwrap();
    symlink("real.rtc", &dir.join("link.rtc"));
    let run = rtc_in(&dir, &["fmt", "link.rtc"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    let link = std::fs::symlink_metadata(dir.join("link.rtc")).unwrap();
    assert!(
        link.file_type().is_symlink(),
        "the link was replaced by a file"
    );
    let formatted = std::fs::read_to_string(&file).unwrap();
    assert_ne!(formatted, messy, "the target was not formatted");
    let mode = std::fs::metadata(&file).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o600);
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 11. the output is checked before rendering ------------------------------------------------

/// An output rtc cannot write is refused before the render (which here would take minutes), so
/// the run ends at once.
#[cfg(unix)]
#[test]
fn the_output_is_checked_before_the_render() {
    use std::os::unix::fs::PermissionsExt;
    let dir = scratch("output-first");
    // 4000×4000 at 64 samples per pixel axis: far beyond a minute if it started.
    let slow = SCENE.replace("[8, 6]", "[4000, 4000]") + "render { supersampling: 64 }\n";
    write(&dir.join("s.rtc"), &slow);
    fails(
        &rtc_in(&dir, &["render", "s.rtc", "-o", "x.jpg"]),
        2,
        "unknown image format",
    );
    fails(
        &rtc_in(&dir, &["render", "s.rtc", "-o", "none/x.png"]),
        2,
        "does not exist",
    );
    std::fs::create_dir(dir.join("ro")).unwrap();
    std::fs::set_permissions(dir.join("ro"), std::fs::Permissions::from_mode(0o555)).unwrap();
    // Root writes anywhere: the read-only case only means something for other users.
    if std::fs::write(dir.join("ro/probe"), b"").is_err() {
        fails(
            &rtc_in(&dir, &["render", "s.rtc", "-o", "ro/x.png"]),
            2,
            "not writable",
        );
    }
    std::fs::set_permissions(dir.join("ro"), std::fs::Permissions::from_mode(0o755)).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 12. a scene's `output` stays in its folder ------------------------------------------------

#[cfg(unix)]
#[test]
fn a_scene_output_outside_its_folder_is_refused() {
    let root = scratch("output-confined");
    let dir = root.join("scenes");
    std::fs::create_dir_all(dir.join("out")).unwrap();
    let victim = write(&root.join("victim.png"), "precious");
    symlink(root.to_str().unwrap(), &dir.join("up"));
    let outside = [
        victim.to_str().unwrap().to_owned(),
        "../victim.png".into(),
        "out/../../victim.png".into(),
        "up/victim.png".into(),
    ];
    for output in &outside {
        write(
            &dir.join("s.rtc"),
            &format!("{SCENE}render {{ output: \"{output}\" }}\n"),
        );
        let text = fails(
            &rtc_in(&dir, &["render", "s.rtc"]),
            1,
            "rtc::render::output",
        );
        assert!(text.contains("s.rtc:5:"), "{text}");
        assert!(text.contains("-o"), "{text}");
        assert_eq!(std::fs::read(&victim).unwrap(), b"precious", "{output}");
    }
    // Inside the folder, as before; and `-o` is the user's choice.
    write(
        &dir.join("s.rtc"),
        &format!("{SCENE}render {{ output: \"out/a.png\" }}\n"),
    );
    let run = rtc_in(&dir, &["render", "s.rtc"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    assert!(dir.join("out/a.png").is_file());
    write(
        &dir.join("s.rtc"),
        &format!("{SCENE}render {{ output: \"../victim.png\" }}\n"),
    );
    let run = rtc_in(&dir, &["render", "s.rtc", "-o", "mine.png"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    assert!(dir.join("mine.png").is_file());
    std::fs::remove_dir_all(&root).unwrap();
}

// ---- 15. `rtc merge` checks a part's header against its length ---------------------------------

/// A part file: the magic line, `header` with the payload's fingerprint, and the payload.
fn part_bytes(mut header: serde_json::Value, payload: &[u8]) -> Vec<u8> {
    header["payload"] = rtc::opt::fingerprint::bytes(payload).into();
    let mut out = format!("rtc-part 1\n{header}\n").into_bytes();
    out.extend_from_slice(payload);
    out
}

#[test]
fn a_part_header_that_claims_more_than_the_file_holds_is_refused() {
    let header = |height: u32, rows: serde_json::Value| {
        serde_json::json!({
            "scene": "s", "settings": "t", "width": 4, "height": height,
            "channels": ["color"], "encoding": "srgb", "shard": [0, 1], "rows": rows,
            "stats": [0, 0, 0, 0, 0, 0],
        })
    };
    let payload = vec![0u8; 4 * 16 * 24];
    let path = Path::new("p.rtcpart");
    let good = part_bytes(header(16, serde_json::json!([[0, 16]])), &payload);
    rtc::render::part::Part::from_bytes(&good, path).expect("a sound part reads");
    let cases = [
        // 2³² − 1 rows: refused from the header, before 2²⁸ bands are made.
        (
            header(u32::MAX, serde_json::json!([[0, 16]])),
            "larger than rtc renders",
        ),
        // 64 rows are four bands of 16, the header lists one.
        (
            header(64, serde_json::json!([[0, 16]])),
            "rows are not those",
        ),
        // Rows that need more pixel data than the file has.
        (
            header(32, serde_json::json!([[0, 16], [16, 32]])),
            "claims 3072 bytes of pixels",
        ),
    ];
    for (h, why) in cases {
        let e = rtc::render::part::Part::from_bytes(&part_bytes(h, &payload), path).unwrap_err();
        assert_eq!(e.code, "rtc::merge::malformed");
        assert!(e.message.contains(why), "{}", e.message);
    }
}

// ---- 17. the settings fingerprint of shards ---------------------------------------------------

/// Shards rendered with the same options in another order, and `--set a=1` against
/// `--set a=1.0` for a `Float` parameter, merge; a different value of the parameter does not.
#[test]
fn shards_merge_whatever_the_order_of_their_options() {
    let dir = scratch("shard-order");
    write(
        &dir.join("s.rtc"),
        &format!("{SCENE}param a = 0.5\nsphere(radius: a).translate([2, 0, 0])\n"),
    );
    let shard = |k: &str, args: &[&str]| {
        let mut all = args.to_vec();
        all.extend(["--shard", k, "-o"]);
        all.push(if k == "0/2" {
            "p0.rtcpart"
        } else {
            "p1.rtcpart"
        });
        let run = rtc_in(&dir, &all);
        assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    };
    shard("0/2", &["render", "--frame", "0", "--set", "a=1", "s.rtc"]);
    shard(
        "1/2",
        &["render", "s.rtc", "--set", "a=1.0", "--frame", "0"],
    );
    let run = rtc_in(&dir, &["merge", "p0.rtcpart", "p1.rtcpart", "-o", "m.png"]);
    assert_eq!(run.status.code(), Some(0), "{}", stderr(&run));
    shard("1/2", &["render", "s.rtc", "--set", "a=0.75"]);
    fails(
        &rtc_in(&dir, &["merge", "p0.rtcpart", "p1.rtcpart", "-o", "m.png"]),
        1,
        "rtc::merge::mismatch",
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 10. the accuracy cache -------------------------------------------------------------------

/// A cached reference whose bytes were changed fails its checksum and is rendered again (with
/// a note), giving the same reference as before; a cache that cannot be written is a note, not
/// a failure, and leaves no partial file.
#[test]
fn a_damaged_or_unwritable_accuracy_cache_is_a_miss_with_a_note() {
    use rtc::accuracy::reference::{Source, rendered};
    let dir = scratch("accuracy-cache");
    let mut sources = SourceMap::new();
    let loaded = load_source(
        &dir.join("s.rtc"),
        SCENE,
        &mut sources,
        &EvalOptions::default(),
    );
    let mut scene = rtc::opt::prepare(&loaded.scene.expect("the scene loads")).unwrap();
    let options = rtc::accuracy::MeasureOptions {
        repeat: 1,
        seeds: [0, 1],
        threads: 1,
        region: None,
    };
    let cache = dir.join("cache");
    let mut run = |cache: &Path| {
        rendered(
            &mut scene,
            &options,
            Some((cache, "h")),
            &rtc::render::Silent,
        )
        .unwrap()
    };
    let first = run(&cache);
    assert_eq!(first.source, Source::Rendered);
    assert!(first.notes.is_empty(), "{:?}", first.notes);
    assert!(matches!(run(&cache).source, Source::Cached(_)));

    // One flipped byte in the middle of the cached EXR.
    let entry = cache.join("h-seed0.exr");
    let mut bytes = std::fs::read(&entry).unwrap();
    let mid = bytes.len() / 2;
    bytes[mid] ^= 0x40;
    std::fs::write(&entry, &bytes).unwrap();
    let again = run(&cache);
    assert_eq!(again.source, Source::Rendered);
    assert!(
        again.notes.iter().any(|n| n.contains("checksum")),
        "{:?}",
        again.notes
    );
    assert_eq!(again.data, first.data);
    assert!(
        matches!(run(&cache).source, Source::Cached(_)),
        "the entry was written anew"
    );

    // A file where the cache folder should be: the reference is rendered, the run goes on.
    let blocked = write(&dir.join("blocked"), "not a folder");
    let r = run(&blocked.join("sub"));
    assert_eq!(r.data, first.data);
    assert!(
        r.notes.iter().any(|n| n.contains("could not be cached")),
        "{:?}",
        r.notes
    );
    let leftovers: Vec<_> = std::fs::read_dir(&cache)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !n.ends_with(".exr") && !n.ends_with(".sha256"))
        .collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

// ---- 7. `rtc watch` and DNS rebinding -------------------------------------------------------------

/// Sends one request with the given `Host` header to `addr`; the status line of the answer.
fn status_for_host(addr: &str, host: Option<&str>) -> String {
    use std::io::{BufRead, Write};
    let mut s = std::net::TcpStream::connect(addr).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    let host = host.map_or(String::new(), |h| format!("Host: {h}\r\n"));
    write!(s, "GET / HTTP/1.1\r\n{host}Connection: close\r\n\r\n").unwrap();
    let mut line = String::new();
    std::io::BufReader::new(s).read_line(&mut line).unwrap();
    line
}

/// A page on another site whose name was rebound to 127.0.0.1 sends its own `Host`: refused
/// (403); the loopback names with the right port are answered.
#[test]
fn rtc_watch_answers_only_its_loopback_host() {
    use std::io::{BufRead, BufReader};
    let dir = scratch("watch-host");
    let scene = write(&dir.join("s.rtc"), SCENE);
    let mut child = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["watch", scene.to_str().unwrap(), "--port", "0"])
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut lines = BufReader::new(child.stderr.take().unwrap()).lines();
    let first = lines.next().and_then(Result::ok).unwrap_or_default();
    std::thread::spawn(move || lines.for_each(drop));
    let addr = first
        .split("http://")
        .nth(1)
        .and_then(|r| r.split('/').next())
        .unwrap_or("")
        .to_string();
    let port = addr.rsplit(':').next().unwrap().to_string();
    for good in [
        addr.clone(),
        format!("localhost:{port}"),
        format!("LOCALHOST:{port}"),
    ] {
        assert!(
            status_for_host(&addr, Some(&good)).contains("200"),
            "{good}"
        );
    }
    for bad in [
        Some(format!("evil.example:{port}")),
        Some("127.0.0.1:1".into()),
        Some("127.0.0.1".into()),
        None,
    ] {
        let line = status_for_host(&addr, bad.as_deref());
        assert!(line.contains("403"), "{bad:?}: {line}");
    }
    let _ = child.kill();
    let _ = child.wait();
    std::fs::remove_dir_all(&dir).unwrap();
}
