//! SCPI on the live rig (`testrig panel --scpi ADDR:PORT`, Python's `Rig(scpi=…)`): lab
//! scripts over VISA's raw socket drive the same rig the panel shows, in the IEEE 488.2
//! syntax and a 35670A-style analyser tree (`docs/scpi.md`).
//!
//! `ascii.rs` answers kept to 7-bit ASCII (a client's bytes echoed as `\xNN`);
//! `rack.rs` what the clients of one rig share; `message.rs` a line to units (headers resolved, parameters parsed); `tree.rs` the
//! command tree; `instrument.rs` one client's instrument executing units against the
//! rig, `instrument_settings.rs` its analyser, chain and scope settings and displays; `registers.rs` its IEEE 488.2 status and error queue; `error.rs` SCPI's error
//! numbers; `data.rs` ASCII and definite-length block answers; `words.rs` parameters read
//! against ranges and the rig's names in SCPI's spelling; `server.rs` the socket.

pub(crate) mod ascii;
pub(crate) mod data;
pub(crate) mod error;
pub(crate) mod instrument;
pub(crate) mod instrument_settings;
pub(crate) mod message;
pub(crate) mod rack;
pub(crate) mod registers;
pub(crate) mod server;
pub(crate) mod tree;
pub(crate) mod words;

pub use rack::{Rack, scpi_rack};
pub use server::{MAX_CLIENTS, ScpiServer};
