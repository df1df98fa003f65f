//! Every seed the application derives, in one place: the seeded noise sources of the
//! measuring chain in a run and in a sweep case, and the seed of each case of a sweep (or
//! stream of a calibration). The derivations are the ones the rig has always used, so
//! that a scenario or a campaign with a given seed gives the same bytes as before.

/// A seeded source of noise in the measuring chain.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NoiseSource {
    /// The slip rings' broadband and contact noise.
    SlipRings,
    /// The ADC's TPDF dither.
    AdcDither,
    /// A sweep's knocks on the driven gear before a repeated measurement.
    Knock,
}

impl NoiseSource {
    /// The source's seed in a run (a scenario, the panel) seeded `run_seed`: one apart
    /// for each source, after the run's own.
    pub fn seed(self, run_seed: u64) -> u64 {
        match self {
            Self::SlipRings => run_seed.wrapping_add(1),
            Self::AdcDither => run_seed.wrapping_add(2),
            Self::Knock => run_seed.wrapping_add(3),
        }
    }

    /// The source's seed in a sweep case seeded `case_seed` ([`case_seed`]): the slip
    /// rings take the case's seed, the dither the case's with its lowest bit flipped, the
    /// knock the case's with its second bit flipped.
    pub fn case_seed(self, case_seed: u64) -> u64 {
        match self {
            Self::SlipRings => case_seed,
            Self::AdcDither => case_seed ^ 1,
            Self::Knock => case_seed ^ 2,
        }
    }
}

/// Seed of case `index`: the base seed and the index mixed (SplitMix64), so neighbouring
/// cases get unrelated noise and any shard reproduces any case.
pub fn case_seed(base: u64, index: usize) -> u64 {
    let mut z = base.wrapping_add((index as u64 + 1).wrapping_mul(0x9E37_79B9_7F4A_7C15));
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}
