//! The watch page's HTTP side, on 127.0.0.1 only: `/` is the page, `/events` a server-sent event
//! stream ("frame N is ready", diagnostics, progress), `/frame/N.png` the latest image. Image
//! bytes never go through the event stream: the page fetches them when told. The HTTP side
//! itself (limits, parsing) is [`http`](super::http).

use std::collections::{BTreeMap, VecDeque};
use std::io::Write;
use std::net::{Ipv4Addr, TcpListener, TcpStream};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::time::Duration;

use super::http::{self, Limits, Request};

const PAGE: &str = include_str!("page.html");

/// Events kept for clients that are momentarily behind; older ones are dropped (a client that
/// far behind still gets the latest state of each kind when it reconnects).
const BACKLOG: usize = 256;

/// How long an idle event stream waits before a keep-alive comment.
const KEEPALIVE: Duration = Duration::from_secs(10);

/// How often an idle event stream looks whether its page has closed the connection.
const CLOSED_CHECK: Duration = Duration::from_secs(1);

/// The latest image and the events announced so far, shared by the renderer and every client.
#[derive(Default)]
pub(crate) struct Hub {
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
    pub(crate) fn publish(&self, kind: &'static str, data: &serde_json::Value) {
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
    pub(crate) fn set_frame(&self, n: u64, png: Vec<u8>) {
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
pub(crate) fn bind(port: u16) -> Result<TcpListener, String> {
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

/// Serves requests on a thread of its own until the process ends, within `limits`
/// ([`http`](super::http): a connection cap, an idle limit, a bounded request head).
pub(crate) fn serve(listener: TcpListener, hub: Arc<Hub>, limits: Limits) -> Result<(), String> {
    let port = listener.local_addr().map_or(0, |a| a.port());
    http::serve(listener, limits, move |request, stream| {
        answer(&request, stream, &hub, port)
    })
    .map_err(|e| format!("cannot start the HTTP server: {e}"))
}

/// Whether a request's `Host` header names this server by a loopback name and its port:
/// `127.0.0.1`, `localhost` or `[::1]`, with `:port`. A request without one is refused too
/// (every browser sends it).
fn loopback_host(host: Option<&str>, port: u16) -> bool {
    let Some(host) = host.map(|h| h.trim().to_ascii_lowercase()) else {
        return false;
    };
    let Some((name, p)) = host.rsplit_once(':') else {
        return false;
    };
    p.parse::<u16>() == Ok(port) && matches!(name, "127.0.0.1" | "localhost" | "[::1]")
}

fn answer(request: &Request, stream: &mut TcpStream, hub: &Hub, port: u16) {
    if !loopback_host(request.header("Host"), port) {
        // DNS rebinding: a web page whose name now points at 127.0.0.1 reaches this port, but
        // its requests name its own host.
        let text = format!(
            "rtc watch answers only requests for http://127.0.0.1:{port}/ or http://localhost:{port}/"
        );
        return http::respond_text(stream, 403, "Forbidden", &text);
    }
    let no_store = ("Cache-Control", "no-store");
    // A failed write means the page went away; there is nobody to tell.
    let _ = match request.path() {
        "/" | "/index.html" => http::respond(
            stream,
            200,
            "OK",
            &[("Content-Type", "text/html; charset=utf-8"), no_store],
            PAGE.as_bytes(),
        ),
        "/events" => {
            stream_events(stream, hub);
            Ok(())
        }
        p if p.starts_with("/frame/") => match hub.frame() {
            Some(png) => http::respond(
                stream,
                200,
                "OK",
                &[("Content-Type", "image/png"), no_store],
                &png,
            ),
            None => {
                http::respond_text(stream, 404, "Not Found", "no frame yet");
                Ok(())
            }
        },
        _ => {
            http::respond_text(stream, 404, "Not Found", "not found");
            Ok(())
        }
    };
}

/// Writes the event stream: its head, then events as they come, each flushed at once, until
/// the page goes away: a failed write (also a page that stopped reading for the idle limit), or
/// the end of its side of the connection, looked for every [`CLOSED_CHECK`], so that a closed
/// page frees its place among the connections at once rather than at the next write.
fn stream_events(w: &mut TcpStream, hub: &Hub) {
    let head = "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nCache-Control: no-store\r\nConnection: close\r\n\r\nretry: 500\n\n";
    let (first, mut seen) = hub.snapshot();
    if w.write_all(head.as_bytes())
        .and_then(|_| w.write_all(first.as_bytes()))
        .and_then(|_| w.flush())
        .is_err()
    {
        return;
    }
    let mut quiet = Duration::ZERO;
    loop {
        let (text, now) = hub.after(seen, CLOSED_CHECK);
        seen = now;
        let text = if !text.is_empty() {
            quiet = Duration::ZERO;
            text
        } else if peer_closed(w) {
            return;
        } else {
            quiet += CLOSED_CHECK;
            if quiet < KEEPALIVE {
                continue;
            }
            quiet = Duration::ZERO;
            ": keep-alive\n\n".to_string()
        };
        if w.write_all(text.as_bytes())
            .and_then(|_| w.flush())
            .is_err()
        {
            return;
        }
    }
}

/// Whether the client has closed its side (or the connection failed): a read that does not
/// wait finds the end of the stream. Bytes it sent after its request are left unread.
fn peer_closed(stream: &TcpStream) -> bool {
    if stream.set_nonblocking(true).is_err() {
        return true;
    }
    let mut byte = [0u8; 1];
    let closed = match stream.peek(&mut byte) {
        Ok(0) => true,
        Ok(_) => false,
        Err(e) => e.kind() != std::io::ErrorKind::WouldBlock,
    };
    stream.set_nonblocking(false).is_err() || closed
}
