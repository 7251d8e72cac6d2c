//! A small HTTP/1.1 server for the watch page, on a `std::net::TcpListener`: GET requests only,
//! one response per connection (`Connection: close`), and bounds a misbehaving local client
//! cannot push past (docs/watch.md, "Limits"):
//!
//! * at most [`Limits::connections`] connections at once, each on a thread of its own; one more
//!   is answered `503 Service Unavailable` and closed at once by the accepting thread;
//! * the request line and headers must arrive within [`Limits::idle`] of the connection opening
//!   (else `408`, or a silent close if nothing came) and fit in [`Limits::head_bytes`] (else
//!   `414 URI Too Long` when not even the request line fits, `431 Request Header Fields Too
//!   Large` otherwise); nothing past the head is kept, so a request costs at most that much;
//! * a client that stops reading an answer is dropped after [`Limits::idle`] too.
//!
//! tiny_http (used before) reads a request line of any length into memory, has no read or
//! write timeouts and starts a thread for every connection, so a 300 MiB URL grew the process
//! to 699 MiB and 3,000 unfinished requests held 3,004 threads for ever (issue 35).

use std::io::{Read, Write};
use std::net::{Shutdown, TcpListener, TcpStream};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// Environment variable, for tests: the idle limit in milliseconds instead of 10 s.
const IDLE_VAR: &str = "RTC_WATCH_IDLE_MS";

/// How long a refused client's remaining bytes are read and dropped before the socket closes,
/// so it sees the answer rather than a connection reset.
const LINGER: Duration = Duration::from_secs(1);

/// At most this many bytes are read and dropped while lingering.
const LINGER_BYTES: usize = 4 << 20;

/// Stack of a connection's thread: it parses a head and copies buffers, nothing deep.
const STACK: usize = 256 << 10;

/// The server's bounds.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Limits {
    /// Connections served at once; more are answered 503.
    connections: usize,
    /// Time for the whole request head to arrive, and for each write of an answer.
    idle: Duration,
    /// Bytes of the request line and headers together.
    head_bytes: usize,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits {
            connections: 64,
            idle: Duration::from_secs(10),
            head_bytes: 16 << 10,
        }
    }
}

impl Limits {
    /// The defaults, with the idle limit from [`IDLE_VAR`] when it holds a whole number of
    /// milliseconds (tests lower it so idle connections end quickly).
    pub(crate) fn from_env() -> Limits {
        let mut limits = Limits::default();
        if let Some(ms) = std::env::var(IDLE_VAR)
            .ok()
            .and_then(|v| v.trim().parse::<u64>().ok())
        {
            limits.idle = Duration::from_millis(ms.max(1));
        }
        limits
    }
}

/// A request's head: method, target and headers (names as sent).
#[derive(Debug)]
pub(crate) struct Request {
    /// `GET`.
    method: String,
    /// The request target as sent (`/frame/3.png?x`).
    target: String,
    headers: Vec<(String, String)>,
}

impl Request {
    /// The value of the first header named `name` (any case), trimmed.
    pub(crate) fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name))
            .map(|(_, v)| v.trim())
    }

    /// The target's path, without the query.
    pub(crate) fn path(&self) -> &str {
        self.target.split('?').next().unwrap_or("")
    }
}

/// Why no request was read from a connection.
#[derive(Debug, PartialEq, Eq)]
enum Refusal {
    /// The client closed the connection (or it failed) before a whole head came.
    Closed,
    /// The head did not arrive within the idle limit; `partial` when some of it did.
    Timeout {
        /// Whether any bytes came.
        partial: bool,
    },
    /// The head is longer than the limit and has no line end: the request line is too long.
    UriTooLong,
    /// The head is longer than the limit.
    HeadTooLarge,
    /// Not an HTTP/1 request head (what is wrong).
    Malformed(&'static str),
}

impl Refusal {
    /// The answer's status and reason, if the client gets one.
    fn status(&self) -> Option<(u16, &'static str)> {
        match self {
            Refusal::Closed | Refusal::Timeout { partial: false } => None,
            Refusal::Timeout { partial: true } => Some((408, "Request Timeout")),
            Refusal::UriTooLong => Some((414, "URI Too Long")),
            Refusal::HeadTooLarge => Some((431, "Request Header Fields Too Large")),
            Refusal::Malformed(_) => Some((400, "Bad Request")),
        }
    }
}

/// Reads one request head from `stream` within `limits`; bytes after it are left unread.
fn read_head(stream: &mut TcpStream, limits: &Limits) -> Result<Request, Refusal> {
    let deadline = Instant::now() + limits.idle;
    let mut head: Vec<u8> = Vec::with_capacity(1024);
    let mut chunk = [0u8; 4096];
    loop {
        let left = deadline.saturating_duration_since(Instant::now());
        if left.is_zero() {
            return Err(Refusal::Timeout {
                partial: !head.is_empty(),
            });
        }
        if stream.set_read_timeout(Some(left)).is_err() {
            return Err(Refusal::Closed);
        }
        // One byte past the limit tells a head that is too long from one that just fits.
        let room = (limits.head_bytes + 1 - head.len()).min(chunk.len());
        let n = match stream.read(&mut chunk[..room]) {
            Ok(0) => return Err(Refusal::Closed),
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e)
                if matches!(
                    e.kind(),
                    std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut
                ) =>
            {
                return Err(Refusal::Timeout {
                    partial: !head.is_empty(),
                });
            }
            Err(_) => return Err(Refusal::Closed),
        };
        let from = head.len().saturating_sub(3);
        head.extend_from_slice(&chunk[..n]);
        if let Some(end) = head_end(&head[from..]).map(|e| from + e) {
            if end > limits.head_bytes {
                return Err(Refusal::HeadTooLarge);
            }
            head.truncate(end);
            return parse_head(&head);
        }
        if head.len() > limits.head_bytes {
            return Err(if head.contains(&b'\n') {
                Refusal::HeadTooLarge
            } else {
                Refusal::UriTooLong
            });
        }
    }
}

/// Where the blank line ending a head ends in `bytes` (`\r\n\r\n`, or bare `\n\n`).
fn head_end(bytes: &[u8]) -> Option<usize> {
    let crlf = bytes
        .windows(4)
        .position(|w| w == b"\r\n\r\n")
        .map(|i| i + 4);
    let lf = bytes.windows(2).position(|w| w == b"\n\n").map(|i| i + 2);
    match (crlf, lf) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// Parses a whole head (ending in its blank line).
fn parse_head(bytes: &[u8]) -> Result<Request, Refusal> {
    let text =
        std::str::from_utf8(bytes).map_err(|_| Refusal::Malformed("the head is not UTF-8"))?;
    let mut lines = text.split('\n').map(|l| l.strip_suffix('\r').unwrap_or(l));
    let first = lines.next().unwrap_or("");
    let mut words = first.split(' ');
    let (Some(method), Some(target), Some(version), None) =
        (words.next(), words.next(), words.next(), words.next())
    else {
        return Err(Refusal::Malformed(
            "the request line is not `METHOD TARGET HTTP/1.1`",
        ));
    };
    if method.is_empty() || target.is_empty() || !version.starts_with("HTTP/1.") {
        return Err(Refusal::Malformed(
            "the request line is not `METHOD TARGET HTTP/1.1`",
        ));
    }
    let mut headers = Vec::new();
    for line in lines.take_while(|l| !l.is_empty()) {
        let Some((name, value)) = line.split_once(':') else {
            return Err(Refusal::Malformed("a header line has no `:`"));
        };
        if name.is_empty() || name.contains(|c: char| c.is_ascii_whitespace()) {
            return Err(Refusal::Malformed(
                "a header name is empty or holds a space",
            ));
        }
        headers.push((name.to_string(), value.to_string()));
    }
    Ok(Request {
        method: method.to_string(),
        target: target.to_string(),
        headers,
    })
}

/// Writes a whole answer: status line, `Content-Length`, `Connection: close`, the given
/// headers, and `body`.
pub(crate) fn respond(
    stream: &mut TcpStream,
    status: u16,
    reason: &str,
    headers: &[(&str, &str)],
    body: &[u8],
) -> std::io::Result<()> {
    let mut head = format!(
        "HTTP/1.1 {status} {reason}\r\nContent-Length: {}\r\nConnection: close\r\n",
        body.len()
    );
    for (name, value) in headers {
        head.push_str(&format!("{name}: {value}\r\n"));
    }
    head.push_str("\r\n");
    stream.write_all(head.as_bytes())?;
    stream.write_all(body)?;
    stream.flush()
}

/// A plain-text answer `status` with `text` as its body.
pub(crate) fn respond_text(stream: &mut TcpStream, status: u16, reason: &str, text: &str) {
    // A failed write means the client went away; there is nobody to tell.
    let _ = respond(
        stream,
        status,
        reason,
        &[("Content-Type", "text/plain; charset=utf-8")],
        text.as_bytes(),
    );
}

/// Closes after an answer: no more writes, then the client's remaining bytes (a request too
/// long to read, a pipelined one) are read and dropped for a moment, so that closing with them
/// unread does not reset the connection before the client has read the answer.
fn linger_close(mut stream: TcpStream, limits: &Limits) {
    let _ = stream.shutdown(Shutdown::Write);
    let deadline = Instant::now() + LINGER.min(limits.idle);
    let mut sink = [0u8; 8192];
    let mut drained = 0;
    while drained < LINGER_BYTES {
        let left = deadline.saturating_duration_since(Instant::now());
        if left.is_zero() || stream.set_read_timeout(Some(left)).is_err() {
            break;
        }
        match stream.read(&mut sink) {
            Ok(0) | Err(_) => break,
            Ok(n) => drained += n,
        }
    }
}

/// Decrements the count of open connections when the connection's thread ends (or was never
/// started).
struct Slot(Arc<AtomicUsize>);

impl Drop for Slot {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::SeqCst);
    }
}

/// Accepts connections on `listener` on a thread of its own until the process ends, and calls
/// `handle` with each well-formed request on the connection's thread; `handle` writes the whole
/// answer (an event stream returns only when its page has gone).
pub(crate) fn serve<H>(listener: TcpListener, limits: Limits, handle: H) -> std::io::Result<()>
where
    H: Fn(Request, &mut TcpStream) + Send + Sync + 'static,
{
    let handle = Arc::new(handle);
    let open = Arc::new(AtomicUsize::new(0));
    std::thread::Builder::new()
        .name("rtc-watch-accept".into())
        .spawn(move || {
            for conn in listener.incoming() {
                let stream = match conn {
                    Ok(s) => s,
                    Err(_) => {
                        // Out of file descriptors, or a connection reset before it was
                        // accepted: wait a moment rather than spin.
                        std::thread::sleep(Duration::from_millis(10));
                        continue;
                    }
                };
                if open.load(Ordering::SeqCst) >= limits.connections {
                    busy(stream);
                    continue;
                }
                open.fetch_add(1, Ordering::SeqCst);
                let slot = Slot(open.clone());
                let handle = handle.clone();
                // A thread that cannot start drops its closure, and with it the slot and stream.
                let _ = std::thread::Builder::new()
                    .name("rtc-watch-conn".into())
                    .stack_size(STACK)
                    .spawn(move || {
                        let _slot = slot;
                        connection(stream, &limits, &*handle);
                    });
            }
        })?;
    Ok(())
}

/// One connection: read its head within the limits, answer it, close.
fn connection<H: Fn(Request, &mut TcpStream)>(mut stream: TcpStream, limits: &Limits, handle: &H) {
    let _ = stream.set_nodelay(true);
    if stream.set_write_timeout(Some(limits.idle)).is_err() {
        return;
    }
    match read_head(&mut stream, limits) {
        Ok(request) if request.method != "GET" => {
            let _ = respond(
                &mut stream,
                405,
                "Method Not Allowed",
                &[("Allow", "GET")],
                b"rtc watch answers GET requests only",
            );
        }
        Ok(request) => handle(request, &mut stream),
        Err(refusal) => {
            let Some((status, reason)) = refusal.status() else {
                return;
            };
            let why = match &refusal {
                Refusal::UriTooLong | Refusal::HeadTooLarge => format!(
                    "the request line and headers are limited to {} bytes",
                    limits.head_bytes
                ),
                Refusal::Malformed(what) => (*what).to_string(),
                _ => format!(
                    "the request did not arrive within {} ms",
                    limits.idle.as_millis()
                ),
            };
            respond_text(&mut stream, status, reason, &why);
        }
    }
    linger_close(stream, limits);
}

/// Answers a connection over the limit `503` and closes it, from the accepting thread (so
/// briefly: a write timeout of a second, and no reading).
fn busy(mut stream: TcpStream) {
    let _ = stream.set_write_timeout(Some(Duration::from_secs(1)));
    let _ = respond(
        &mut stream,
        503,
        "Service Unavailable",
        &[("Retry-After", "1"), ("Content-Type", "text/plain")],
        b"rtc watch is serving as many connections as it allows; try again",
    );
    let _ = stream.shutdown(Shutdown::Write);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_head_ends_at_its_blank_line() {
        assert_eq!(head_end(b"GET / HTTP/1.1\r\nHost: a\r\n\r\nrest"), Some(27));
        assert_eq!(head_end(b"GET / HTTP/1.1\n\n"), Some(16));
        assert_eq!(head_end(b"GET / HTTP/1.1\r\nHost: a\r\n"), None);
    }

    #[test]
    fn heads_parse_or_are_refused_with_what_is_wrong() {
        let r = parse_head(b"GET /frame/2.png?x HTTP/1.1\r\nhost: 127.0.0.1:1\r\n\r\n").unwrap();
        assert_eq!((r.method.as_str(), r.path()), ("GET", "/frame/2.png"));
        assert_eq!(r.header("Host"), Some("127.0.0.1:1"));
        for bad in [
            &b"GET /\r\n\r\n"[..],
            b"GET / HTTP/2\r\n\r\n",
            b"GET  / HTTP/1.1\r\n\r\n",
            b"GET / HTTP/1.1\r\nno colon\r\n\r\n",
            b"GET / HTTP/1.1\r\n folded: x\r\n\r\n",
            b"GET /\xff HTTP/1.1\r\n\r\n",
        ] {
            assert!(
                matches!(parse_head(bad), Err(Refusal::Malformed(_))),
                "{}",
                String::from_utf8_lossy(bad)
            );
        }
    }
}
