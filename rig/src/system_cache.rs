//! The linear systems of the modes visited so far, built on first use and dropped when
//! the forcing frequencies change.

use crate::events::{EventFlags, mode_events};
use crate::layout::Layout;
use crate::matrix_exp::spectral_radius;
use crate::mode::{MeshMode, Mode, MotorMode, PairZone};
use crate::model::{Frequencies, ModelConstants, harmonic_pairs, system_matrix};
use crate::options::ContactLaw;
use crate::propagator::ModeSystem;
use crate::schedule::LiveCeiling;
use crate::stride::MAX_STRIDE;
use crate::taylor::MAX_RHO_H;

/// Lazily built [`ModeSystem`]s for the current forcing frequencies.
pub struct SystemCache {
    mc: ModelConstants,
    layout: Layout,
    law: ContactLaw,
    flags: EventFlags,
    step_s: f64,
    frequencies: Frequencies,
    systems: Vec<Option<ModeSystem>>,
    /// Rotations of the harmonic pairs by k steps, k = 1..=MAX_STRIDE.
    rotations: Vec<Vec<(usize, f64, f64)>>,
}

impl SystemCache {
    /// An empty cache for internal step `step_s` (s).
    pub fn new(
        mc: ModelConstants,
        layout: Layout,
        law: ContactLaw,
        flags: EventFlags,
        step_s: f64,
    ) -> Self {
        Self {
            mc,
            layout,
            law,
            flags,
            step_s,
            frequencies: Frequencies {
                rotation_rad_s: 0.0,
                oscillating_load_rad_s: 0.0,
                brake_characteristic_nms_per_rad: 0.0,
            },
            systems: (0..Mode::COUNT).map(|_| None).collect(),
            rotations: Vec::new(),
        }
    }

    /// Internal steps per output step so that ρ·h ≤ [`MAX_RHO_H`] in the stiffest mode at
    /// the highest speed and oscillating-load frequency the plant is built for.
    pub fn substeps_for(
        mc: &ModelConstants,
        layout: &Layout,
        ceiling: LiveCeiling,
        output_step_s: f64,
    ) -> u64 {
        let frequencies = Frequencies {
            rotation_rad_s: ceiling.speed_rpm * std::f64::consts::PI / 30.0,
            oscillating_load_rad_s: 2.0 * std::f64::consts::PI * ceiling.oscillating_load_hz,
            brake_characteristic_nms_per_rad: 0.0,
        };
        let stiffest = Mode {
            mesh: MeshMode::Drive,
            pairs: if mc.double_pair_ratio > 1.0 {
                PairZone::TWO
            } else {
                PairZone::ONE
            },
            motor: MotorMode::Linear,
        };
        let rho = spectral_radius(&system_matrix(mc, layout, stiffest, frequencies));
        ((rho * output_step_s / MAX_RHO_H).ceil() as u64).max(1)
    }

    /// The set-point terms the systems are built for.
    pub fn frequencies(&self) -> Frequencies {
        self.frequencies
    }

    /// Switches to new forcing frequencies, dropping every system built for the old ones.
    pub fn set_frequencies(&mut self, frequencies: Frequencies) {
        self.frequencies = frequencies;
        self.systems.iter_mut().for_each(|s| *s = None);
        let h = self.step_s;
        let rotations = harmonic_pairs(&self.mc, &self.layout, frequencies);
        self.rotations = (1..=MAX_STRIDE)
            .map(|k| {
                let span_s = k as f64 * h;
                rotations
                    .iter()
                    .map(|&(i, w)| (i, (w * span_s).cos(), (w * span_s).sin()))
                    .collect()
            })
            .collect();
    }

    /// Builds the system of `mode` if it is not built yet.
    #[inline]
    pub fn ensure(&mut self, mode: Mode) {
        if self.systems[mode.index()].is_none() {
            self.build(mode);
        }
    }

    #[cold]
    fn build(&mut self, mode: Mode) {
        let a = system_matrix(&self.mc, &self.layout, mode, self.frequencies);
        let events = mode_events(
            &self.mc,
            &self.layout,
            self.law,
            self.flags,
            mode,
            &a,
            self.frequencies.rotation_rad_s,
        );
        self.systems[mode.index()] = Some(ModeSystem::new(&a, self.step_s, events));
    }

    /// The system of `mode`; [`SystemCache::ensure`] must have been called for it.
    pub fn built(&self, mode: Mode) -> &ModeSystem {
        match &self.systems[mode.index()] {
            Some(system) => system,
            None => unreachable!("SystemCache::built called before ensure"),
        }
    }

    /// Per-step rotations (index of the cos state, cos ωh, sin ωh) of the harmonic pairs.
    pub fn rotations(&self) -> &[(usize, f64, f64)] {
        &self.rotations[0]
    }

    /// The rotation of the set rotation's own pair (cos φ, sin φ) by `steps` steps
    /// (1..=[`MAX_STRIDE`]): the first of the pairs, as [`SystemCache::set_frequencies`] lists them.
    pub fn phase_rotation_by(&self, steps: usize) -> (usize, f64, f64) {
        self.rotations[steps - 1][0]
    }

    /// Rotations of the harmonic pairs by `steps` steps (1..=[`MAX_STRIDE`]): (index of the
    /// cos state, cos ω·steps·h, sin ω·steps·h).
    pub fn rotations_by(&self, steps: usize) -> &[(usize, f64, f64)] {
        &self.rotations[steps - 1]
    }
}
