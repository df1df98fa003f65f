//! The front panel's server: the page and its script (embedded), the JSON API over HTTP
//! (`/api/info`, `/api/state`, `/api/command`) and the state streamed over a WebSocket
//! (`/api/stream`, ten times a second). See `docs/api.md`.

use std::net::{SocketAddr, TcpListener, TcpStream};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use serde::Serialize;

use super::descriptors::descriptors_for_connections;
use super::guard::Guard;
use super::http::{HttpRequest, HttpResponse, read_request};
use super::state::PanelState;
use crate::runtime::status::SharedStatus;
use crate::vocabulary::command::{Reply, RigCommand};
use crate::vocabulary::control::ControlHandle;

/// How often the stream sends the state (s).
pub const STREAM_PERIOD_S: f64 = 0.1;
/// Most connections served at once, streams included; one more is answered 503 and
/// closed.
pub const MAX_CONNECTIONS: usize = 512;
/// Most state streams (WebSockets) open at once, within [`MAX_CONNECTIONS`].
pub const MAX_STREAMS: usize = 256;
/// Time a client has to take a response or a streamed state before it is dropped.
const WRITE_TIMEOUT: Duration = Duration::from_secs(5);
/// Pause after the listener fails to accept (out of file descriptors): the server waits
/// for connections to close rather than stopping.
const ACCEPT_RETRY: Duration = Duration::from_millis(100);
/// How long, and how much of, a refused client's writing is read before closing.
const LINGER: Duration = Duration::from_millis(200);
const LINGER_BYTES: usize = 256 * 1024;
/// How long a connection refused for want of room waits before it is closed.
const CLOSE_DELAY: Duration = Duration::from_millis(50);
/// Most refused connections waiting to be closed.
const CLOSING_QUEUE: usize = 1024;

const PAGE_HTML: &str = include_str!("page/panel.html");
const PAGE_JS: &str = include_str!("page/panel.js");
/// The page's icon: a gear with a sine, in the panel's green.
const FAVICON_SVG: &str = r##"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 32 32"><rect width="32" height="32" rx="6" fill="#1e2227"/><circle cx="16" cy="16" r="10" fill="none" stroke="#7fdc7f" stroke-width="3" stroke-dasharray="4 3"/><path d="M6 16 Q11 6 16 16 T26 16" fill="none" stroke="#7fdc7f" stroke-width="2"/></svg>"##;

/// What the page needs to know once: the scenario, the stream and the limits.
#[derive(Clone, Debug, Serialize)]
pub struct PanelInfo {
    /// Scenario name.
    pub scenario: String,
    /// Stream rate (Hz).
    pub rate_hz: f64,
    /// Pace: `1` is real time.
    pub pace: String,
    /// Highest speed set point (rev/min).
    pub max_speed_rpm: f64,
    /// Highest brake load (N m): the motor's torque limit.
    pub max_load_nm: f64,
    /// Highest oscillating-load frequency (Hz).
    pub max_oscillating_load_hz: f64,
    /// Whether the rig has an analyser, a scope and a recording.
    pub analyser: bool,
    /// See `analyser`.
    pub scope: bool,
    /// See `analyser`.
    pub record: bool,
}

/// The state serialised for the streams, and when.
type StateJson = (Instant, Arc<str>);

/// What the server's threads share.
#[derive(Clone)]
struct Shared {
    guard: Guard,
    control: ControlHandle,
    status: SharedStatus,
    info: Arc<PanelInfo>,
    stop: Arc<AtomicBool>,
    connections: Arc<AtomicUsize>,
    streams: Arc<AtomicUsize>,
    /// The caps in effect: [`MAX_CONNECTIONS`] and the closing queue, less where the
    /// process has fewer file descriptors.
    max_connections: usize,
    /// The state as JSON, made once a period for every stream.
    state_json: Arc<Mutex<Option<StateJson>>>,
    /// Refused connections on their way to a graceful close.
    closer: crossbeam_channel::Sender<(TcpStream, Instant)>,
}

/// The running server.
pub struct PanelServer {
    /// The address it listens on.
    pub address: SocketAddr,
    /// The token API requests must carry, when bound beyond loopback.
    pub token: Option<String>,
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

impl PanelServer {
    /// Listens on `address` and serves until [`PanelServer::shut_down`].
    pub fn start(
        address: SocketAddr,
        control: ControlHandle,
        status: SharedStatus,
        info: PanelInfo,
    ) -> anyhow::Result<Self> {
        let cannot = |e: std::io::Error| anyhow::anyhow!("--listen {address}: cannot listen: {e}");
        let listener = TcpListener::bind(address).map_err(cannot)?;
        let address = listener.local_addr().map_err(cannot)?;
        let stop = Arc::new(AtomicBool::new(false));
        let guard = Guard::new(address)
            .map_err(|e| anyhow::anyhow!("cannot draw the panel's token: {e}"))?;
        let token = guard.token().map(str::to_string);
        // Connections and refused ones waiting to close share the descriptors the run
        // does not keep, half each.
        let spare = descriptors_for_connections() / 2;
        let caps = (MAX_CONNECTIONS.min(spare), CLOSING_QUEUE.min(spare).max(1));
        let shared = Shared {
            guard,
            control,
            status,
            info: Arc::new(info),
            stop: Arc::clone(&stop),
            connections: Arc::new(AtomicUsize::new(0)),
            streams: Arc::new(AtomicUsize::new(0)),
            state_json: Arc::default(),
            max_connections: caps.0,
            closer: start_closer(caps.1)?,
        };
        let thread = std::thread::Builder::new()
            .name("panel-server".into())
            .spawn(move || serve(&listener, &shared))
            .map_err(|e| anyhow::anyhow!("cannot start the panel's server: {e}"))?;
        Ok(Self {
            address,
            token,
            stop,
            thread: Some(thread),
        })
    }

    /// Stops serving (open streams end at their next send).
    pub fn shut_down(mut self) {
        self.stop.store(true, Ordering::Relaxed);
        // Wakes the listener from its accept with a connection of its own.
        let mut wake = self.address;
        if wake.ip().is_unspecified() {
            wake.set_ip(match wake {
                SocketAddr::V4(_) => std::net::Ipv4Addr::LOCALHOST.into(),
                SocketAddr::V6(_) => std::net::Ipv6Addr::LOCALHOST.into(),
            });
        }
        let _ = TcpStream::connect_timeout(&wake, Duration::from_secs(1));
        if let Some(thread) = self.thread.take() {
            // A panic in the server thread has already been reported on stderr.
            let _ = thread.join();
        }
    }
}

impl Shared {
    /// The state as the streams send it, made afresh when the last is older than half a
    /// stream period: however many streams, it is serialised about 20 times a second.
    fn state_json(&self) -> Arc<str> {
        let fresh_for = Duration::from_secs_f64(STREAM_PERIOD_S / 2.0);
        let mut cached = self
            .state_json
            .lock()
            .unwrap_or_else(PoisonError::into_inner);
        if let Some((made, text)) = &*cached
            && made.elapsed() < fresh_for
        {
            return Arc::clone(text);
        }
        let state = PanelState::of(&self.status.snapshot(), self.info.rate_hz);
        let text: Arc<str> = serde_json::to_string(&state)
            .unwrap_or_else(|e| format!("{{\"error\":\"{e}\"}}"))
            .into();
        *cached = Some((Instant::now(), Arc::clone(&text)));
        text
    }
}

/// A place among a bounded number, given back when dropped.
struct Permit(Arc<AtomicUsize>);

impl Permit {
    /// One of `most` places counted by `count`, if one is free.
    fn take(count: &Arc<AtomicUsize>, most: usize) -> Option<Self> {
        count
            .fetch_update(Ordering::AcqRel, Ordering::Acquire, |n| {
                (n < most).then_some(n + 1)
            })
            .ok()
            .map(|_| Self(Arc::clone(count)))
    }
}

impl Drop for Permit {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::AcqRel);
    }
}

/// Accepts connections until stopped: each on a thread of its own while fewer than
/// [`MAX_CONNECTIONS`] are open, else answered 503. Running out of file descriptors
/// pauses accepting; it never ends the server.
fn serve(listener: &TcpListener, shared: &Shared) {
    let mut failing = false;
    while !shared.stop.load(Ordering::Relaxed) {
        match listener.accept() {
            Ok(_) if shared.stop.load(Ordering::Relaxed) => return,
            Ok((conn, _)) => {
                failing = false;
                dispatch(conn, shared);
            }
            Err(e) => {
                if !failing {
                    eprintln!("testrig panel: cannot accept a connection ({e}); retrying");
                }
                failing = true;
                std::thread::sleep(ACCEPT_RETRY);
            }
        }
    }
}

/// Serves `conn` on a thread of its own, or answers 503 when the server is full.
fn dispatch(mut conn: TcpStream, shared: &Shared) {
    if conn.set_nonblocking(false).is_err() || conn.set_write_timeout(Some(WRITE_TIMEOUT)).is_err()
    {
        return;
    }
    let Some(permit) = Permit::take(&shared.connections, shared.max_connections) else {
        let why = format!(
            "the panel is serving {} connections; try again",
            shared.max_connections
        );
        let _ = refusal(503, why).write_to(&mut conn);
        let _ = conn.shutdown(std::net::Shutdown::Write);
        // Closed a moment later, its request read and dropped, so that the close does not
        // reset the connection before the client reads the answer; dropped at once when
        // [`CLOSING_QUEUE`] refused connections already wait.
        let _ = shared.closer.try_send((conn, Instant::now() + CLOSE_DELAY));
        return;
    };
    let worker = shared.clone();
    // A thread that cannot be started drops the connection (and its permit) unanswered.
    let _ = std::thread::Builder::new()
        .name("panel-connection".into())
        .spawn(move || handle(conn, &worker, permit));
}

/// Starts the thread that closes refused connections gracefully, in the order refused.
fn start_closer(queue: usize) -> anyhow::Result<crossbeam_channel::Sender<(TcpStream, Instant)>> {
    let (send, receive) = crossbeam_channel::bounded::<(TcpStream, Instant)>(queue);
    std::thread::Builder::new()
        .name("panel-closer".into())
        .spawn(move || {
            for (mut conn, at) in receive {
                std::thread::sleep(at.saturating_duration_since(Instant::now()));
                drain_without_waiting(&mut conn);
            }
        })
        .map_err(|e| anyhow::anyhow!("cannot start the panel's server: {e}"))?;
    Ok(send)
}

/// Reads and drops what `conn` has already received (at most [`LINGER_BYTES`]).
fn drain_without_waiting(conn: &mut TcpStream) {
    if conn.set_nonblocking(true).is_ok() {
        read_and_drop(conn);
    }
}

/// Reads and drops what `conn` sends until it closes, a read fails or times out, or
/// [`LINGER_BYTES`] have come.
fn read_and_drop(conn: &mut TcpStream) {
    use std::io::Read;
    let mut sink = [0u8; 4096];
    let mut read = 0;
    while read < LINGER_BYTES {
        match conn.read(&mut sink) {
            Ok(0) | Err(_) => break,
            Ok(n) => read += n,
        }
    }
}

/// A JSON reply `{ok: false, error}` of `status`.
fn refusal(status: u16, why: String) -> HttpResponse {
    json(
        status,
        &Reply {
            ok: false,
            at_s: f64::NAN,
            error: Some(why),
        },
    )
}

fn handle(mut conn: TcpStream, shared: &Shared, permit: Permit) {
    let request = match read_request(&mut conn) {
        Ok(request) => request,
        Err(e) => {
            if let Some(status) = e.status() {
                let _ = refusal(status, e.to_string()).write_to(&mut conn);
                close_after_reading_on(conn);
            }
            return;
        }
    };
    let path = request.path().to_string();
    if let Err((status, why)) = shared.guard.check(&request, &path) {
        let _ = refusal(status, why).write_to(&mut conn);
        return;
    }
    if request.method == "GET" && path == "/api/stream" {
        return stream(conn, &request, shared, permit);
    }
    // The client may have gone; nothing is owed to it then.
    let _ = respond(&request, &path, shared).write_to(&mut conn);
}

/// Closes `conn` after an answer to a request not read whole: the client's writing is
/// read and dropped for a moment (at most [`LINGER_BYTES`]) so that the close does not
/// reset the connection before the client has read the answer.
fn close_after_reading_on(mut conn: TcpStream) {
    let _ = conn.shutdown(std::net::Shutdown::Write);
    let _ = conn.set_read_timeout(Some(LINGER));
    read_and_drop(&mut conn);
}

/// The answer to every request but the stream.
fn respond(request: &HttpRequest, path: &str, shared: &Shared) -> HttpResponse {
    let rate_hz = shared.info.rate_hz;
    let method = request.method.as_str();
    match (method, path) {
        ("GET", "/" | "/index.html") => text(PAGE_HTML, "text/html; charset=utf-8"),
        ("GET", "/panel.js") => text(PAGE_JS, "text/javascript; charset=utf-8"),
        ("GET", "/favicon.svg" | "/favicon.ico") => text(FAVICON_SVG, "image/svg+xml"),
        ("GET", "/api/info") => json(200, &*shared.info),
        ("GET", "/api/state") => json(200, &PanelState::of(&shared.status.snapshot(), rate_hz)),
        ("POST", "/api/command") => {
            let reply = command_reply(&request.body, &shared.control);
            json(if reply.ok { 200 } else { 400 }, &reply)
        }
        (_, path) if allowed_methods(path).is_some() => {
            let allowed = allowed_methods(path).unwrap_or_default();
            refusal(
                405,
                format!("{method} {path}: only {allowed}; see docs/api.md"),
            )
            .with_header("Allow", allowed)
        }
        _ => refusal(404, format!("no {method} {path}; see docs/api.md")),
    }
}

/// The methods a known path answers (for `Allow`); `None` for an unknown path.
fn allowed_methods(path: &str) -> Option<&'static str> {
    match path {
        "/" | "/index.html" | "/panel.js" | "/favicon.svg" | "/favicon.ico" | "/api/info"
        | "/api/state" | "/api/stream" => Some("GET"),
        "/api/command" => Some("POST"),
        _ => None,
    }
}

/// Parses `body` as a command and sends it; a malformed body is refused unsent.
fn command_reply(body: &[u8], control: &ControlHandle) -> Reply {
    let parsed = std::str::from_utf8(body)
        .map_err(|e| format!("the body is not UTF-8: {e}"))
        .and_then(|body| {
            serde_json::from_str::<RigCommand>(body).map_err(|e| format!("not a command: {e}"))
        });
    match parsed {
        Ok(command) => control.send(command),
        Err(error) => Reply {
            ok: false,
            at_s: f64::NAN,
            error: Some(error),
        },
    }
}

/// Upgrades to a WebSocket and sends the state every [`STREAM_PERIOD_S`] until the page
/// goes or the server stops; at most [`MAX_STREAMS`] at once.
fn stream(mut conn: TcpStream, request: &HttpRequest, shared: &Shared, _permit: Permit) {
    let Some(key) = request.header("Sec-WebSocket-Key") else {
        let _ = refusal(400, "/api/stream is a WebSocket".into()).write_to(&mut conn);
        return;
    };
    let Some(_stream_permit) = Permit::take(&shared.streams, MAX_STREAMS) else {
        let why = format!("{MAX_STREAMS} state streams are open; close one");
        let _ = refusal(503, why).write_to(&mut conn);
        return;
    };
    let accept = tungstenite::handshake::derive_accept_key(key.as_bytes());
    let head = format!(
        "HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Accept: {accept}\r\n\r\n"
    );
    if std::io::Write::write_all(&mut conn, head.as_bytes()).is_err() {
        return;
    }
    let mut ws =
        tungstenite::WebSocket::from_raw_socket(conn, tungstenite::protocol::Role::Server, None);
    while !shared.stop.load(Ordering::Relaxed) {
        let text = shared.state_json();
        if ws.send(tungstenite::Message::text(&*text)).is_err() {
            return;
        }
        std::thread::sleep(Duration::from_secs_f64(STREAM_PERIOD_S));
    }
    let _ = ws.close(None);
}

fn text(body: &str, content_type: &str) -> HttpResponse {
    HttpResponse::new(200, content_type, body)
}

fn json<T: Serialize>(status: u16, value: &T) -> HttpResponse {
    let body = serde_json::to_string(value).unwrap_or_else(|e| format!("{{\"error\":\"{e}\"}}"));
    HttpResponse::new(status, "application/json", body)
}
