//! Time-synchronous averaging: a signal cut into revolutions at the tacho's
//! once-per-revolution pulses, each revolution resampled to the same number of points
//! (linear interpolation between the stream's samples), and the revolutions averaged.
//! What is not locked to the shaft (noise, other shafts) averages away as 1/√revolutions.

use crate::error::InstrumentError;

/// The average revolution of `signal` (sampled at `rate_hz`) over the revolutions that
/// start at each of `pulses_s` (s; ascending) and end at the next: `points` values per
/// revolution. At least one whole revolution must lie inside the signal.
pub fn synchronous_average(
    signal: &[f64],
    rate_hz: f64,
    pulses_s: &[f64],
    points: usize,
) -> Result<Vec<f64>, InstrumentError> {
    if points < 8 || !(rate_hz.is_finite() && rate_hz > 0.0) {
        return Err(InstrumentError::setting(
            "synchronous average",
            "points per revolution",
            points as f64,
            "at least 8 points on a stream of a positive rate",
        ));
    }
    let last_s = signal.len().saturating_sub(1) as f64 / rate_hz;
    let mut sum = vec![0.0; points];
    let mut revolutions = 0usize;
    let points_f64 = points as f64;
    for pair in pulses_s.windows(2) {
        let (start, end) = (pair[0], pair[1]);
        if !(start >= 0.0 && end > start && end <= last_s) {
            continue;
        }
        // j counted as a float (whole numbers, exact): a conversion from usize is several
        // instructions on x86-64.
        let mut j = 0.0;
        for total in &mut sum {
            let t = start + (end - start) * j / points_f64;
            *total += interpolate(signal, t * rate_hz);
            j += 1.0;
        }
        revolutions += 1;
    }
    if revolutions == 0 {
        return Err(InstrumentError::setting(
            "synchronous average",
            "revolutions",
            0.0,
            "at least one whole revolution between two pulses inside the signal",
        ));
    }
    Ok(sum.iter().map(|s| s / revolutions as f64).collect())
}

/// `signal` at fractional sample position `x` ≥ 0 (linear between neighbours).
fn interpolate(signal: &[f64], x: f64) -> f64 {
    // x ≥ 0: truncation is the floor, without a call to `floor` on baseline x86-64; by
    // i64, one instruction each way (by usize, several), the same values below 2^63
    // (above, no sample is there either way).
    let i = x as i64;
    let frac = x - i as f64;
    let i = i as usize;
    match (signal.get(i), signal.get(i + 1)) {
        (Some(&a), Some(&b)) => a + (b - a) * frac,
        (Some(&a), None) => a,
        _ => 0.0,
    }
}
