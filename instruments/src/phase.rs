//! A running phase kept within one period.

/// `phase` brought into [0, `period`), exactly as `phase.rem_euclid(period)`, without its
/// division where one subtraction or addition does: a phase that moved on by less than a
/// period per sample. In [period, 2·period) the difference is exact (Sterbenz), as fmod
/// is; in (−period, 0) rem_euclid adds the period as here.
pub(crate) fn wrapped(phase: f64, period: f64) -> f64 {
    if (0.0..period).contains(&phase) {
        phase
    } else if phase >= period && phase < 2.0 * period {
        phase - period
    } else if phase < 0.0 && phase > -period {
        phase + period
    } else {
        phase.rem_euclid(period)
    }
}

#[cfg(test)]
mod tests {
    use super::wrapped;

    /// Bit for bit as rem_euclid, over phases within two periods either side, across the
    /// boundaries, and beyond.
    #[test]
    fn wraps_as_rem_euclid_does() {
        let period = std::f64::consts::TAU * 1.5;
        let mut phase = -2.2 * period;
        while phase < 2.2 * period {
            for p in [phase, phase.next_up(), phase.next_down()] {
                assert_eq!(
                    wrapped(p, period).to_bits(),
                    p.rem_euclid(period).to_bits(),
                    "at {p}"
                );
            }
            phase += period / 997.0;
        }
        for p in [0.0, -0.0, period, -period, 2.0 * period, 1e9, -1e9] {
            assert_eq!(
                wrapped(p, period).to_bits(),
                p.rem_euclid(period).to_bits(),
                "at {p}"
            );
        }
    }
}
