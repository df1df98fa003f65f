//! Seeded Gaussian noise, reproducible across runs and versions (PCG 64 with Box–Muller).

use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;

/// Standard normal samples from a seed.
#[derive(Clone, Debug)]
pub struct GaussianSource {
    seed: u64,
    rng: Pcg64Mcg,
    spare: Option<f64>,
}

impl GaussianSource {
    /// A source that always starts from `seed`.
    pub fn new(seed: u64) -> Self {
        Self {
            seed,
            rng: Pcg64Mcg::seed_from_u64(seed),
            spare: None,
        }
    }

    /// Back to the first sample of the seed's sequence.
    pub fn reset(&mut self) {
        *self = Self::new(self.seed);
    }

    /// One sample of N(0, 1).
    pub fn sample(&mut self) -> f64 {
        if let Some(z) = self.spare.take() {
            return z;
        }
        let u1 = 1.0 - self.rng.random::<f64>();
        let u2 = self.rng.random::<f64>();
        let radius = (-2.0 * u1.ln()).sqrt();
        let angle = std::f64::consts::TAU * u2;
        self.spare = Some(radius * angle.sin());
        radius * angle.cos()
    }
}
