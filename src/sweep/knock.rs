//! The knock of the lab's doubtful repeat (`knocked.rs` runs the repeats): a seeded kick
//! of the driven gear's speed, a share of the set speed either way.

use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;

/// Smallest knock, as a share of the set speed: enough to part the teeth.
pub const KNOCK_MIN_SHARE: f64 = 0.02;
/// Largest knock, as a share of the set speed.
pub const KNOCK_MAX_SHARE: f64 = 0.2;

/// A knock's change of the driven gear's speed (rad/s) at `rpm`, drawn from `seed`: a
/// share of the set speed uniform in [[`KNOCK_MIN_SHARE`], [`KNOCK_MAX_SHARE`]], either
/// way.
pub fn knock_rad_s(seed: u64, rpm: f64) -> f64 {
    let mut rng = Pcg64Mcg::seed_from_u64(seed);
    let share = KNOCK_MIN_SHARE + (KNOCK_MAX_SHARE - KNOCK_MIN_SHARE) * rng.random::<f64>();
    let sign = if rng.random::<bool>() { 1.0 } else { -1.0 };
    sign * share * rpm * std::f64::consts::PI / 30.0
}
