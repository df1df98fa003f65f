//! The front panel (`testrig panel`): the HTTP and WebSocket server, the page it serves,
//! the state it shows and the session file it keeps. It sits above the runtime: it reads
//! the run's status and sends commands through the control channel.

pub mod server;
pub mod session;
pub mod state;
