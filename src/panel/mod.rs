//! The front panel (`testrig panel`): the HTTP and WebSocket server, the page it serves,
//! the state it shows and the session file it keeps. It sits above the runtime: it reads
//! the run's status and sends commands through the control channel.

pub(crate) mod descriptors;
pub(crate) mod guard;
pub(crate) mod http;
pub(crate) mod server;
pub(crate) mod session;
pub(crate) mod state;
pub use http::{
    HttpRequest, MAX_BODY_BYTES, MAX_HEAD_BYTES, RequestError, parse_head, read_request_from,
};
pub use server::{MAX_CONNECTIONS, MAX_STREAMS, PanelInfo, PanelServer};
pub use session::{Session, commands_toml, session_head};
pub use state::PanelState;
