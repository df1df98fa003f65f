//! The plant's state: parameters, set-point segment, augmented state, mode, logs; its
//! construction and accessors.

use std::f64::consts::TAU;

use crate::error::RigError;
use crate::events::EventFlags;
use crate::fused_step::MAX_ROW_EVENTS;
use crate::geometry::GearGeometry;
use crate::layout::{LOAD, Layout, N_MECH, UNIT, V0, VF, X0, Z};
use crate::mode::{MeshMode, Mode, MotorMode, PairZone};
use crate::model::ModelConstants;
use crate::options::{ContactLaw, MeshPairs};
use crate::output_rate::takes_output_rate;
use crate::pair_zones::PairZones;
use crate::params::RigParams;
use crate::records::{Impact, RevolutionSample};
use crate::schedule::{LiveCeiling, MAX_SPEED_RPM, Schedule, SetPoints};
use crate::system_cache::SystemCache;
use crate::taylor::{TAYLOR_ORDER, TaylorVectors};

use super::chunk::StateChunk;
use super::segment::Segment;

/// Output and set-point timing of a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlantConfig {
    /// Rate of the true signals (Hz).
    pub output_rate_hz: f64,
    /// During a ramp the set points change in steps this long (s).
    pub setpoint_update_s: f64,
    /// For set points changed while the plant runs ([`Plant::set_points_from_now`]): the
    /// highest speed (rev/min) and oscillating-load frequency (Hz) they may reach, beside
    /// the schedule's own (the internal step is sized for them), and with an oscillating
    /// frequency above 0 the oscillating-load states are kept. `None`: only the schedule's.
    pub live_ceiling: Option<LiveCeiling>,
}

impl Default for PlantConfig {
    fn default() -> Self {
        Self {
            output_rate_hz: 51_200.0,
            setpoint_update_s: 0.01,
            live_ceiling: None,
        }
    }
}

/// Most switches handled within one internal step before the run is declared chattering.
pub const SWITCH_LIMIT: usize = 64;

/// Largest relative twist (rad) or relative speed (rad/s) the state may reach before the
/// run is declared blown up: far beyond anything the shafts or gears could bear.
pub(super) const TWIST_LIMIT_RAD: f64 = 1.0;
pub(super) const SPEED_LIMIT_RAD_S: f64 = 1.0e4;

/// Internal steps between exact re-syncs of the harmonic states from the phase.
pub(super) const RESYNC_STEPS: u64 = 4096;

/// The five-inertia rig with backlash, advanced in virtual time.
pub struct Plant {
    pub(super) params: RigParams,
    pub(super) mc: ModelConstants,
    pub(super) geometry: GearGeometry,
    /// The mesh stiffness zones of a tooth period.
    pub(super) zones: PairZones,
    pub(super) schedule: Schedule,
    pub(super) layout: Layout,
    pub(super) law: ContactLaw,
    pub(super) flags: EventFlags,
    pub(super) output_step_s: f64,
    pub(super) substeps: u64,
    pub(super) step_s: f64,
    pub(super) setpoint_update_s: f64,
    pub(super) ceiling: LiveCeiling,
    pub(super) cache: SystemCache,
    pub(super) u: [f64; Layout::MAX_LEN],
    pub(super) mode: Mode,
    pub(super) step_index: u64,
    pub(super) segment: Segment,
    pub(super) zone_index: i64,
    pub(super) next_tooth_rad: f64,
    pub(super) next_rev_rad: f64,
    pub(super) taylor: Box<TaylorVectors>,
    /// Row events' values and slopes at the current state, when known from the last fast step.
    pub(super) edge: Option<[f64; 2 * MAX_ROW_EVENTS]>,
    /// States of the samples of the current fast run.
    pub(super) chunk: Box<StateChunk>,
    pub(super) impacts: Vec<Impact>,
    pub(super) revolutions: Vec<RevolutionSample>,
    pub(super) switch_count: u64,
}

impl Plant {
    /// A plant at the steady state of the schedule's first set points (shafts twisted by
    /// the load, teeth on the loaded flank, or centred in the free play at zero load), at
    /// t = 0 with the driving gear at angle 0.
    pub fn new(
        params: RigParams,
        schedule: Schedule,
        config: PlantConfig,
    ) -> Result<Self, RigError> {
        params.validate()?;
        schedule.validate()?;
        check_config(&config)?;
        let mc = ModelConstants::of(&params);
        let geometry = GearGeometry::of(&params);
        let ceiling = ceiling_of(&schedule, config.live_ceiling);
        let layout = Layout::new(
            params.gear_error_c3_nm != 0.0,
            schedule.has_oscillating_load() || ceiling.oscillating_load_hz > 0.0,
            params.te_mesh_frequency_um != 0.0,
            params.tooth_spacing_error_um != 0.0,
        );
        if !layout.fits() {
            return Err(RigError::InvalidParameter {
                name: "tooth_spacing_error_um".into(),
                value: params.tooth_spacing_error_um.to_string(),
                allowed: "not with gear_error_c3_nm, an oscillating load and te_mesh_frequency_um all on at once (the plant's state has room for three of the four)".into(),
            });
        }
        let alternating =
            params.mesh_pairs == MeshPairs::Alternating && geometry.double_pair_fraction() > 0.0;
        let flags = EventFlags {
            alternating_pairs: alternating && geometry.double_pair_fraction() < 1.0,
            tooth_shifting: params.tooth_shifting,
            spacing_errors: params.tooth_spacing_error_um != 0.0,
        };
        let zones = PairZones::new(
            geometry.double_pair_fraction(),
            params.mesh_stiffness_smoothing,
        );
        let output_step_s = 1.0 / config.output_rate_hz;
        let substeps = SystemCache::substeps_for(&mc, &layout, ceiling, output_step_s);
        let step_s = output_step_s / substeps as f64;
        let set = schedule.held_over(0.0, 0.0);
        let segment = Segment {
            start_step: 0,
            end_step: Some(0),
            phase_rad: 0.0,
            osc_phase_rad: 0.0,
            set,
        };
        let law = params.contact_law;
        let mut plant = Self {
            cache: SystemCache::new(mc.clone(), layout, law, flags, step_s),
            params,
            mc,
            zones,
            geometry,
            schedule,
            layout,
            law,
            flags,
            output_step_s,
            substeps,
            step_s,
            setpoint_update_s: config.setpoint_update_s,
            ceiling,
            u: [0.0; Layout::MAX_LEN],
            mode: Mode {
                mesh: MeshMode::Apart,
                pairs: PairZone::ONE,
                motor: MotorMode::Linear,
            },
            step_index: 0,
            segment,
            zone_index: 0,
            next_tooth_rad: 0.0,
            next_rev_rad: 0.0,
            taylor: Box::new([[0.0; Layout::MAX_LEN]; TAYLOR_ORDER + 1]),
            edge: None,
            chunk: StateChunk::new(layout.spacing),
            impacts: Vec::new(),
            revolutions: Vec::new(),
            switch_count: 0,
        };
        plant.set_steady_state(set);
        plant.begin_segment();
        Ok(plant)
    }

    /// Steady state at `set`: no vibration, every shaft carrying the load and the drag of
    /// the bodies after it.
    pub(super) fn set_steady_state(&mut self, set: SetPoints) {
        let load = set.load_nm + self.params.brake_drag_nm;
        let drag = self.mc.bearing_drag_nm(set.speed_rad_s());
        let [k12, k34, k45] = self.mc.shaft_stiffness_nm_per_rad;
        let b = self.mc.half_backlash_rad * (1.0 - self.mc.backlash_variation);
        let (e, _) = self
            .mc
            .transmission_error(set.speed_rad_s(), [1.0, 0.0, 1.0, 0.0]);
        // The driving gear starts at angle 0: the pair of tooth 0 is in mesh.
        let e = e + self.mc.spacing_of_tooth(0);
        let k23 = self.mc.mesh_stiffness_nm_per_rad;
        // Torques through K12, the mesh, K34 and K45: the load and the drag behind each.
        let [t12, mesh, t34, t45] = [4.0, 3.0, 2.0, 1.0].map(|bodies| load + bodies * drag);
        // Loaded: on the loaded flank; unloaded: centred in the free play.
        let d = match mesh.partial_cmp(&0.0) {
            Some(std::cmp::Ordering::Greater) => e - b - mesh / k23,
            Some(std::cmp::Ordering::Less) => e + b - mesh / k23,
            _ => e,
        };
        let x = [t12 / k12, 0.0, d, d - t34 / k34, d - t34 / k34 - t45 / k45];
        let motor_nm = load + 5.0 * drag;
        self.u = [0.0; Layout::MAX_LEN];
        self.u[X0..X0 + 5].copy_from_slice(&x);
        self.u[Z] = if self.mc.ki_nm_per_rad > 0.0 {
            motor_nm / self.mc.ki_nm_per_rad
        } else {
            0.0
        };
        self.u[UNIT] = 1.0;
        self.u[LOAD] = load;
        let mesh = match mesh.partial_cmp(&0.0) {
            Some(std::cmp::Ordering::Greater) => MeshMode::Drive,
            Some(std::cmp::Ordering::Less) => MeshMode::Back,
            _ => MeshMode::Apart,
        };
        self.mode = Mode {
            mesh,
            pairs: PairZone::ONE,
            motor: MotorMode::Linear,
        };
        self.clamp_controller();
        self.reset_angle_targets();
    }

    /// Replaces the relative state [X1..X5, V1..V5, Vf, z] and the mesh mode (for tests
    /// and studies that start from a chosen condition).
    pub fn set_relative_state(&mut self, state: [f64; N_MECH], mesh: MeshMode) {
        self.u[..N_MECH].copy_from_slice(&state);
        self.edge = None;
        self.mode.mesh = mesh;
        self.reset_angle_targets();
    }

    /// Puts the plant, built a moment ago, at rest: the shafts twisted to carry the load
    /// at standstill, the speed knob already at the schedule's set speed, so that the
    /// speed loop and the drive's current limit run the rig up from t = 0.
    pub(crate) fn start_at_rest(&mut self) {
        let set = self.segment.set;
        self.set_steady_state(SetPoints {
            speed_rpm: 0.0,
            ..set
        });
        let omega = set.speed_rad_s();
        for v in &mut self.u[V0..V0 + 5] {
            *v -= omega;
        }
        self.u[VF] -= omega;
        self.clamp_controller();
        self.resync_harmonics(0.0);
    }

    /// A knock on the driven gear (M3): its speed changes by `delta_rad_s` at this
    /// instant, every angle and every other speed unchanged (a lab's disturbed repeat).
    /// The flanks in contact stay so; the next switch is found from the new state.
    pub fn kick_driven_gear(&mut self, delta_rad_s: f64) {
        let mut state = self.relative_state();
        state[V0 + 2] += delta_rad_s;
        self.set_relative_state(state, self.mode.mesh);
    }

    pub(super) fn reset_angle_targets(&mut self) {
        let theta2 = self.driving_gear_angle_rad(0.0);
        let pitch = self.geometry.tooth_pitch_rad;
        if let Some(index) = self.layout.spacing {
            self.u[index] = self.mc.spacing_of_tooth(self.tooth_at(theta2));
        }
        self.next_tooth_rad = ((theta2 / pitch).floor() + 1.0) * pitch;
        self.next_rev_rad = ((theta2 / TAU).floor() + 1.0) * TAU;
        self.set_zone_from_angle(0.0);
    }

    /// Simulated time (s).
    pub fn time_s(&self) -> f64 {
        self.time_at(0.0)
    }

    /// Every contact start so far.
    pub fn impacts(&self) -> &[Impact] {
        &self.impacts
    }

    /// Takes the impacts logged so far, leaving the log empty (keeps memory flat in long runs).
    pub fn drain_impacts(&mut self) -> Vec<Impact> {
        std::mem::take(&mut self.impacts)
    }

    /// Once-per-revolution samples so far.
    pub fn revolutions(&self) -> &[RevolutionSample] {
        &self.revolutions
    }

    /// Takes the revolution samples logged so far.
    pub fn drain_revolutions(&mut self) -> Vec<RevolutionSample> {
        std::mem::take(&mut self.revolutions)
    }

    /// Number of mode switches handled so far.
    pub fn switch_count(&self) -> u64 {
        self.switch_count
    }

    /// The relative state [X1..X5 (rad), V1..V5 (rad/s), Vf (rad/s), z (rad)].
    pub fn relative_state(&self) -> [f64; N_MECH] {
        std::array::from_fn(|i| self.u[i])
    }

    /// The current discrete mode.
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// The parameters the plant runs with.
    pub fn params(&self) -> &RigParams {
        &self.params
    }

    /// The plant's constants as the equations use them.
    pub fn constants(&self) -> &ModelConstants {
        &self.mc
    }

    /// Gear geometry derived from the parameters.
    pub fn geometry(&self) -> &GearGeometry {
        &self.geometry
    }

    /// Output sample period (s).
    pub fn output_step_s(&self) -> f64 {
        self.output_step_s
    }

    /// Internal steps per output sample.
    pub fn substeps(&self) -> u64 {
        self.substeps
    }

    /// Set points in force now.
    pub fn set_points(&self) -> SetPoints {
        self.segment.set
    }
}

/// The highest speed and oscillating-load frequency the plant is built for.
fn ceiling_of(schedule: &Schedule, live: Option<LiveCeiling>) -> LiveCeiling {
    let live = live.unwrap_or(LiveCeiling {
        speed_rpm: 0.0,
        oscillating_load_hz: 0.0,
    });
    LiveCeiling {
        speed_rpm: schedule.speed_rpm.range().1.max(live.speed_rpm),
        oscillating_load_hz: schedule
            .oscillating_load_hz
            .range()
            .1
            .max(live.oscillating_load_hz),
    }
}

fn check_config(config: &PlantConfig) -> Result<(), RigError> {
    if let Some(c) = config.live_ceiling {
        let speed_ok = (0.0..=MAX_SPEED_RPM).contains(&c.speed_rpm);
        if !(speed_ok && c.oscillating_load_hz.is_finite() && c.oscillating_load_hz >= 0.0) {
            return Err(RigError::InvalidOption {
                name: "live_ceiling",
                value: format!("{c:?}"),
                allowed: "a speed in [0, 10000] rev/min and a frequency ≥ 0 Hz",
            });
        }
    }
    if !takes_output_rate(config.output_rate_hz) {
        return Err(RigError::InvalidOption {
            name: "output_rate_hz",
            value: config.output_rate_hz.to_string(),
            allowed: "must lie in [100, 1e7] Hz",
        });
    }
    if !(config.setpoint_update_s.is_finite() && config.setpoint_update_s > 0.0) {
        return Err(RigError::InvalidOption {
            name: "setpoint_update_s",
            value: config.setpoint_update_s.to_string(),
            allowed: "must be a finite time > 0 s",
        });
    }
    Ok(())
}
