//! The front panel (`testrig panel`): the HTTP and WebSocket server, the page it serves,
//! the state it shows and the session file it keeps. It sits above the runtime: it reads
//! the run's status and sends commands through the control channel.

pub(crate) mod guard;
pub(crate) mod server;
pub(crate) mod session;
pub(crate) mod state;
pub use server::{PanelInfo, PanelServer};
pub use session::Session;
