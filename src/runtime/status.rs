//! What the console shows while a run goes: shared between the threads that know it.

use std::sync::{Arc, Mutex, PoisonError};

use crate::vocabulary::{AppliedChain, LiveSpectrum, LiveTrace};

/// The rack as the experimenter reads it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Status {
    /// Samples the plant has released.
    pub simulated_samples: u64,
    /// Tacho DVM display (V).
    pub dvm_v: f64,
    /// RMS meter reading (V).
    pub meter_v: f64,
    /// Analyser averages taken in the current measurement, and the number set.
    pub averages: (usize, usize),
    /// ADC overloads so far.
    pub adc_overloads: u64,
    /// Blocks dropped at a full queue.
    pub overruns: u64,
    /// The set points now.
    pub set_points: Option<rig::SetPoints>,
    /// The analyser's display (live runs).
    pub spectrum: Option<Arc<LiveSpectrum>>,
    /// The scope's latest trace (live runs).
    pub trace: Option<Arc<LiveTrace>>,
    /// Whether the recorder is writing.
    pub recording: bool,
    /// Lateness of the last release (s; paced runs).
    pub lateness_s: f64,
    /// Contact starts so far.
    pub impacts: u64,
    /// Regime of the last full 10 s window after settling, or "settling" (live runs).
    pub regime: Option<String>,
    /// The physics judge's motion of the last full 10 s window after settling, or
    /// "settling" (live runs).
    pub motion: Option<String>,
    /// The chain's settings in effect (live runs).
    pub chain: AppliedChain,
    /// The latest block of every signal (live runs).
    pub latest: Option<Arc<LatestBlock>>,
}

/// The latest block of every signal, plant and chain, as the sinks received it.
#[derive(Clone, Debug, PartialEq)]
pub struct LatestBlock {
    /// Index of its first sample in the run.
    pub start_sample: u64,
    /// The signals' names, in channel order.
    pub names: Arc<[String]>,
    /// The samples, one channel per name (each signal's unit).
    pub channels: Vec<Arc<[f64]>>,
}

/// A handle every thread can update.
#[derive(Clone, Debug, Default)]
pub struct SharedStatus(Arc<Mutex<Status>>);

impl SharedStatus {
    /// Changes the status under the lock.
    pub fn update(&self, change: impl FnOnce(&mut Status)) {
        change(&mut self.0.lock().unwrap_or_else(PoisonError::into_inner));
    }

    /// A copy of the status now.
    pub fn snapshot(&self) -> Status {
        self.0
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .clone()
    }
}
