//! A running phase kept within one period: wrapped as a float, or counted in whole
//! numbers where the step is a fraction p/q of small q.

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

/// `x` > 0 as p/q in lowest terms: the smallest q ≤ `max_q` for which x·q is whole, to
/// 1e-12 of x·q (or of 1, where x·q is below 1); `None` if there is none.
pub(crate) fn small_fraction(x: f64, max_q: u64) -> Option<(u64, u64)> {
    (1..=max_q).find_map(|q| {
        let scaled = x * q as f64;
        ((scaled - scaled.round()).abs() < 1e-12 * scaled.max(1.0))
            .then(|| (scaled.round() as u64, q))
    })
}

/// k·p/q for k = 0, 1, … counted on in whole numbers: its whole part ⌊kp/q⌋ and its
/// phase kp mod q, exact however large k grows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct FractionCounter {
    whole_step: u64,
    phase_step: usize,
    q: usize,
    /// ⌊kp/q⌋.
    pub whole: u64,
    /// kp mod q.
    pub phase: usize,
}

impl FractionCounter {
    /// The counter of p/q at k = 0.
    pub fn new(p: u64, q: u64) -> Self {
        Self {
            whole_step: p / q,
            phase_step: (p % q) as usize,
            q: q as usize,
            whole: 0,
            phase: 0,
        }
    }

    /// Back to k = 0.
    pub fn reset(&mut self) {
        self.whole = 0;
        self.phase = 0;
    }

    /// On to k + 1.
    pub fn advance(&mut self) {
        self.whole += self.whole_step;
        self.phase += self.phase_step;
        if self.phase >= self.q {
            self.phase -= self.q;
            self.whole += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{FractionCounter, small_fraction, wrapped};

    /// Rates as they are written (10 240 Hz over 400 Hz, 2 kHz over 10.24 kHz, 44.1 kHz
    /// over 400 Hz) come out in lowest terms; 4π and a hair off 64/5 have no small q.
    #[test]
    fn small_fractions_are_found_in_lowest_terms() {
        assert_eq!(small_fraction(10_240.0 / 400.0, 256), Some((128, 5)));
        assert_eq!(small_fraction(2_000.0 / 10_240.0, 1024), Some((25, 128)));
        assert_eq!(small_fraction(44_100.0 / 400.0, 256), Some((441, 4)));
        assert_eq!(small_fraction(3.0, 256), Some((3, 1)));
        assert_eq!(small_fraction(4.0 * std::f64::consts::PI, 256), None);
        assert_eq!(small_fraction(12.8 * (1.0 + 1e-10), 256), None);
    }

    /// The counter's whole part and phase are ⌊kp/q⌋ and kp mod q, as whole-number
    /// division gives them, over many periods; reset starts again at k = 0.
    #[test]
    fn the_counter_keeps_whole_part_and_phase() {
        for (p, q) in [(128, 5), (25, 128), (3, 1), (441, 4)] {
            let mut counter = FractionCounter::new(p, q);
            for k in 0..10_000u64 {
                assert_eq!(counter.whole, k * p / q, "{p}/{q} at {k}");
                assert_eq!(counter.phase as u64, k * p % q, "{p}/{q} at {k}");
                counter.advance();
            }
            counter.reset();
            assert_eq!((counter.whole, counter.phase), (0, 0));
        }
    }

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
