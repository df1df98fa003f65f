//! The testrig application's library part: what the commands share and tests use.

pub mod recording;
