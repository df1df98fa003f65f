//! The output rates a plant takes (Hz), either plant: from 100 Hz, below which a step
//! would hold a whole resonance, to 10 MHz, far above any analyser's band (above it a
//! short window held more samples than memory: 297 MHz for 0.05 s took 2.7 GB and 9 s).

/// The lowest output rate a plant takes (Hz).
pub const MIN_OUTPUT_RATE_HZ: f64 = 100.0;

/// The highest output rate a plant takes (Hz).
pub const MAX_OUTPUT_RATE_HZ: f64 = 10.0e6;

/// Whether a plant takes `rate_hz` as its output rate.
pub fn takes_output_rate(rate_hz: f64) -> bool {
    (MIN_OUTPUT_RATE_HZ..=MAX_OUTPUT_RATE_HZ).contains(&rate_hz)
}
