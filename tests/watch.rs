//! `rtc watch` as a page sees it: the event stream announces a new frame after an edit, the
//! diagnostics after a broken edit and the recovery after the fix; a busy port is refused with a
//! free one suggested. The browser's view of the same is tests/watch_browser.rs.

mod watch_support;

use std::net::TcpListener;

use watch_support::{Watch, save, scene_text, scratch};

#[test]
fn edits_breakage_and_recovery_reach_the_event_stream() {
    let dir = scratch("stream");
    let scene = dir.join("scene.rtc");
    std::fs::write(&scene, scene_text("rgb(1, 0, 0)", 2)).unwrap();
    let watch = Watch::start(&scene);
    let mut events = watch.events();

    let first = events.wait_for("frame", |f| f["stage"] == "final");
    assert_eq!(first["width"], 240);
    let red = watch.frame_png(first["n"].as_u64().unwrap());
    let red_center = center_pixel(&red);
    assert!(
        red_center[0] > 100 && red_center[2] < 30,
        "a red sphere: {red_center:?}"
    );

    // An edit (write-and-rename, as editors save) shows a coarse preview (the image is 240
    // wide), then full resolution, then the scene's 2×2 sampling, in that order.
    save(&scene, &scene_text("rgb(0, 0, 1)", 2));
    let preview = events.wait_for("frame", |f| f["n"].as_u64() > first["n"].as_u64());
    assert_eq!(preview["stage"], "preview");
    assert_eq!(
        (preview["width"].as_u64(), preview["full_width"].as_u64()),
        (Some(120), Some(240))
    );
    let full = events.wait_for("frame", |_| true);
    assert_eq!(
        (full["stage"].as_str(), full["width"].as_u64()),
        (Some("full"), Some(240))
    );
    let blue = events.wait_for("frame", |_| true);
    assert_eq!(blue["stage"], "final");
    assert!(blue["n"].as_u64() > first["n"].as_u64());
    let blue_center = center_pixel(&watch.frame_png(blue["n"].as_u64().unwrap()));
    assert!(
        blue_center[2] > 100 && blue_center[0] < 30,
        "a blue sphere: {blue_center:?}"
    );

    // A broken edit: diagnostics with the snippet, and no new frame.
    save(
        &scene,
        &scene_text("rgb(0, 0, 1)", 2).replace("radius: 1", "radius: -1"),
    );
    let broken = events.wait_for("diagnostics", |d| d["errors"].as_u64() > Some(0));
    let html = broken["html"].as_str().unwrap();
    assert!(
        html.contains("<mark>"),
        "the snippet marks the span: {html}"
    );
    assert!(html.contains("scene.rtc:"), "the location is shown: {html}");

    // The fix clears them and renders again.
    save(&scene, &scene_text("rgb(0, 1, 0)", 2));
    events.wait_for("diagnostics", |d| d["errors"] == 0 && d["html"] == "");
    let green = events.wait_for("frame", |f| f["stage"] == "final");
    let green_center = center_pixel(&watch.frame_png(green["n"].as_u64().unwrap()));
    assert!(
        green_center[1] > 100 && green_center[0] < 30,
        "a green sphere: {green_center:?}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_rewrite_with_the_same_content_renders_nothing_new() {
    let dir = scratch("same");
    let scene = dir.join("scene.rtc");
    let text = scene_text("rgb(1, 1, 1)", 1);
    std::fs::write(&scene, &text).unwrap();
    let watch = Watch::start(&scene);
    let mut events = watch.events();
    let first = events.wait_for("frame", |f| f["stage"] == "final");
    save(&scene, &text);
    // Give an (unwanted) render of the identical save time to show before the real edit.
    std::thread::sleep(std::time::Duration::from_secs(1));
    save(&scene, &scene_text("rgb(1, 1, 0)", 1));
    // The real edit's frames are the two right after `first` (preview and full; the scene
    // samples once per pixel): the identical save rendered nothing.
    let next = events.wait_for("frame", |f| f["stage"] == "final");
    assert_eq!(
        next["n"].as_u64(),
        first["n"].as_u64().map(|n| n + 2),
        "the identical save must not render: {next}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn an_imported_module_is_watched_too() {
    let dir = scratch("import");
    let lib = dir.join("lib.rtc");
    std::fs::write(&lib, "rtc 1\npub let tint = rgb(1, 0, 0)\n").unwrap();
    let scene = dir.join("scene.rtc");
    let text = scene_text("lib.tint", 1);
    let text = text.replacen("rtc 1\n", "rtc 1\nimport \"./lib.rtc\"\n", 1);
    std::fs::write(&scene, text).unwrap();
    let watch = Watch::start(&scene);
    let mut events = watch.events();
    let first = events.wait_for("frame", |f| f["stage"] == "final");
    assert!(center_pixel(&watch.frame_png(first["n"].as_u64().unwrap()))[0] > 100);
    save(&lib, "rtc 1\npub let tint = rgb(0, 0, 1)\n");
    let next = events.wait_for("frame", |f| f["stage"] == "final");
    assert!(center_pixel(&watch.frame_png(next["n"].as_u64().unwrap()))[2] > 100);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_busy_port_is_refused_with_a_free_one_suggested() {
    let dir = scratch("busy");
    let scene = dir.join("scene.rtc");
    std::fs::write(&scene, scene_text("rgb(1, 1, 1)", 1)).unwrap();
    let taken = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = taken.local_addr().unwrap().port().to_string();
    let run = std::process::Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["watch", scene.to_str().unwrap(), "--port", &port])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains(&format!("port {port} is busy")), "{stderr}");
    assert!(stderr.contains("try `--port "), "{stderr}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The RGB bytes of the image's centre pixel.
fn center_pixel(png: &[u8]) -> [u8; 3] {
    let img = image::load_from_memory(png).unwrap().to_rgb8();
    img.get_pixel(img.width() / 2, img.height() / 2).0
}

#[test]
fn a_new_edit_cancels_the_render_in_progress() {
    let dir = scratch("cancel");
    let scene = dir.join("scene.rtc");
    // 8×8 samples at 1200×900: the refined stage takes many seconds, the others are quick.
    let slow = scene_text("rgb(1, 0, 0)", 8).replace("[240, 180]", "[1200, 900]");
    std::fs::write(&scene, &slow).unwrap();
    let watch = Watch::start(&scene);
    let mut events = watch.events();
    let full = events.wait_for("frame", |f| f["stage"] == "full");
    events.wait_for("progress", |p| p["stage"] == "refined");
    save(&scene, &scene_text("rgb(0, 0, 1)", 1));
    // The next frame is the edit's preview: the refined red frame never comes.
    let next = events.wait_for("frame", |_| true);
    assert_eq!(next["stage"], "preview", "{next}");
    assert_eq!(next["n"].as_u64(), full["n"].as_u64().map(|n| n + 1));
    let blue = center_pixel(&watch.frame_png(next["n"].as_u64().unwrap()));
    assert!(blue[2] > 100 && blue[0] < 30, "{blue:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}
