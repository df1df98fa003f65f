//! Pacing: blocks released at wall-clock deadlines t0 + k·period/pace, and a fixed-size
//! histogram of how late each release was.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// How fast simulated time runs against the wall clock.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pace {
    /// This many simulated seconds per wall second (1 = real time).
    Factor(f64),
    /// As fast as the machine goes.
    Max,
}

/// Slowest pace accepted: a thousand times slower than real time.
pub const SLOWEST_PACE: f64 = 1.0e-3;
/// Fastest pace factor accepted (beyond it, use `max`).
pub const FASTEST_PACE: f64 = 1.0e6;

impl Pace {
    /// Parses `1`, `20`, `0.5` (a factor in [0.001, 10⁶]) or `max`.
    pub fn parse(text: &str) -> Option<Self> {
        if text == "max" {
            return Some(Self::Max);
        }
        text.parse::<f64>()
            .ok()
            .filter(|f| (SLOWEST_PACE..=FASTEST_PACE).contains(f))
            .map(Self::Factor)
    }

    /// As written in the manifest: the factor, or "max".
    pub fn label(self) -> String {
        match self {
            Self::Factor(f) => format!("{f}"),
            Self::Max => "max".into(),
        }
    }
}

/// Longest a paced wait goes without looking at the stop flag (s).
pub const STOP_CHECK_S: f64 = 0.05;

/// Wall-clock deadlines of a paced run.
#[derive(Clone, Copy, Debug)]
pub struct Pacer {
    start: Instant,
    seconds_per_sample: f64,
}

impl Pacer {
    /// Deadlines from now, for a stream of `rate_hz` at `factor` times real time.
    pub fn new(rate_hz: f64, factor: f64) -> Self {
        Self {
            start: Instant::now(),
            seconds_per_sample: 1.0 / (rate_hz * factor),
        }
    }

    /// Waits until the block ending at sample `end_sample` is due (its last sample's
    /// simulated time, scaled by the pace) and returns how late the release is (s, ≥ 0).
    /// The wait ends early, within [`STOP_CHECK_S`], once `stop` is set: a slow pace
    /// (a block may be due seconds away) never holds up a stop signal.
    pub fn wait_for(&self, end_sample: u64, stop: &AtomicBool) -> f64 {
        let due = self.start + Duration::from_secs_f64(end_sample as f64 * self.seconds_per_sample);
        let slice = Duration::from_secs_f64(STOP_CHECK_S);
        loop {
            let now = Instant::now();
            if now >= due || stop.load(Ordering::Relaxed) {
                break;
            }
            std::thread::sleep((due - now).min(slice));
        }
        Instant::now().saturating_duration_since(due).as_secs_f64()
    }
}

/// Lateness counts in 10 µs bins up to 100 ms, with the largest value kept exactly:
/// fixed memory however long the run.
#[derive(Clone, Debug)]
pub struct LatenessHistogram {
    bins: Vec<u64>,
    count: u64,
    max_s: f64,
}

const BIN_S: f64 = 10e-6;
const BINS: usize = 10_000;

impl Default for LatenessHistogram {
    fn default() -> Self {
        Self {
            bins: vec![0; BINS + 1],
            count: 0,
            max_s: 0.0,
        }
    }
}

impl LatenessHistogram {
    /// Adds one lateness (s).
    pub fn add(&mut self, lateness_s: f64) {
        let bin = ((lateness_s / BIN_S) as usize).min(BINS);
        self.bins[bin] += 1;
        self.count += 1;
        self.max_s = self.max_s.max(lateness_s);
    }

    /// Releases counted.
    pub fn count(&self) -> u64 {
        self.count
    }

    /// The `q` quantile (0–1) in s, to the bin's upper edge (10 µs; beyond 100 ms, the
    /// largest value); 0 when empty.
    pub fn quantile_s(&self, q: f64) -> f64 {
        if self.count == 0 {
            return 0.0;
        }
        let rank = ((q * self.count as f64).ceil() as u64).clamp(1, self.count);
        let mut seen = 0;
        for (i, &n) in self.bins.iter().enumerate() {
            seen += n;
            if seen >= rank {
                // The last bin gathers everything beyond 100 ms: its largest is the max.
                return if i == BINS {
                    self.max_s
                } else {
                    ((i + 1) as f64 * BIN_S).min(self.max_s)
                };
            }
        }
        self.max_s
    }

    /// Largest lateness (s).
    pub fn max_s(&self) -> f64 {
        self.max_s
    }
}
