//! The front panel's server: the page and its script (embedded), the JSON API over HTTP
//! (`/api/info`, `/api/state`, `/api/command`) and the state streamed over a WebSocket
//! (`/api/stream`, ten times a second). See `docs/api.md`.

use std::io::Read;
use std::net::SocketAddr;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::JoinHandle;
use std::time::Duration;

use serde::Serialize;
use tiny_http::{Header, Request, Response, Server, StatusCode};

use super::guard::Guard;
use super::state::PanelState;
use crate::runtime::status::SharedStatus;
use crate::vocabulary::command::{Reply, RigCommand};
use crate::vocabulary::control::ControlHandle;

/// How often the stream sends the state (s).
pub const STREAM_PERIOD_S: f64 = 0.1;
/// Largest command body read (bytes).
const MAX_BODY_BYTES: u64 = 64 * 1024;

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

/// What the server's threads share.
#[derive(Clone)]
struct Shared {
    guard: Guard,
    control: ControlHandle,
    status: SharedStatus,
    info: Arc<PanelInfo>,
    stop: Arc<AtomicBool>,
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
        let server = Server::http(address)
            .map_err(|e| anyhow::anyhow!("--listen {address}: cannot listen: {e}"))?;
        let address = server
            .server_addr()
            .to_ip()
            .ok_or_else(|| anyhow::anyhow!("--listen {address}: not an IP address"))?;
        let stop = Arc::new(AtomicBool::new(false));
        let guard = Guard::new(address)
            .map_err(|e| anyhow::anyhow!("cannot draw the panel's token: {e}"))?;
        let token = guard.token().map(str::to_string);
        let shared = Shared {
            guard,
            control,
            status,
            info: Arc::new(info),
            stop: Arc::clone(&stop),
        };
        let thread = std::thread::spawn(move || serve(&server, &shared));
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
        if let Some(thread) = self.thread.take() {
            // A panic in the server thread has already been reported on stderr.
            let _ = thread.join();
        }
    }
}

fn serve(server: &Server, shared: &Shared) {
    while !shared.stop.load(Ordering::Relaxed) {
        let request = match server.recv_timeout(Duration::from_millis(100)) {
            Ok(Some(request)) => request,
            Ok(None) => continue,
            Err(e) => {
                eprintln!("testrig panel: the server stopped: {e}");
                return;
            }
        };
        let shared = shared.clone();
        std::thread::spawn(move || handle(request, &shared));
    }
}

fn handle(mut request: Request, shared: &Shared) {
    let path = request.url().split('?').next().unwrap_or("").to_string();
    let method = request.method().as_str().to_string();
    let rate_hz = shared.info.rate_hz;
    if let Err((status, why)) = shared.guard.check(&request, &path) {
        let refusal = Reply {
            ok: false,
            at_s: f64::NAN,
            error: Some(why),
        };
        let _ = request.respond(json(status, &refusal));
        return;
    }
    let response = match (method.as_str(), path.as_str()) {
        ("GET", "/" | "/index.html") => text(PAGE_HTML, "text/html; charset=utf-8"),
        ("GET", "/panel.js") => text(PAGE_JS, "text/javascript; charset=utf-8"),
        ("GET", "/favicon.svg" | "/favicon.ico") => text(FAVICON_SVG, "image/svg+xml"),
        ("GET", "/api/info") => json(200, &*shared.info),
        ("GET", "/api/state") => json(200, &PanelState::of(&shared.status.snapshot(), rate_hz)),
        ("POST", "/api/command") => {
            let reply = command_reply(&mut request, &shared.control);
            json(if reply.ok { 200 } else { 400 }, &reply)
        }
        ("GET", "/api/stream") => return stream(request, shared),
        (_, path) if allowed_methods(path).is_some() => {
            let allowed = allowed_methods(path).unwrap_or_default();
            json(
                405,
                &Reply {
                    ok: false,
                    at_s: f64::NAN,
                    error: Some(format!("{method} {path}: only {allowed}; see docs/api.md")),
                },
            )
            .with_header(header("Allow", allowed))
        }
        _ => json(
            404,
            &Reply {
                ok: false,
                at_s: f64::NAN,
                error: Some(format!("no {method} {path}; see docs/api.md")),
            },
        ),
    };
    // The client may have gone; nothing is owed to it then.
    let _ = request.respond(response);
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

/// Parses the body as a command and sends it; a malformed body is refused unsent.
fn command_reply(request: &mut Request, control: &ControlHandle) -> Reply {
    let mut body = String::new();
    let read = request
        .as_reader()
        .take(MAX_BODY_BYTES)
        .read_to_string(&mut body);
    let parsed = read
        .map_err(|e| format!("cannot read the body: {e}"))
        .and_then(|_| {
            serde_json::from_str::<RigCommand>(&body).map_err(|e| format!("not a command: {e}"))
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
/// goes or the server stops.
fn stream(request: Request, shared: &Shared) {
    let key = request
        .headers()
        .iter()
        .find(|h| h.field.equiv("Sec-WebSocket-Key"))
        .map(|h| h.value.as_str().to_string());
    let Some(key) = key else {
        let _ = request.respond(json(
            400,
            &Reply {
                ok: false,
                at_s: f64::NAN,
                error: Some("/api/stream is a WebSocket".into()),
            },
        ));
        return;
    };
    let accept = tungstenite::handshake::derive_accept_key(key.as_bytes());
    let response = Response::empty(StatusCode(101))
        .with_header(header("Upgrade", "websocket"))
        .with_header(header("Connection", "Upgrade"))
        .with_header(header("Sec-WebSocket-Accept", &accept));
    let socket = request.upgrade("websocket", response);
    let mut ws =
        tungstenite::WebSocket::from_raw_socket(socket, tungstenite::protocol::Role::Server, None);
    while !shared.stop.load(Ordering::Relaxed) {
        let state = PanelState::of(&shared.status.snapshot(), shared.info.rate_hz);
        let Ok(text) = serde_json::to_string(&state) else {
            return;
        };
        if ws.send(tungstenite::Message::text(text)).is_err() {
            return;
        }
        std::thread::sleep(Duration::from_secs_f64(STREAM_PERIOD_S));
    }
    let _ = ws.close(None);
}

/// A header of ASCII text (the names and values here are constants, or base64).
fn header(name: &str, value: &str) -> Header {
    Header::from_bytes(name.as_bytes(), value.as_bytes()).expect("an ASCII header")
}

fn text(body: &str, content_type: &str) -> Response<std::io::Cursor<Vec<u8>>> {
    Response::from_string(body)
        .with_header(header("Content-Type", content_type))
        .with_chunked_threshold(usize::MAX)
}

fn json<T: Serialize>(status: u16, value: &T) -> Response<std::io::Cursor<Vec<u8>>> {
    let body = serde_json::to_string(value).unwrap_or_else(|e| format!("{{\"error\":\"{e}\"}}"));
    // Content-Length rather than chunks, so that the simplest client reads it whole.
    Response::from_string(body)
        .with_status_code(status)
        .with_header(header("Content-Type", "application/json"))
        .with_chunked_threshold(usize::MAX)
}
