//! The signals that end a run early with every file complete: SIGINT (Ctrl-C), SIGTERM
//! (`kill`, a batch system's time limit) and SIGHUP (the terminal closed). Each sets the
//! run's stop flag and records which signal came, for the exit status (128 + number).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};

/// The handlers, installed for the life of the process.
#[derive(Debug)]
pub struct StopSignals {
    stop: Arc<AtomicBool>,
    which: Arc<AtomicUsize>,
}

/// Signals handled, with their names.
const HANDLED: [(i32, &str); 3] = [
    (SIGINT, "SIGINT (Ctrl-C)"),
    (SIGTERM, "SIGTERM"),
    (SIGHUP, "SIGHUP"),
];

impl StopSignals {
    /// Installs the handlers.
    pub fn install() -> std::io::Result<Self> {
        let stop = Arc::new(AtomicBool::new(false));
        let which = Arc::new(AtomicUsize::new(0));
        for (signal, _) in HANDLED {
            signal_hook::flag::register(signal, Arc::clone(&stop))?;
            signal_hook::flag::register_usize(signal, Arc::clone(&which), signal as usize)?;
        }
        Ok(Self { stop, which })
    }

    /// The flag the run watches; set by any of the signals.
    pub fn flag(&self) -> Arc<AtomicBool> {
        Arc::clone(&self.stop)
    }

    /// The last signal received: its number and name.
    pub fn received(&self) -> Option<(i32, &'static str)> {
        let number = self.which.load(Ordering::Relaxed) as i32;
        HANDLED
            .iter()
            .copied()
            .find(|&(signal, _)| signal == number)
    }
}
