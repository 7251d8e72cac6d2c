//! Shared helpers of the hostile-input tests (issue 35): run `rtc` with a guard against hangs,
//! assert a coded failure, make files, links and FIFOs.

#![allow(dead_code)] // each test target uses a part

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

/// A fresh directory for this test process and `name`.
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rtc-hostile-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A small scene that renders in a moment; tests append to it.
pub const SCENE: &str = "rtc 1\ncamera { eye: [0, 0, 5], center: [0, 0, 0], up: Y, resolution: [8, 6] }\n\
                     point_light { position: [5, 5, 5] }\nsphere()\n";

/// A run's standard error as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Runs `rtc args` in `dir`; a run still going after a minute is killed and fails the test
/// (a hang is the defect these cases guard against, so it must not hang the suite too). Its
/// output is read while it runs, so a long message cannot fill the pipe and stall it.
pub fn rtc_in(dir: &Path, args: &[&str]) -> Output {
    use std::io::Read;
    let mut child = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the rtc binary runs");
    let drain = |mut r: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut buf = Vec::new();
            let _ = r.read_to_end(&mut buf);
            buf
        })
    };
    let out = drain(Box::new(child.stdout.take().unwrap()));
    let err = drain(Box::new(child.stderr.take().unwrap()));
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            panic!("`rtc {}` did not end within a minute", args.join(" "));
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    Output {
        status,
        stdout: out.join().unwrap(),
        stderr: err.join().unwrap(),
    }
}

/// Asserts a run failed with exit code `code` and `what` in its stderr; returns the stderr.
pub fn fails(run: &Output, code: i32, what: &str) -> String {
    let text = stderr(run);
    assert_eq!(run.status.code(), Some(code), "{text}");
    assert!(text.contains(what), "expected `{what}` in:\n{text}");
    text
}

/// Writes `text` to `path` and returns the path.
pub fn write(path: &Path, text: &str) -> PathBuf {
    std::fs::write(path, text).unwrap();
    path.to_path_buf()
}

/// Makes the symlink `link` to `target`.
#[cfg(unix)]
pub fn symlink(target: &str, link: &Path) {
    std::os::unix::fs::symlink(target, link).unwrap();
}

/// Makes a FIFO (named pipe) at `path`.
#[cfg(unix)]
pub fn mkfifo(path: &Path) {
    let ok = Command::new("mkfifo").arg(path).status().unwrap();
    assert!(ok.success(), "mkfifo {}", path.display());
}

/// Waits for `child` to end; one still running after a minute is killed and fails the test.
pub fn wait_guarded(child: &mut std::process::Child) -> std::process::ExitStatus {
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return status;
        }
        if start.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            panic!("the process did not end within a minute");
        }
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// Sends the signal `name` (`TERM`, `INT`, `HUP`) to process `pid` with kill(1).
#[cfg(unix)]
pub fn signal(pid: u32, name: &str) {
    let ok = Command::new("kill")
        .args([format!("-{name}"), pid.to_string()])
        .status()
        .unwrap();
    assert!(ok.success(), "kill -{name} {pid}");
}

/// The names in `dir` that start with a dot: rtc's temporary files (`.out.png.XXXXXX.tmp`,
/// `.rtc-probe.XXXXXX`).
pub fn dot_files(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with('.'))
        .collect();
    names.sort();
    names
}
