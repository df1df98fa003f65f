//! The plant of a rig file's rig: its state, construction at rest or in steady motion,
//! set-point segments, and the samples it writes. The exact steps are in `stepping.rs`.

use std::f64::consts::PI;

use crate::error::RigError;
use crate::mode::PairZone;
use crate::output_rate::takes_output_rate;
use crate::schedule::{LiveCeiling, Schedule};
use crate::taylor::{MAX_RHO_H, TAYLOR_ORDER};
use crate::topology::RigTopology;

use super::block::{NetworkBlock, NetworkImpact};
use super::equilibrium::{assembled, equilibrium};
use super::mode::{Contact, MeshState, NetMode};
use super::model::NetworkModel;
use super::output::SampleChunk;
use super::record_stride::RecordStride;
use super::system::fastest_rate;
use super::system_cache::SystemCache;

/// Where a run starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NetworkStart {
    /// In steady motion at the schedule's first set points (shafts and meshes twisted to
    /// carry the load, every body at its share of the speed).
    Steady,
    /// At rest, the shafts and meshes twisted to carry the schedule's first load at
    /// standstill (a loop its locked torque); the motor then follows the schedule.
    Rest,
}

/// Longest stretch (s) a ramping oscillating load, or a ramping set speed where meshes
/// turn harmonic states, is held (the harmonics are then set again from the exact
/// rotation).
pub(super) const OSCILLATING_HOLD_S: f64 = 0.01;

/// Samples between checks of the state's bounds (and at the end of every run).
pub(super) const CHECK_EVERY: u64 = 64;

/// Samples between the questions of [`NetworkPlant::skip_while`]: a multiple of
/// `CHECK_EVERY`, 1.3 s at 51.2 kHz.
pub const SKIP_STRETCH: u64 = CHECK_EVERY * 1024;

/// Most internal steps per output sample.
const MAX_SUBSTEPS: u32 = 4096;

/// Fastest any body may turn before the run is called blown up (rad/s).
const SPEED_LIMIT_RAD_S: f64 = 1.0e5;

/// A rig of any topology, advanced exactly. A clone is the whole state, its modes met
/// so far included (an FMU's saved state).
#[derive(Clone, Debug)]
pub struct NetworkPlant {
    pub(super) model: NetworkModel,
    pub(super) schedule: Schedule,
    /// Highest set speed the internal step is sized for (rev/min), and the highest
    /// oscillating-load frequency set points may bring (Hz).
    pub(super) ceiling: LiveCeiling,
    pub(super) output_step_s: f64,
    pub(super) substeps: u32,
    pub(super) step_s: f64,
    /// The modes met so far (boxed, so that a step can hold it apart from the plant by
    /// moving a pointer; `None` only within a step).
    pub(super) cache: Option<Box<SystemCache>>,
    pub(super) u: Vec<f64>,
    pub(super) mode: NetMode,
    pub(super) sample: u64,
    pub(super) segment_end: Option<u64>,
    /// Each mesh's pair zone as a count of zone boundaries (even: two pairs).
    pub(super) zones: Vec<i64>,
    pub(super) next_revolution_rad: f64,
    /// The set speed the harmonic pairs turn with in this segment (rad/s).
    pub(super) harmonic_speed_rad_s: f64,
    /// Each mesh's driver's next tooth boundary (rad in its sense of rotation).
    pub(super) next_tooth_rad: Vec<f64>,
    pub(super) impacts: Vec<NetworkImpact>,
    pub(super) revolutions_s: Vec<f64>,
    /// Start time of the step being taken (s).
    pub(super) step_start_s: f64,
    /// Each switching function's value and rate at `u`, when known (empty when not).
    pub(super) edge: Vec<(f64, f64)>,
    /// The same at the step's end.
    pub(super) next_edge: Vec<(f64, f64)>,
    /// Scratch: the step's end state, the span's end rows (the fused step's rows, then
    /// each shared angle's value and rate: at least `ModeSystem::end_rows` long where
    /// read), the forcing states' rows and the Taylor vectors.
    pub(super) next: Vec<f64>,
    pub(super) fused_out: Vec<f64>,
    pub(super) forcing_out: Vec<f64>,
    pub(super) taylor: Vec<Vec<f64>>,
    /// The order of the last expansion: the Taylor vectors up to it are valid.
    pub(super) taylor_order: usize,
    /// Each switching function's target, taken at a fast run's start and, on the exact
    /// path, after each switch.
    pub(super) targets: Vec<f64>,
    /// The samples stored and not yet written to a block.
    pub(super) chunk: SampleChunk,
    /// The stride a run that writes samples has under way (`record_stride.rs`).
    pub(super) stride: RecordStride,
}

impl NetworkPlant {
    /// A plant of `rig` following `schedule`, sampled at `output_rate_hz`.
    pub fn new(
        rig: &RigTopology,
        schedule: Schedule,
        output_rate_hz: f64,
        start: NetworkStart,
    ) -> Result<Self, RigError> {
        let ceiling = LiveCeiling {
            speed_rpm: schedule.speed_rpm.range().1.abs(),
            oscillating_load_hz: f64::INFINITY,
        };
        Self::live(rig, schedule, output_rate_hz, start, ceiling)
    }

    /// [`Self::new`] for set points changed while it runs ([`Self::hold_set_points`]):
    /// its internal step is sized for set speeds up to `ceiling.speed_rpm`, and a higher
    /// one is refused, as is an oscillating load above `ceiling.oscillating_load_hz` (the
    /// load's harmonic pair is exact at any frequency: that ceiling is the user's).
    pub fn live(
        rig: &RigTopology,
        schedule: Schedule,
        output_rate_hz: f64,
        start: NetworkStart,
        ceiling: LiveCeiling,
    ) -> Result<Self, RigError> {
        rig.check()?;
        rig.check_steppable()?;
        schedule.validate()?;
        if !takes_output_rate(output_rate_hz) {
            return Err(RigError::InvalidOption {
                name: "output_rate_hz",
                value: output_rate_hz.to_string(),
                allowed: "must lie in [100, 1e7] Hz",
            });
        }
        let model = assembled(rig)?;
        let output_step_s = 1.0 / output_rate_hz;
        let top_rpm = ceiling.speed_rpm.max(schedule.speed_rpm.range().1.abs());
        let top_rad_s = top_rpm * PI / 30.0;
        let rho = fastest_rate(&model).max(model.fastest_harmonic_rad_s(top_rad_s));
        let steps = (rho * output_step_s / MAX_RHO_H).ceil().max(1.0);
        if steps.is_nan() || steps > f64::from(MAX_SUBSTEPS) {
            return Err(RigError::InvalidOption {
                name: "output_rate_hz",
                value: format!(
                    "{output_rate_hz} (the rig's fastest motion, {:.3e} rad/s, would need {steps:e} steps a sample)",
                    rho
                ),
                allowed: "a rate at which the rig's fastest motion needs at most 4096 internal steps a sample: stiffer or lighter parts than any rig has, or a rate far too low",
            });
        }
        let substeps = steps as u32;
        let step_s = output_step_s / f64::from(substeps);
        let len = model.layout.padded();
        let meshes = model.meshes.len();
        // The schedule's own oscillating load is always taken, as its top speed is.
        let oscillating_top_hz = schedule.oscillating_load_hz.range().1;
        let mut plant = Self {
            model,
            schedule,
            ceiling: LiveCeiling {
                speed_rpm: top_rpm,
                oscillating_load_hz: ceiling.oscillating_load_hz.max(oscillating_top_hz),
            },
            output_step_s,
            substeps,
            step_s,
            cache: Some(Box::new(SystemCache::new(step_s, substeps, rho))),
            u: vec![0.0; len],
            mode: NetMode::apart(meshes),
            sample: 0,
            segment_end: Some(0),
            zones: vec![1; meshes],
            next_revolution_rad: 2.0 * PI,
            harmonic_speed_rad_s: 0.0,
            next_tooth_rad: vec![0.0; meshes],
            impacts: Vec::new(),
            revolutions_s: Vec::new(),
            step_start_s: 0.0,
            edge: Vec::new(),
            next_edge: Vec::new(),
            next: vec![0.0; len],
            fused_out: Vec::new(),
            forcing_out: Vec::new(),
            taylor: vec![vec![0.0; len]; TAYLOR_ORDER + 1],
            taylor_order: TAYLOR_ORDER,
            targets: Vec::new(),
            chunk: SampleChunk::new(len),
            stride: RecordStride::default(),
        };
        plant.start(start)?;
        Ok(plant)
    }

    /// Places the rig in its steady state at the first set points, or at rest.
    fn start(&mut self, start: NetworkStart) -> Result<(), RigError> {
        let (speed_rad_s, load_nm) = match start {
            NetworkStart::Steady => (
                self.schedule.speed_rpm.value_at(0.0) * PI / 30.0,
                self.schedule.load_nm.value_at(0.0),
            ),
            NetworkStart::Rest => (0.0, self.schedule.load_nm.value_at(0.0)),
        };
        let l = self.model.layout;
        // The constant state first: the meshes' tooth periods are phased by it.
        self.u[l.unit()] = 1.0;
        let mut levels = vec![PairZone::ONE; self.model.meshes.len()];
        let mut state = equilibrium(&self.model, speed_rad_s, load_nm, &levels)?;
        for _ in 0..3 {
            self.u[..l.coordinates].copy_from_slice(&state.angles_rad);
            self.set_zones_from_angles();
            let now: Vec<PairZone> = (0..levels.len())
                .map(|i| self.model.meshes[i].level(self.zones[i]))
                .collect();
            if now == levels {
                break;
            }
            levels = now;
            state = equilibrium(&self.model, speed_rad_s, load_nm, &levels)?;
        }
        self.u[..l.coordinates].copy_from_slice(&state.angles_rad);
        for i in 0..l.coordinates {
            self.u[l.speed(i)] = self.model.speed_ratio[i] * speed_rad_s;
        }
        for (i, s) in state.meshes.iter().enumerate() {
            self.mode.meshes[i] = *s;
            // A faulted pair in mesh at the start takes its stiffness (the start's
            // twists are the healthy pair's; the difference dies in settling).
            let factor = self.model.meshes[i].zone_factor(self.zones[i]);
            let start = &mut self.mode.meshes[i];
            start.factor_bits = factor.to_bits();
            if factor == 0.0 && start.contact != Contact::Apart {
                *start = MeshState {
                    toothless: true,
                    factor_bits: factor.to_bits(),
                    ..MeshState::APART
                };
            }
        }
        self.u[l.set_speed()] = speed_rad_s;
        self.u[l.load()] = load_nm;
        if let Some(m) = &self.model.motor {
            if m.limit_nm
                .is_some_and(|limit| state.motor_torque_nm.abs() > limit)
            {
                return Err(RigError::Schedule(format!(
                    "the motor's torque limit cannot carry the {:.3} N m this steady point takes",
                    state.motor_torque_nm
                )));
            }
            self.u[l.filtered()] = speed_rad_s;
            self.u[l.integral()] = state.motor_torque_nm / m.ki_nm_per_rad;
            let angle = self.model.absolute_angle_rad(m.body, &self.u);
            self.next_revolution_rad = ((angle / (2.0 * PI)).floor() + 1.0) * 2.0 * PI;
        }
        Ok(())
    }

    /// Runs `samples` output samples, appending them to `block`: sample n holds the state
    /// at t = n / rate, then the plant advances to the next. On an error the samples
    /// before it are in `block`.
    pub fn run(&mut self, samples: usize, block: &mut NetworkBlock) -> Result<(), RigError> {
        let result = self.run_samples::<true>(samples, block);
        self.flush_samples(block);
        result.and_then(|()| self.check_bounds())
    }

    /// Advances `samples` output samples without writing them (a settling run), the
    /// impacts and revolutions kept: the motion of [`Self::run`], to rounding, taken in
    /// strides of several steps in modes slow against the step (`plant/fast.rs`).
    pub fn skip(&mut self, samples: usize) -> Result<(), RigError> {
        let mut unwritten = self.block();
        self.run_samples::<false>(samples, &mut unwritten)?;
        self.check_bounds()
    }

    /// As [`Self::skip`], asking `keep_going` after every stretch of [`SKIP_STRETCH`]
    /// samples and stopping where it says no; returns the samples advanced. The stretches
    /// end where every run stops anyway (a check of bounds), so the steps are those of one
    /// [`Self::skip`], bit for bit.
    pub fn skip_while(
        &mut self,
        samples: usize,
        mut keep_going: impl FnMut() -> bool,
    ) -> Result<usize, RigError> {
        let (first, end) = (self.sample, self.sample + samples as u64);
        while self.sample < end {
            let stretch_end = (self.sample / SKIP_STRETCH + 1) * SKIP_STRETCH;
            self.skip((stretch_end.min(end) - self.sample) as usize)?;
            if self.sample < end && !keep_going() {
                break;
            }
        }
        Ok((self.sample - first) as usize)
    }

    /// Appends the state at the current time to `block`: the sample [`Self::run`] writes
    /// first (its set points taken up if they change now).
    pub fn sample_now(&mut self, block: &mut NetworkBlock) {
        self.store_sample(block);
        self.flush_samples(block);
    }

    /// [`Self::run`] without the final check of bounds, its last samples maybe still held;
    /// without samples at all unless `RECORD`.
    fn run_samples<const RECORD: bool>(
        &mut self,
        samples: usize,
        block: &mut NetworkBlock,
    ) -> Result<(), RigError> {
        let mut left = samples as u64;
        while left > 0 {
            left -= self.run_some::<RECORD>(left, block)?;
            if self.sample.is_multiple_of(CHECK_EVERY) {
                self.check_bounds()?;
            }
        }
        Ok(())
    }

    /// Holds the current sample (its set points taken up if they change now), writing
    /// out the samples held before it where it cannot join them.
    pub(super) fn store_sample(&mut self, block: &mut NetworkBlock) {
        self.ready_sample::<true>(block);
        self.chunk.store(self.sample, &self.mode, &self.u);
    }

    /// Readies the plant for the current sample: where a stretch of set points begins
    /// now, it is taken up (the samples held written out first, if `RECORD`); else, if
    /// `RECORD`, the samples held are written out where the sample cannot join them, and
    /// their mode-dependent signals where it is in another mode.
    pub(super) fn ready_sample<const RECORD: bool>(&mut self, block: &mut NetworkBlock) {
        if self.segment_end.is_some_and(|end| self.sample >= end) {
            if RECORD {
                self.flush_samples(block);
            }
            self.begin_segment();
        } else if RECORD && !self.chunk.takes(self.sample) {
            self.flush_samples(block);
        } else if RECORD && !self.chunk.takes_mode(&self.mode) {
            self.write_held(None, block);
        }
    }

    /// Appends the samples held to `block`.
    pub(super) fn flush_samples(&mut self, block: &mut NetworkBlock) {
        self.write_held(Some(self.output_step_s), block);
    }

    /// Writes the signals of the samples held to `block` by the forms of their mode: with
    /// `whole` (the output step, s) all of them, the chunk emptied; without, only their
    /// mode-dependent signals.
    fn write_held(&mut self, whole: Option<f64>, block: &mut NetworkBlock) {
        debug_assert!(self.cache.is_some(), "samples written inside a step");
        if self.chunk.is_empty() {
            return;
        }
        let Some(cache) = self.cache.as_mut() else {
            return;
        };
        let system = cache.get(&self.model, self.chunk.mode());
        match whole {
            Some(output_step_s) => self.chunk.flush(&system.outputs, output_step_s, block),
            None => self.chunk.flush_mode(&system.outputs, block),
        }
    }

    /// Refuses a state that is not finite or turns impossibly fast.
    pub(super) fn check_bounds(&self) -> Result<(), RigError> {
        let l = &self.model.layout;
        let speeds = &self.u[l.speed(0)..l.speed(0) + l.bodies];
        if self.u.iter().all(|x| x.is_finite())
            && speeds.iter().all(|w| w.abs() < SPEED_LIMIT_RAD_S)
        {
            return Ok(());
        }
        Err(RigError::BlowUp {
            t_s: self.time_s(),
            reason: "a body's speed left the finite range or exceeded 1e5 rad/s".into(),
            state: self.u[..l.mechanical()].to_vec(),
        })
    }

    /// An empty block shaped for this plant's rig.
    pub fn block(&self) -> NetworkBlock {
        let l = &self.model.layout;
        NetworkBlock::shaped(
            l.turning().count(),
            self.model.shafts.len() + self.model.frame_shafts,
            self.model.meshes.len(),
            l.translations(),
        )
    }

    /// Time of the current sample (s).
    pub fn time_s(&self) -> f64 {
        self.sample as f64 * self.output_step_s
    }

    /// The time between output samples (s).
    pub fn output_step_s(&self) -> f64 {
        self.output_step_s
    }

    /// The current sample's index: samples run so far.
    pub fn sample(&self) -> u64 {
        self.sample
    }

    /// Internal steps per output sample (ρh ≤ 0.5 in the stiffest mode).
    pub fn substeps(&self) -> u32 {
        self.substeps
    }

    /// Each coordinate's speed per unit speed of the motor's body (signed, in
    /// `topology::RigCoordinates`' order): each body's, 0 for a body's translation, each
    /// planet's rotation, and a planet's translation its pin's r_c s_c e_t.
    pub fn speed_ratios(&self) -> &[f64] {
        &self.model.speed_ratio
    }

    /// Each mesh's contact now.
    pub fn contacts(&self) -> Vec<Contact> {
        (0..self.model.meshes.len())
            .map(|i| self.mode.meshes[i].contact)
            .collect()
    }

    /// The impacts since the last call.
    pub fn take_impacts(&mut self) -> Vec<NetworkImpact> {
        std::mem::take(&mut self.impacts)
    }

    /// The motor body's whole-revolution instants since the last call (s).
    pub fn take_revolutions(&mut self) -> Vec<f64> {
        std::mem::take(&mut self.revolutions_s)
    }

    /// The mechanical state: the coordinates (`topology::RigCoordinates`: the bodies'
    /// angles less their share of the set rotation, rad, absolute while the set rotation
    /// is 0, as at the start; then translations, m), their absolute rates (rad/s, each
    /// about its own axis, signed; m/s), the speed loop's two states.
    pub fn state_rad(&self) -> &[f64] {
        &self.u[..self.model.layout.mechanical()]
    }

    /// Adds `delta_rad_s` to coordinate `coordinate`'s rate (a kick, as a hammer blow):
    /// body i's speed for i below the bodies, past them a translation's velocity (m/s)
    /// or a planet's speed (`topology::RigCoordinates` orders them).
    pub fn kick(&mut self, coordinate: usize, delta_rad_s: f64) {
        let l = &self.model.layout;
        self.u[l.speed(coordinate)] += delta_rad_s;
        self.edge.clear();
        self.stride.drop_stride();
    }

    /// The mechanical energy (J): kinetic, shafts' k·twist²/2 + T0·twist, bearings'
    /// k·deflection²/2, meshes' k·overlap²/2 on their flank.
    pub fn energy_j(&self) -> f64 {
        let l = &self.model.layout;
        let u = &self.u;
        let kinetic: f64 = (0..l.coordinates)
            .map(|i| 0.5 * self.model.inertia[i] * u[l.speed(i)].powi(2))
            .sum();
        let supports: f64 = self
            .model
            .supports
            .iter()
            .map(|c| {
                let deflection: f64 = c.terms.iter().map(|&(j, g)| g * u[l.angle(j)]).sum();
                0.5 * c.stiffness * deflection * deflection
            })
            .sum();
        let shafts: f64 = self
            .model
            .shafts
            .iter()
            .map(|s| {
                let twist = u[l.angle(s.between[0])] - u[l.angle(s.between[1])];
                0.5 * s.stiffness_nm_per_rad * twist * twist + s.preload_nm * twist
            })
            .sum();
        let speed = self.harmonic_speed_rad_s;
        let meshes: f64 = (0..self.model.meshes.len())
            .map(|i| {
                let state = self.mode.meshes[i];
                let (k, _) = self.model.meshes[i].spring(state);
                let overlap = state
                    .pushing_flank()
                    .map_or(0.0, |flank| self.model.overlap(i, flank, u, speed).0);
                0.5 * k * overlap * overlap
            })
            .sum();
        kinetic + shafts + supports + meshes
    }
}
