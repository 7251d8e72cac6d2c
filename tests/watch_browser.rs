//! `rtc watch` in a real browser: headless Chromium loads the page once, the scene file is
//! edited, and the image on screen changes without a reload, judged by screenshot pixels.
//!
//! Chromium is driven over the DevTools protocol (a WebSocket). `.ci/run` installs the Debian
//! package `chromium` when it is absent and sets `RTC_REQUIRE_BROWSER=1`, which makes a missing
//! browser a failure; elsewhere the test is skipped with a message when no Chromium is found.

mod watch_support;

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use base64::Engine;
use serde_json::{Value, json};
use watch_support::{Watch, save, scene_text, scratch};

/// How long the page may take to show an expected image.
const SHOW_TIMEOUT: Duration = Duration::from_secs(120);

#[test]
fn the_page_shows_an_edit_without_a_reload() {
    let Some(browser) = find_browser() else {
        let required = std::env::var("RTC_REQUIRE_BROWSER").is_ok_and(|v| v == "1");
        assert!(
            !required,
            "RTC_REQUIRE_BROWSER=1 but no Chromium was found (install the Debian package `chromium`)"
        );
        eprintln!(
            "skipped: no Chromium found (`chromium`, `chromium-browser`, `google-chrome` or $CHROMIUM); `.ci/run` installs it"
        );
        return;
    };
    let dir = scratch("browser");
    let scene = dir.join("scene.rtc");
    std::fs::write(&scene, scene_text("rgb(1, 0, 0)", 1)).unwrap();
    let watch = Watch::start(&scene);
    let chromium = Chromium::launch(
        &browser,
        &dir.join("profile"),
        &format!("http://{}/", watch.addr),
    );
    let mut page = chromium.page();

    let red = page.wait_for_center(|[r, g, b]| r > 100 && g < 40 && b < 40, "a red sphere");
    // A reload would clear this.
    page.evaluate("window.__loadedOnce = 'yes'");

    save(&scene, &scene_text("rgb(0, 0, 1)", 1));
    let blue = page.wait_for_center(
        |[r, g, b]| b > 100 && r < 40 && g < 40,
        "the edited blue sphere",
    );
    assert_ne!(red, blue);
    assert_eq!(
        page.evaluate("window.__loadedOnce"),
        json!("yes"),
        "the page was not reloaded"
    );

    // A broken edit dims the last image and shows the diagnostics; the fix clears them.
    save(
        &scene,
        &scene_text("rgb(0, 0, 1)", 1).replace("radius: 1", "radius: -1"),
    );
    let dimmed = page.wait_for_center(
        |[r, g, b]| b < blue[2] && b > 0 && r < 100 && g < 100,
        "the dimmed last image",
    );
    assert!(dimmed[2] < blue[2], "dimmed: {dimmed:?} vs {blue:?}");
    let diagnostics = page.evaluate("document.getElementById('diagnostics').textContent");
    assert!(
        diagnostics.as_str().is_some_and(|t| t.contains("error[")),
        "{diagnostics}"
    );
    save(&scene, &scene_text("rgb(0, 1, 0)", 1));
    page.wait_for_center(
        |[r, g, b]| g > 100 && r < 40 && b < 40,
        "the fixed green sphere",
    );
    assert_eq!(
        page.evaluate("document.getElementById('diagnostics').textContent"),
        json!("")
    );
    assert_eq!(
        page.evaluate("window.__loadedOnce"),
        json!("yes"),
        "the page was not reloaded"
    );
    drop(chromium);
    // Chromium may still be writing its profile after it is killed: cleaning up is best effort.
    let _ = std::fs::remove_dir_all(&dir);
}

/// The Chromium binary: `$CHROMIUM`, else the first of the usual names on `PATH`.
fn find_browser() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("CHROMIUM") {
        return Some(PathBuf::from(p));
    }
    let path = std::env::var_os("PATH")?;
    ["chromium", "chromium-browser", "google-chrome"]
        .iter()
        .flat_map(|name| std::env::split_paths(&path).map(move |d| d.join(name)))
        .find(|p| p.is_file())
}

/// A headless Chromium with the DevTools protocol on a free port (killed when dropped).
struct Chromium {
    child: Child,
    devtools: String,
}

impl Chromium {
    fn launch(binary: &PathBuf, profile: &std::path::Path, url: &str) -> Chromium {
        let mut child = Command::new(binary)
            .args([
                "--headless=new",
                "--no-sandbox", // CI runs as root, where Chromium's sandbox refuses to start
                "--disable-gpu",
                "--no-first-run",
                "--disable-extensions",
                "--remote-debugging-port=0",
                "--window-size=400,400",
                "--force-device-scale-factor=1",
            ])
            .arg(format!("--user-data-dir={}", profile.display()))
            .arg(url)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .expect("chromium starts");
        let mut lines = BufReader::new(child.stderr.take().unwrap()).lines();
        let devtools = lines
            .by_ref()
            .map_while(Result::ok)
            .find_map(|l| {
                l.strip_prefix("DevTools listening on ws://")
                    .and_then(|rest| rest.split('/').next().map(str::to_owned))
            })
            .expect("chromium prints its DevTools address");
        std::thread::spawn(move || lines.for_each(drop));
        Chromium { child, devtools }
    }

    /// The WebSocket of the (only) page.
    fn page(&self) -> Page {
        let deadline = Instant::now() + SHOW_TIMEOUT;
        loop {
            let list = http_get(&self.devtools, "/json/list");
            let targets: Value = serde_json::from_str(&list).unwrap_or(Value::Null);
            let ws = targets.as_array().and_then(|ts| {
                ts.iter()
                    .find(|t| t["type"] == "page")
                    .and_then(|t| t["webSocketDebuggerUrl"].as_str().map(str::to_owned))
            });
            if let Some(ws) = ws {
                let (socket, _) =
                    tungstenite::connect(ws.as_str()).expect("the page's DevTools socket");
                return Page { socket, next_id: 1 };
            }
            assert!(Instant::now() < deadline, "chromium opened no page: {list}");
            std::thread::sleep(Duration::from_millis(100));
        }
    }
}

impl Drop for Chromium {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// A plain HTTP/1.1 GET returning the body (read by its Content-Length: Chromium keeps the
/// connection open).
fn http_get(addr: &str, path: &str) -> String {
    let Ok(mut s) = TcpStream::connect(addr) else {
        return String::new();
    };
    let _ = s.set_read_timeout(Some(Duration::from_secs(10)));
    let _ = write!(
        s,
        "GET {path} HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\n\r\n"
    );
    let mut reader = BufReader::new(s);
    let mut length = 0;
    loop {
        let mut line = String::new();
        if reader.read_line(&mut line).unwrap_or(0) == 0 {
            return String::new();
        }
        let line = line.trim_end();
        if line.is_empty() {
            break;
        }
        if let Some((name, value)) = line.split_once(':')
            && name.eq_ignore_ascii_case("content-length")
        {
            length = value.trim().parse().unwrap_or(0);
        }
    }
    let mut body = vec![0; length];
    match reader.read_exact(&mut body) {
        Ok(()) => String::from_utf8_lossy(&body).into_owned(),
        Err(_) => String::new(),
    }
}

/// One page's DevTools protocol session.
struct Page {
    socket: tungstenite::WebSocket<tungstenite::stream::MaybeTlsStream<TcpStream>>,
    next_id: u64,
}

impl Page {
    /// Sends a command and returns its result (events in between are skipped).
    fn call(&mut self, method: &str, params: Value) -> Value {
        let id = self.next_id;
        self.next_id += 1;
        let msg = json!({ "id": id, "method": method, "params": params });
        self.socket
            .send(tungstenite::Message::text(msg.to_string()))
            .unwrap();
        loop {
            let reply = self.socket.read().expect("a DevTools reply");
            let Ok(text) = reply.to_text() else { continue };
            let v: Value = serde_json::from_str(text).unwrap_or(Value::Null);
            if v["id"] == id {
                assert!(v.get("error").is_none(), "{method} failed: {v}");
                return v["result"].clone();
            }
        }
    }

    /// The value of a JavaScript expression in the page.
    fn evaluate(&mut self, expression: &str) -> Value {
        let r = self.call(
            "Runtime.evaluate",
            json!({ "expression": expression, "returnByValue": true }),
        );
        r["result"]["value"].clone()
    }

    /// The screenshot's pixel at the centre of the displayed image, in page pixels.
    fn center_pixel(&mut self) -> Option<[u8; 3]> {
        let rect = self.evaluate(
            "(() => { const r = document.getElementById('frame').getBoundingClientRect(); \
             return [r.left + r.width / 2, r.top + r.height / 2, r.width]; })()",
        );
        let (x, y, w) = (rect[0].as_f64()?, rect[1].as_f64()?, rect[2].as_f64()?);
        if w < 2.0 {
            return None; // no image yet
        }
        let shot = self.call("Page.captureScreenshot", json!({ "format": "png" }));
        let png = base64::engine::general_purpose::STANDARD
            .decode(shot["data"].as_str()?)
            .ok()?;
        let img = image::load_from_memory(&png).ok()?.to_rgb8();
        let (x, y) = (x as u32, y as u32);
        (x < img.width() && y < img.height()).then(|| img.get_pixel(x, y).0)
    }

    /// Takes screenshots until the image's centre pixel satisfies `ok`, and returns it.
    fn wait_for_center(&mut self, ok: impl Fn([u8; 3]) -> bool, what: &str) -> [u8; 3] {
        let deadline = Instant::now() + SHOW_TIMEOUT;
        let mut last = None;
        loop {
            if let Some(p) = self.center_pixel() {
                if ok(p) {
                    return p;
                }
                last = Some(p);
            }
            assert!(
                Instant::now() < deadline,
                "the page never showed {what}; last centre pixel {last:?}"
            );
            std::thread::sleep(Duration::from_millis(100));
        }
    }
}
