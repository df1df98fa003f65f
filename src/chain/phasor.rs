//! e^{i k ω} for k = 0, 1, 2 … by rotation, one complex product a sample instead of a
//! sine and a cosine: a single-frequency DFT over half a million samples (a planetary
//! stage's fault lines in the condition report) costs a few milliseconds instead of a
//! hundred. The rotation is restarted from the exact sin_cos every [`RESYNC`] samples, so
//! its rounding stays near 1e-13 whatever the length.

/// Samples between exact restarts of the rotation.
const RESYNC: usize = 1024;

/// The unit phasor e^{i k ω} at sample k.
pub(crate) struct Phasor {
    omega: f64,
    step: (f64, f64),
    now: (f64, f64),
    k: usize,
}

impl Phasor {
    /// A phasor turning by `omega` (rad) a sample, at sample 0.
    pub(crate) fn new(omega: f64) -> Self {
        let (sin, cos) = omega.sin_cos();
        Self {
            omega,
            step: (cos, sin),
            now: (1.0, 0.0),
            k: 0,
        }
    }

    /// (cos kω, sin kω) at the current sample k, then on to k + 1.
    pub(crate) fn next_value(&mut self) -> (f64, f64) {
        let out = self.now;
        self.k += 1;
        self.now = if self.k.is_multiple_of(RESYNC) {
            let (sin, cos) = (self.k as f64 * self.omega).sin_cos();
            (cos, sin)
        } else {
            let ((c, s), (a, b)) = (self.now, self.step);
            (c * a - s * b, c * b + s * a)
        };
        out
    }
}

#[cfg(test)]
mod tests {
    use super::Phasor;

    #[test]
    fn the_rotation_follows_the_exact_phase() {
        let omega = std::f64::consts::TAU * 13.333 / 51_200.0;
        let mut phasor = Phasor::new(omega);
        let mut worst = 0.0_f64;
        for k in 0..600_000 {
            let (c, s) = phasor.next_value();
            let (sin, cos) = (k as f64 * omega).sin_cos();
            worst = worst.max((c - cos).abs()).max((s - sin).abs());
        }
        assert!(worst < 1e-12, "{worst:e}");
    }
}
