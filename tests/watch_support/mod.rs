//! Helpers for the `rtc watch` tests: start the command on a free port, read its event stream
//! like a page does, fetch frames, and save files the way editors do.
#![allow(dead_code)]

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::Duration;

/// How long any one expected event may take before the test fails (a debug build on a busy
/// two-core machine is slow; a healthy run needs well under a second per event).
const EVENT_TIMEOUT: Duration = Duration::from_secs(120);

/// A fresh scratch folder for one test.
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rtc-watch-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A 240×180 scene: one sphere of colour `color` (an rtc expression) at the centre, lit from
/// the camera's side, with `supersampling` samples per axis.
pub fn scene_text(color: &str, supersampling: u32) -> String {
    format!(
        "rtc 1\n\
         camera {{ eye: [0, 0, 5], center: [0, 0, 0], up: Y, fov: 40deg, resolution: [240, 180] }}\n\
         point_light {{ position: [0, 0, 10], color: rgb(1, 1, 1) }}\n\
         sphere(center: [0, 0, 0], radius: 1)\n  .material(material {{ color: {color}, ka: 0.3, kd: 0.7, ks: 0, n: 1 }})\n\
         render {{ supersampling: {supersampling}, encoding: linear }}\n"
    )
}

/// Saves `text` to `path` as editors do: write a temporary file beside it, rename it over.
pub fn save(path: &Path, text: &str) {
    let tmp = path.with_extension("rtc.swp");
    std::fs::write(&tmp, text).unwrap();
    std::fs::rename(&tmp, path).unwrap();
}

/// A running `rtc watch` (killed when dropped).
pub struct Watch {
    child: Child,
    /// `127.0.0.1:PORT`.
    pub addr: String,
}

impl Watch {
    /// Starts `rtc watch SCENE --port 0` and reads the address it serves on.
    pub fn start(scene: &Path) -> Watch {
        Watch::start_with(scene, &[])
    }

    /// [`Watch::start`] with extra environment variables (`RTC_WATCH_IDLE_MS` for the limits
    /// tests).
    pub fn start_with(scene: &Path, env: &[(&str, &str)]) -> Watch {
        let mut child = Command::new(env!("CARGO_BIN_EXE_rtc"))
            .args(["watch", scene.to_str().unwrap(), "--port", "0"])
            .envs(env.iter().copied())
            .stderr(Stdio::piped())
            .spawn()
            .expect("rtc watch starts");
        let mut lines = BufReader::new(child.stderr.take().unwrap()).lines();
        let first = lines.next().and_then(Result::ok).unwrap_or_default();
        let addr = first
            .split("http://")
            .nth(1)
            .and_then(|rest| rest.split('/').next())
            .unwrap_or_else(|| panic!("no address in `{first}`"))
            .to_string();
        // Keep draining stderr so the child never blocks on a full pipe.
        std::thread::spawn(move || lines.for_each(drop));
        Watch { child, addr }
    }

    /// The process id of the running `rtc watch`.
    pub fn pid(&self) -> u32 {
        self.child.id()
    }

    /// Opens the event stream.
    pub fn events(&self) -> Events {
        let mut stream = TcpStream::connect(&self.addr).unwrap();
        stream.set_read_timeout(Some(EVENT_TIMEOUT)).unwrap();
        write!(
            stream,
            "GET /events HTTP/1.1\r\nHost: {}\r\n\r\n",
            self.addr
        )
        .unwrap();
        let mut reader = BufReader::new(stream);
        let mut line = String::new();
        reader.read_line(&mut line).unwrap();
        assert!(line.contains("200"), "the event stream answers 200: {line}");
        loop {
            line.clear();
            reader.read_line(&mut line).unwrap();
            if line.trim().is_empty() {
                break;
            }
        }
        Events { reader }
    }

    /// The PNG bytes `/frame/N.png` serves.
    pub fn frame_png(&self, n: u64) -> Vec<u8> {
        let mut stream = TcpStream::connect(&self.addr).unwrap();
        write!(
            stream,
            "GET /frame/{n}.png HTTP/1.1\r\nHost: {}\r\nConnection: close\r\n\r\n",
            self.addr
        )
        .unwrap();
        let mut all = Vec::new();
        stream.read_to_end(&mut all).unwrap();
        let split = all.windows(4).position(|w| w == b"\r\n\r\n").unwrap();
        let head = String::from_utf8_lossy(&all[..split]);
        assert!(head.starts_with("HTTP/1.1 200"), "{head}");
        all[split + 4..].to_vec()
    }
}

impl Drop for Watch {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// A server-sent event stream.
pub struct Events {
    reader: BufReader<TcpStream>,
}

impl Events {
    /// The next event's kind and JSON payload.
    pub fn next(&mut self) -> (String, serde_json::Value) {
        let (mut kind, mut data) = (String::new(), String::new());
        loop {
            let mut line = String::new();
            let n = self
                .reader
                .read_line(&mut line)
                .expect("an event within the timeout");
            assert!(n > 0, "the event stream ended");
            let line = line.trim_end();
            if let Some(k) = line.strip_prefix("event: ") {
                kind = k.to_string();
            } else if let Some(d) = line.strip_prefix("data: ") {
                data = d.to_string();
            } else if line.is_empty() && !kind.is_empty() {
                return (kind, serde_json::from_str(&data).unwrap());
            }
        }
    }

    /// Skips events until one of `kind` satisfies `pred`, and returns its payload.
    pub fn wait_for(
        &mut self,
        kind: &str,
        pred: impl Fn(&serde_json::Value) -> bool,
    ) -> serde_json::Value {
        loop {
            let (k, data) = self.next();
            if k == kind && pred(&data) {
                return data;
            }
        }
    }
}
