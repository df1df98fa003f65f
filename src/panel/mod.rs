//! The front panel (`testrig panel`): the HTTP and WebSocket server, the page it serves,
//! the state it shows and the session file it keeps. It sits above the runtime: it reads
//! the run's status and sends commands through the control channel.
//!
//! Files: the front panel above the runtime: `server.rs` (page, `/api/info`, `/api/state`,
//! `/api/command`; tungstenite WebSocket `/api/stream`; 405 with `Allow`; at most 512
//! connections and 256 streams, 503 beyond, refused ones closed by one closer thread; the
//! streams share one serialised state), `descriptors.rs` (raises the open-file limit, keeps
//! 128 descriptors for the run), `http.rs` (HTTP/1.1 read with bounds on head, body and
//! time, parsed by httparse; one request a connection), `guard.rs` (what it trusts: Host,
//! Origin, JSON commands, the token beyond loopback; `docs/security.md`), `state.rs` the
//! API's state, `session.rs` `session.toml` (its head written at start, each command
//! appended as it takes effect through `ControlHandle::journal_to`, the whole rewritten at
//! the end), `page/` the HTML and script, embedded with `include_str!`; `scpi/` the same
//! live rig over SCPI for lab scripts (`docs/scpi.md`)

pub(crate) mod descriptors;
pub(crate) mod guard;
pub(crate) mod http;
pub(crate) mod scpi;
pub(crate) mod server;
pub(crate) mod session;
pub(crate) mod state;
pub use http::{
    HttpRequest, MAX_BODY_BYTES, MAX_HEAD_BYTES, RequestError, parse_head, read_request_from,
};
pub use scpi::{MAX_CLIENTS as MAX_SCPI_CLIENTS, Rack as ScpiRack, ScpiServer, scpi_rack};
pub use server::{MAX_CONNECTIONS, MAX_STREAMS, PanelInfo, PanelServer};
pub use session::{Session, commands_toml, session_head};
pub use state::PanelState;
