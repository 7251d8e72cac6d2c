//! The watch page's HTTP side, on 127.0.0.1 only: `/` is the page, `/events` a server-sent event
//! stream ("frame N is ready", diagnostics, progress), `/frame/N.png` the latest image. Image
//! bytes never go through the event stream: the page fetches them when told.

use std::collections::{BTreeMap, VecDeque};
use std::io::Write;
use std::net::{Ipv4Addr, TcpListener};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::time::Duration;

const PAGE: &str = include_str!("page.html");

/// Events kept for clients that are momentarily behind; older ones are dropped (a client that
/// far behind still gets the latest state of each kind when it reconnects).
const BACKLOG: usize = 256;

/// How long an idle event stream waits before a keep-alive comment (which also notices a
/// closed page).
const KEEPALIVE: Duration = Duration::from_secs(10);

/// The latest image and the events announced so far, shared by the renderer and every client.
#[derive(Default)]
pub struct Hub {
    state: Mutex<HubState>,
    changed: Condvar,
}

#[derive(Default)]
struct HubState {
    /// Sequence number of the last event.
    seq: u64,
    /// Recent events, oldest first, with their sequence numbers.
    events: VecDeque<(u64, String)>,
    /// The latest event of each kind: what a newly opened page is sent first.
    latest: BTreeMap<&'static str, String>,
    /// The latest frame's number and PNG bytes.
    frame: Option<(u64, Arc<Vec<u8>>)>,
}

impl Hub {
    fn lock(&self) -> MutexGuard<'_, HubState> {
        // A poisoned lock only means a client thread panicked; the state is still whole.
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Announces an event `kind` with a JSON payload to every open page.
    pub fn publish(&self, kind: &'static str, data: &serde_json::Value) {
        let text = format!("event: {kind}\ndata: {data}\n\n");
        let mut s = self.lock();
        s.seq += 1;
        let seq = s.seq;
        s.events.push_back((seq, text.clone()));
        if s.events.len() > BACKLOG {
            s.events.pop_front();
        }
        s.latest.insert(kind, text);
        drop(s);
        self.changed.notify_all();
    }

    /// Stores frame `n` (PNG bytes) for `/frame/N.png`; announce it with [`Hub::publish`] after.
    pub fn set_frame(&self, n: u64, png: Vec<u8>) {
        self.lock().frame = Some((n, Arc::new(png)));
    }

    /// The latest state of every kind and the sequence number it is current up to.
    fn snapshot(&self) -> (String, u64) {
        let s = self.lock();
        (s.latest.values().cloned().collect(), s.seq)
    }

    /// The events after `seen` (waiting up to `timeout` for one), and the new sequence number.
    fn after(&self, seen: u64, timeout: Duration) -> (String, u64) {
        let s = self.lock();
        let (s, _) = self
            .changed
            .wait_timeout_while(s, timeout, |s| s.seq == seen)
            .unwrap_or_else(|e| e.into_inner());
        let text = s
            .events
            .iter()
            .filter(|(n, _)| *n > seen)
            .map(|(_, t)| t.as_str())
            .collect();
        (text, s.seq)
    }

    fn frame(&self) -> Option<Arc<Vec<u8>>> {
        self.lock().frame.as_ref().map(|(_, png)| png.clone())
    }
}

/// Binds 127.0.0.1:`port` (0: any free port). A busy port is an error naming a free one.
pub fn bind(port: u16) -> Result<TcpListener, String> {
    match TcpListener::bind((Ipv4Addr::LOCALHOST, port)) {
        Ok(l) => Ok(l),
        Err(e) if e.kind() == std::io::ErrorKind::AddrInUse => {
            let free = (port.saturating_add(1)..=port.saturating_add(50))
                .find(|p| TcpListener::bind((Ipv4Addr::LOCALHOST, *p)).is_ok());
            Err(match free {
                Some(p) => format!(
                    "port {port} is busy (another `rtc watch` or server is using it)\n  help: try `--port {p}`, which is free, or `--port 0` for any free port"
                ),
                None => format!(
                    "port {port} is busy (another `rtc watch` or server is using it)\n  help: pass `--port 0` to use any free port"
                ),
            })
        }
        Err(e) => Err(format!(
            "cannot listen on 127.0.0.1:{port}: {e}\n  help: pass `--port 0` to use any free port"
        )),
    }
}

/// Serves requests until the process ends; each request gets its own thread (event streams
/// stay open).
pub fn serve(listener: TcpListener, hub: Arc<Hub>) -> Result<(), String> {
    let port = listener.local_addr().map_or(0, |a| a.port());
    let server = tiny_http::Server::from_listener(listener, None)
        .map_err(|e| format!("cannot start the HTTP server: {e}"))?;
    std::thread::spawn(move || {
        for request in server.incoming_requests() {
            if !loopback_host(request.headers(), port) {
                // DNS rebinding: a web page whose name now points at 127.0.0.1 reaches this
                // port, but its requests name its own host.
                let _ = request.respond(
                    tiny_http::Response::from_string(format!(
                        "rtc watch answers only requests for http://127.0.0.1:{port}/ or http://localhost:{port}/"
                    ))
                    .with_status_code(403),
                );
                continue;
            }
            let hub = hub.clone();
            std::thread::spawn(move || answer(request, &hub));
        }
    });
    Ok(())
}

/// Whether a request's `Host` header names this server by a loopback name and its port:
/// `127.0.0.1`, `localhost` or `[::1]`, with `:port`. A request without one is refused too
/// (every browser sends it).
pub fn loopback_host(headers: &[tiny_http::Header], port: u16) -> bool {
    let Some(host) = headers
        .iter()
        .find(|h| h.field.equiv("Host"))
        .map(|h| h.value.as_str().trim().to_ascii_lowercase())
    else {
        return false;
    };
    let Some((name, p)) = host.rsplit_once(':') else {
        return false;
    };
    p.parse::<u16>() == Ok(port) && matches!(name, "127.0.0.1" | "localhost" | "[::1]")
}

/// `response` with the given headers (constant ASCII: each one parses).
fn with_headers<R: std::io::Read>(
    mut response: tiny_http::Response<R>,
    headers: &[(&str, &str)],
) -> tiny_http::Response<R> {
    for (name, value) in headers {
        if let Ok(h) = tiny_http::Header::from_bytes(name.as_bytes(), value.as_bytes()) {
            response.add_header(h);
        }
    }
    response
}

fn answer(request: tiny_http::Request, hub: &Hub) {
    let path = request.url().split('?').next().unwrap_or("").to_string();
    // A failed respond means the page went away; there is nobody to tell.
    let _ = match path.as_str() {
        "/" | "/index.html" => request.respond(with_headers(
            tiny_http::Response::from_string(PAGE),
            &[
                ("Content-Type", "text/html; charset=utf-8"),
                ("Cache-Control", "no-store"),
            ],
        )),
        "/events" => {
            stream_events(request, hub);
            Ok(())
        }
        p if p.starts_with("/frame/") => match hub.frame() {
            Some(png) => request.respond(with_headers(
                tiny_http::Response::from_data(png.as_slice()),
                &[("Content-Type", "image/png"), ("Cache-Control", "no-store")],
            )),
            None => request
                .respond(tiny_http::Response::from_string("no frame yet").with_status_code(404)),
        },
        _ => request.respond(tiny_http::Response::from_string("not found").with_status_code(404)),
    };
}

/// Writes the event stream by hand (headers, then events as they come, flushed one by one):
/// tiny_http's own responses buffer their body.
fn stream_events(request: tiny_http::Request, hub: &Hub) {
    let mut w = request.into_writer();
    let head = "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nCache-Control: no-store\r\nConnection: close\r\n\r\nretry: 500\n\n";
    let (first, mut seen) = hub.snapshot();
    if w.write_all(head.as_bytes())
        .and_then(|_| w.write_all(first.as_bytes()))
        .and_then(|_| w.flush())
        .is_err()
    {
        return;
    }
    loop {
        let (text, now) = hub.after(seen, KEEPALIVE);
        seen = now;
        let text = if text.is_empty() {
            ": keep-alive\n\n".to_string()
        } else {
            text
        };
        if w.write_all(text.as_bytes())
            .and_then(|_| w.flush())
            .is_err()
        {
            return;
        }
    }
}
