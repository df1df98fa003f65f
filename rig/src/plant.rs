//! The plant: state, set points and the stepping loop that is exact at every switch.
//!
//! Between switches the equations are linear with constant and harmonic forcing, so a
//! whole internal step is one product with e^{A h} (computed once per mode). Every
//! switching function is checked on each step from its values and slopes at both ends;
//! where it may cross, the step is redone on the Taylor expansion of e^{A τ} (exact to
//! rounding for ρh ≤ 0.5), the first crossing is found to full precision, the mode
//! switches there, and the step continues from that instant.

use std::f64::consts::TAU;

use crate::error::RigError;
use crate::events::{EventFlags, EventFn, EventKind, first_crossing, may_cross};
use crate::geometry::GearGeometry;
use crate::layout::{LOAD, Layout, N_MECH, REV, UNIT, V0, VF, X0, Z};
use crate::mode::{MeshMode, Mode, MotorMode, PairZone};
use crate::model::{Frequencies, ModelConstants};
use crate::options::{ContactLaw, MeshPairs};
use crate::params::RigParams;
use crate::propagator::{
    FUSED_ROWS, FusedRows, MAX_ROW_EVENTS, ModeSystem, TAYLOR_ORDER, TaylorVectors,
};
use crate::records::{Flank, Impact, RevolutionSample};
use crate::schedule::{Schedule, SetPoints};
use crate::signals::{Sample, SignalBlock};
use crate::system_cache::SystemCache;

/// Output and set-point timing of a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlantConfig {
    /// Rate of the true signals (Hz).
    pub output_rate_hz: f64,
    /// During a ramp the set points change in steps this long (s).
    pub setpoint_update_s: f64,
}

impl Default for PlantConfig {
    fn default() -> Self {
        Self {
            output_rate_hz: 51_200.0,
            setpoint_update_s: 0.01,
        }
    }
}

/// Most switches handled within one internal step before the run is declared chattering.
pub const SWITCH_LIMIT: usize = 64;

/// Largest relative twist (rad) or relative speed (rad/s) the state may reach before the
/// run is declared blown up: far beyond anything the shafts or gears could bear.
const TWIST_LIMIT_RAD: f64 = 1.0;
const SPEED_LIMIT_RAD_S: f64 = 1.0e4;

/// Samples gathered on the stack before they are appended to a block column by column.
const CHUNK: usize = 64;

/// Internal steps between exact re-syncs of the harmonic states from the phase.
const RESYNC_STEPS: u64 = 4096;

/// The set points held over the current stretch of internal steps.
#[derive(Clone, Copy, Debug)]
struct Segment {
    start_step: u64,
    end_step: Option<u64>,
    phase_rad: f64,
    osc_phase_rad: f64,
    set: SetPoints,
}

/// The five-inertia rig with backlash, advanced in virtual time.
pub struct Plant {
    params: RigParams,
    mc: ModelConstants,
    geometry: GearGeometry,
    schedule: Schedule,
    layout: Layout,
    law: ContactLaw,
    flags: EventFlags,
    output_step_s: f64,
    substeps: u64,
    step_s: f64,
    setpoint_update_s: f64,
    cache: SystemCache,
    u: [f64; Layout::MAX_LEN],
    mode: Mode,
    step_index: u64,
    segment: Segment,
    zone_index: i64,
    next_tooth_rad: f64,
    next_rev_rad: f64,
    taylor: Box<TaylorVectors>,
    /// Row events' values and slopes at the current state, when known from the last fast step.
    edge: Option<[f64; 2 * MAX_ROW_EVENTS]>,
    impacts: Vec<Impact>,
    revolutions: Vec<RevolutionSample>,
    switch_count: u64,
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
        let layout = Layout::new(
            params.gear_error_c3_nm != 0.0,
            schedule.has_oscillating_load(),
        );
        let alternating =
            params.mesh_pairs == MeshPairs::Alternating && geometry.double_pair_fraction() > 0.0;
        let flags = EventFlags {
            alternating_pairs: alternating && geometry.double_pair_fraction() < 1.0,
            tooth_shifting: params.tooth_shifting,
        };
        let output_step_s = 1.0 / config.output_rate_hz;
        let substeps = SystemCache::substeps_for(&mc, &layout, &schedule, output_step_s);
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
            geometry,
            schedule,
            layout,
            law,
            flags,
            output_step_s,
            substeps,
            step_s,
            setpoint_update_s: config.setpoint_update_s,
            u: [0.0; Layout::MAX_LEN],
            mode: Mode {
                mesh: MeshMode::Apart,
                pairs: PairZone::One,
                motor: MotorMode::Linear,
            },
            step_index: 0,
            segment,
            zone_index: 0,
            next_tooth_rad: 0.0,
            next_rev_rad: 0.0,
            taylor: Box::new([[0.0; Layout::MAX_LEN]; TAYLOR_ORDER + 1]),
            edge: None,
            impacts: Vec::new(),
            revolutions: Vec::new(),
            switch_count: 0,
        };
        plant.set_steady_state(set);
        plant.begin_segment();
        Ok(plant)
    }

    /// Steady state at `set`: no vibration, every shaft carrying the load.
    fn set_steady_state(&mut self, set: SetPoints) {
        let load = set.load_nm;
        let [k12, k34, k45] = self.mc.shaft_stiffness_nm_per_rad;
        let b = self.mc.half_backlash_rad * (1.0 - self.mc.backlash_variation);
        let k23 = self.mc.mesh_stiffness_nm_per_rad;
        // Loaded: on the loaded flank; unloaded: centred in the free play.
        let d = match load.partial_cmp(&0.0) {
            Some(std::cmp::Ordering::Greater) => -b - load / k23,
            Some(std::cmp::Ordering::Less) => b - load / k23,
            _ => 0.0,
        };
        let x = [
            load / k12,
            0.0,
            d,
            d - load / k34,
            d - load / k34 - load / k45,
        ];
        self.u = [0.0; Layout::MAX_LEN];
        self.u[X0..X0 + 5].copy_from_slice(&x);
        self.u[Z] = if self.mc.ki_nm_per_rad > 0.0 {
            load / self.mc.ki_nm_per_rad
        } else {
            0.0
        };
        self.u[UNIT] = 1.0;
        self.u[LOAD] = load;
        let mesh = match load.partial_cmp(&0.0) {
            Some(std::cmp::Ordering::Greater) => MeshMode::Drive,
            Some(std::cmp::Ordering::Less) => MeshMode::Back,
            _ => MeshMode::Apart,
        };
        let motor = if load > self.mc.torque_limit_nm {
            MotorMode::LimitHigh
        } else if load < -self.mc.torque_limit_nm {
            MotorMode::LimitLow
        } else {
            MotorMode::Linear
        };
        self.mode = Mode {
            mesh,
            pairs: PairZone::One,
            motor,
        };
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

    fn reset_angle_targets(&mut self) {
        let theta2 = self.driving_gear_angle_rad(0.0);
        let pitch = self.geometry.tooth_pitch_rad;
        self.next_tooth_rad = ((theta2 / pitch).floor() + 1.0) * pitch;
        self.next_rev_rad = ((theta2 / TAU).floor() + 1.0) * TAU;
        self.set_zone_from_angle(0.0);
    }

    /// Advances `samples` output samples, appending each (the state at t = n / rate, then one step) to `out`.
    /// On an error the block keeps every sample taken before it.
    pub fn run(&mut self, samples: usize, out: &mut SignalBlock) -> Result<(), RigError> {
        let mut chunk = [self.sample(); CHUNK];
        let mut done = 0;
        while done < samples {
            let n = CHUNK.min(samples - done);
            let mut taken = 0;
            let mut result = Ok(());
            while taken < n {
                result = self.take_sample(&mut chunk[taken]);
                if result.is_err() {
                    break;
                }
                taken += 1;
            }
            out.extend_from_samples(&chunk[..taken]);
            result?;
            done += n;
        }
        Ok(())
    }

    /// Stores the sample now in `slot`, then advances one output period.
    #[inline]
    fn take_sample(&mut self, slot: &mut Sample) -> Result<(), RigError> {
        if !self.within_bounds() {
            return Err(self.blow_up());
        }
        *slot = self.sample();
        for _ in 0..self.substeps {
            self.advance_step()?;
        }
        Ok(())
    }

    /// Advances `samples` output samples without recording them.
    pub fn skip(&mut self, samples: usize) -> Result<(), RigError> {
        for _ in 0..samples {
            if !self.within_bounds() {
                return Err(self.blow_up());
            }
            for _ in 0..self.substeps {
                self.advance_step()?;
            }
        }
        Ok(())
    }

    /// One internal step, handling every switch inside it.
    fn advance_step(&mut self) -> Result<(), RigError> {
        if Some(self.step_index) == self.segment.end_step {
            self.begin_segment();
        } else if self.step_index.is_multiple_of(RESYNC_STEPS) {
            self.resync_harmonics(0.0);
        }
        self.cache.ensure(self.mode);
        let system = self.cache.built(self.mode);
        let fused = system.step(&self.u);
        let start = self
            .edge
            .unwrap_or_else(|| system.row_event_values(&self.u));
        if self.may_switch(system, &start, &fused) {
            self.edge = None;
            self.advance_exactly()?;
        } else {
            self.u[..N_MECH].copy_from_slice(&fused[..N_MECH]);
            let rotations = self.cache.rotations();
            rotate(&mut self.u, rotations);
            let mut edge = [0.0; 2 * MAX_ROW_EVENTS];
            edge.copy_from_slice(&fused[N_MECH..FUSED_ROWS]);
            self.edge = Some(edge);
        }
        self.step_index += 1;
        Ok(())
    }

    /// Whether any switching function may cross within a whole step, from the row events'
    /// values and slopes at the step's start (`start`) and end (`end`, from the fused step),
    /// and the driving gear's angle at both ends.
    fn may_switch(
        &self,
        system: &ModeSystem,
        start: &[f64; 2 * MAX_ROW_EVENTS],
        end: &FusedRows,
    ) -> bool {
        let h = self.step_s;
        let n = system.row_events.len();
        for j in 0..n {
            let g1 = end[N_MECH + j];
            if g1 > 0.0 {
                return true;
            }
            let d1 = end[N_MECH + n + j] * h;
            // ≤ 0 at both ends and rising at the end: no interior maximum.
            if d1 < 0.0 && may_cross(start[j].min(0.0), start[n + j] * h, g1, d1) {
                return true;
            }
        }
        let omega = self.segment.set.speed_rad_s();
        let phase = self.phase_rad(0.0);
        let theta0 = phase + self.u[X0 + 1];
        let theta1 = phase + omega * h + end[X0 + 1];
        let (rate0, rate1) = (omega + self.u[V0 + 1], omega + end[V0 + 1]);
        system.angle_events.iter().any(|&k| {
            let event = &system.events[k];
            let sign = event.angle_sign;
            let target = self.angle_target(event.kind);
            let g1 = sign * (theta1 - target);
            if g1 > 0.0 {
                return true;
            }
            let d1 = sign * rate1 * h;
            d1 < 0.0
                && may_cross(
                    (sign * (theta0 - target)).min(0.0),
                    sign * rate0 * h,
                    g1,
                    d1,
                )
        })
    }

    fn event_may_cross(
        &self,
        event: &EventFn,
        u0: &[f64],
        u1: &[f64],
        tau_s: f64,
        delta_s: f64,
    ) -> bool {
        let (offset, rate) = self.angle_terms(event.kind, event.angle_sign, tau_s);
        let g1 = event.value.dot(u1) + offset + rate * delta_s;
        if g1 > 0.0 {
            return true;
        }
        let g0 = event.value.dot(u0) + offset;
        let d0 = (event.slope.dot(u0) + rate) * delta_s;
        let d1 = (event.slope.dot(u1) + rate) * delta_s;
        may_cross(g0.min(0.0), d0, g1, d1)
    }

    /// Offset and rate of an angle event's φ term at `tau_s` into the step: sign·(φ − target), sign·Ω.
    fn angle_terms(&self, kind: EventKind, sign: f64, tau_s: f64) -> (f64, f64) {
        if sign == 0.0 {
            return (0.0, 0.0);
        }
        let phase = self.phase_rad(tau_s);
        (
            sign * (phase - self.angle_target(kind)),
            sign * self.segment.set.speed_rad_s(),
        )
    }

    /// The driving-gear angle an angle event waits for (rad).
    fn angle_target(&self, kind: EventKind) -> f64 {
        match kind {
            EventKind::ToothPass => self.next_tooth_rad,
            EventKind::Revolution => self.next_rev_rad,
            EventKind::ZoneEnd => self.zone_bounds().1,
            EventKind::ZoneStart => self.zone_bounds().0,
            _ => 0.0,
        }
    }

    /// Redoes the current step on the Taylor expansion, switching at every crossing.
    fn advance_exactly(&mut self) -> Result<(), RigError> {
        let mut tau = 0.0;
        for _ in 0..SWITCH_LIMIT {
            let delta = self.step_s - tau;
            self.cache.ensure(self.mode);
            let system = self.cache.built(self.mode);
            let order = system.taylor(&self.u, delta, &mut self.taylor);
            let mut end = [0.0; Layout::MAX_LEN];
            system.taylor_state(&self.taylor, order, 1.0, &mut end);
            match self.first_event(system, &end, order, tau, delta) {
                None => {
                    self.u = end;
                    return Ok(());
                }
                Some((s, kind)) => {
                    let mut at = [0.0; Layout::MAX_LEN];
                    system.taylor_state(&self.taylor, order, s, &mut at);
                    self.u = at;
                    tau += s * delta;
                    self.switch_count += 1;
                    self.handle(kind, tau);
                }
            }
        }
        Err(RigError::Chatter {
            t_s: self.time_at(tau),
            limit: SWITCH_LIMIT,
        })
    }

    /// The earliest crossing (fraction s of the remaining `delta_s`, kind) of any switching
    /// function, given the Taylor vectors from the state now and the state `end` at `delta_s`.
    fn first_event(
        &self,
        system: &ModeSystem,
        end: &[f64],
        order: usize,
        tau_s: f64,
        delta_s: f64,
    ) -> Option<(f64, EventKind)> {
        let mut best: Option<(f64, EventKind)> = None;
        let mut buffer = [0.0; TAYLOR_ORDER + 1];
        let coeffs = &mut buffer[..=order];
        for event in &system.events {
            if !self.event_may_cross(event, &self.u, end, tau_s, delta_s) {
                continue;
            }
            for (c, v) in coeffs.iter_mut().zip(self.taylor.iter()) {
                *c = event.value.dot(v);
            }
            let (offset, rate) = self.angle_terms(event.kind, event.angle_sign, tau_s);
            coeffs[0] += offset;
            coeffs[1] += rate * delta_s;
            if let Some(s) = first_crossing(coeffs)
                && best.is_none_or(|(b, _)| s < b)
            {
                best = Some((s, event.kind));
            }
        }
        best
    }

    /// Applies the consequences of a crossing at `tau_s` into the current step.
    fn handle(&mut self, kind: EventKind, tau_s: f64) {
        match kind {
            EventKind::TouchDrive => self.touch(Flank::Drive, tau_s),
            EventKind::TouchBack => self.touch(Flank::Back, tau_s),
            EventKind::LeaveDrive | EventKind::LeaveBack => self.set_mesh(MeshMode::Apart, tau_s),
            EventKind::DriveUnloads => self.set_mesh(MeshMode::DriveClipped, tau_s),
            EventKind::DriveReloads => self.set_mesh(MeshMode::Drive, tau_s),
            EventKind::BackUnloads => self.set_mesh(MeshMode::BackClipped, tau_s),
            EventKind::BackReloads => self.set_mesh(MeshMode::Back, tau_s),
            EventKind::ZoneEnd => self.move_zone(1),
            EventKind::ZoneStart => self.move_zone(-1),
            EventKind::LimitHigh => self.mode.motor = MotorMode::LimitHigh,
            EventKind::LimitLow => self.mode.motor = MotorMode::LimitLow,
            EventKind::LimitRelease => self.mode.motor = MotorMode::Linear,
            EventKind::ToothPass => self.tooth_pass(tau_s),
            EventKind::Revolution => self.revolution(tau_s),
        }
    }

    fn touch(&mut self, flank: Flank, tau_s: f64) {
        let (gap, closing) = self.gap(flank, tau_s);
        debug_assert!(gap.abs() < 1e-9);
        let theta2 = self.driving_gear_angle_rad(tau_s);
        self.impacts.push(Impact {
            time_s: self.time_at(tau_s),
            flank,
            tooth: self.tooth_at(theta2),
            closing_speed_rad_s: closing,
        });
        let mesh = match flank {
            Flank::Drive => MeshMode::Drive,
            Flank::Back => MeshMode::Back,
        };
        self.set_mesh(mesh, tau_s);
    }

    /// Overlap of `flank` (rad, > 0 when the teeth overlap) and its rate (rad/s) at `tau_s`.
    fn gap(&self, flank: Flank, tau_s: f64) -> (f64, f64) {
        // The harmonic states hold cos φ and sin φ at this instant.
        let _ = tau_s;
        let u = &self.u;
        let omega = self.segment.set.speed_rad_s();
        let b0 = self.mc.half_backlash_rad;
        let c1 = self.mc.backlash_variation;
        let b = b0 * (1.0 - c1 * u[REV]);
        let b_rate = b0 * c1 * omega * u[REV + 1];
        let d = u[X0 + 2] - u[X0 + 1];
        let d_rate = u[V0 + 2] - u[V0 + 1];
        match flank {
            Flank::Drive => (-d - b, -d_rate - b_rate),
            Flank::Back => (d - b, d_rate - b_rate),
        }
    }

    fn set_mesh(&mut self, mesh: MeshMode, tau_s: f64) {
        self.mode.mesh = mesh;
        self.set_zone_from_angle(tau_s);
    }

    /// Thesis §5.4.5: at each tooth pass a loaded pair hands its deflection back, so that
    /// the new pair starts undeflected (X2, X3 each move by half the overlap).
    fn tooth_pass(&mut self, tau_s: f64) {
        self.next_tooth_rad += self.geometry.tooth_pitch_rad;
        let flank = match self.mode.mesh {
            MeshMode::Drive | MeshMode::DriveClipped => Flank::Drive,
            MeshMode::Back | MeshMode::BackClipped => Flank::Back,
            MeshMode::Apart => return,
        };
        let (overlap, _) = self.gap(flank, tau_s);
        let half = 0.5 * overlap.max(0.0);
        let sign = if flank == Flank::Drive { 1.0 } else { -1.0 };
        self.u[X0 + 2] += sign * half;
        self.u[X0 + 1] -= sign * half;
        let (_, closing) = self.gap(flank, tau_s);
        let force = closing * self.mc.mesh_spring(self.mode.pairs).1;
        let mesh = match (
            flank,
            closing > 0.0,
            self.law == ContactLaw::NoPull && force <= 0.0,
        ) {
            (_, false, _) => MeshMode::Apart,
            (Flank::Drive, true, false) => MeshMode::Drive,
            (Flank::Drive, true, true) => MeshMode::DriveClipped,
            (Flank::Back, true, false) => MeshMode::Back,
            (Flank::Back, true, true) => MeshMode::BackClipped,
        };
        self.set_mesh(mesh, tau_s);
    }

    fn revolution(&mut self, tau_s: f64) {
        self.next_rev_rad += TAU;
        let mut state = [0.0; 10];
        state.copy_from_slice(&self.u[..10]);
        self.revolutions.push(RevolutionSample {
            time_s: self.time_at(tau_s),
            state,
            shaft_torque_nm: self.mc.shaft_torques_nm(&self.u)[1],
        });
    }

    /// Pair zones alternate along θ2: zone 2k is [kp, kp + fp) with two pairs, zone 2k+1
    /// [kp + fp, (k+1)p) with one, f = ε − 1.
    fn zone_bounds(&self) -> (f64, f64) {
        let pitch = self.geometry.tooth_pitch_rad;
        let f = self.geometry.double_pair_fraction();
        let k = self.zone_index.div_euclid(2) as f64;
        if self.zone_index.rem_euclid(2) == 0 {
            (k * pitch, (k + f) * pitch)
        } else {
            ((k + f) * pitch, (k + 1.0) * pitch)
        }
    }

    fn set_zone_from_angle(&mut self, tau_s: f64) {
        let engaged = matches!(self.mode.mesh, MeshMode::Drive | MeshMode::Back);
        if !(self.flags.alternating_pairs && engaged) {
            self.mode.pairs = PairZone::One;
            return;
        }
        let pitch = self.geometry.tooth_pitch_rad;
        let theta2 = self.driving_gear_angle_rad(tau_s);
        let k = (theta2 / pitch).floor();
        let in_double = theta2 - k * pitch < self.geometry.double_pair_fraction() * pitch;
        self.zone_index = 2 * k as i64 + i64::from(!in_double);
        self.apply_zone();
    }

    fn move_zone(&mut self, by: i64) {
        self.zone_index += by;
        self.apply_zone();
    }

    fn apply_zone(&mut self) {
        self.mode.pairs = if self.zone_index.rem_euclid(2) == 0 {
            PairZone::Two
        } else {
            PairZone::One
        };
    }

    /// Starts a new stretch of constant set points at the current step.
    fn begin_segment(&mut self) {
        let t = self.time_at(0.0);
        let next_knot = self.schedule.next_knot_after(t);
        let ramping = self.schedule.ramping_at(t);
        let end = match (ramping, next_knot) {
            (true, Some(knot)) => Some(knot.min(t + self.setpoint_update_s)),
            (true, None) => Some(t + self.setpoint_update_s),
            (false, knot) => knot,
        };
        let set = self.schedule.held_over(t, end.map_or(0.0, |e| e - t));
        let old = self.segment;
        let delta_speed = set.speed_rad_s() - old.set.speed_rad_s();
        for v in &mut self.u[V0..V0 + 5] {
            *v -= delta_speed;
        }
        self.u[VF] -= delta_speed;
        self.u[LOAD] = set.load_nm;
        let frequencies_changed =
            delta_speed != 0.0 || set.oscillating_load_hz != old.set.oscillating_load_hz;
        self.segment = Segment {
            start_step: self.step_index,
            end_step: end
                .map(|e| ((e / self.step_s - 1e-6).ceil() as u64).max(self.step_index + 1)),
            phase_rad: self.phase_rad(0.0),
            osc_phase_rad: self.osc_phase_rad(0.0),
            set,
        };
        if frequencies_changed || self.step_index == 0 {
            self.cache.set_frequencies(Frequencies {
                rotation_rad_s: set.speed_rad_s(),
                oscillating_load_rad_s: set.oscillating_load_rad_s(),
            });
        }
        self.resync_harmonics(0.0);
    }

    /// Sets the harmonic states from the exact phases at `tau_s` into the step.
    fn resync_harmonics(&mut self, tau_s: f64) {
        self.edge = None;
        let phase = self.phase_rad(tau_s);
        self.u[REV] = phase.cos();
        self.u[REV + 1] = phase.sin();
        if let Some(rev2) = self.layout.rev2 {
            self.u[rev2] = (2.0 * phase).cos();
            self.u[rev2 + 1] = (2.0 * phase).sin();
        }
        if let Some(osc) = self.layout.osc {
            let psi = self.osc_phase_rad(tau_s);
            let amplitude = self.segment.set.oscillating_load_nm;
            self.u[osc] = amplitude * psi.cos();
            self.u[osc + 1] = amplitude * psi.sin();
        }
    }

    /// Time of the current step's start plus `tau_s` (s).
    fn time_at(&self, tau_s: f64) -> f64 {
        self.step_index as f64 * self.step_s + tau_s
    }

    /// Set rotation φ (rad) at `tau_s` into the current step.
    fn phase_rad(&self, tau_s: f64) -> f64 {
        let elapsed = (self.step_index - self.segment.start_step) as f64 * self.step_s + tau_s;
        self.segment.phase_rad + self.segment.set.speed_rad_s() * elapsed
    }

    fn osc_phase_rad(&self, tau_s: f64) -> f64 {
        let elapsed = (self.step_index - self.segment.start_step) as f64 * self.step_s + tau_s;
        self.segment.osc_phase_rad + self.segment.set.oscillating_load_rad_s() * elapsed
    }

    /// Absolute angle of the driving gear θ2 = φ + X2 (rad) at `tau_s` into the step.
    fn driving_gear_angle_rad(&self, tau_s: f64) -> f64 {
        self.phase_rad(tau_s) + self.u[X0 + 1]
    }

    fn tooth_at(&self, theta2: f64) -> u32 {
        let teeth = i64::from(self.params.teeth);
        ((theta2 / self.geometry.tooth_pitch_rad).floor() as i64).rem_euclid(teeth) as u32
    }

    /// The true signals now.
    pub fn sample(&self) -> Sample {
        let u = &self.u;
        let phase = self.phase_rad(0.0);
        let omega = self.segment.set.speed_rad_s();
        Sample {
            time_s: self.time_at(0.0),
            angle_rad: std::array::from_fn(|i| phase + u[X0 + i]),
            speed_rad_s: std::array::from_fn(|i| omega + u[V0 + i]),
            shaft_torque_nm: self.mc.shaft_torques_nm(u),
            mesh_torque_nm: self.mesh_torque_nm(),
            motor_torque_nm: self.motor_torque_nm(),
            contact: self.mode.mesh.contact_code(),
            tooth: self.tooth_at(phase + u[X0 + 1]),
        }
    }

    /// Mesh torque F_XT on the driven gear (N m).
    pub fn mesh_torque_nm(&self) -> f64 {
        let (k, c) = self.mc.mesh_spring(self.mode.pairs);
        let push = |(overlap, rate): (f64, f64)| k * overlap + c * rate;
        match self.mode.mesh {
            MeshMode::Drive => push(self.gap(Flank::Drive, 0.0)),
            MeshMode::Back => -push(self.gap(Flank::Back, 0.0)),
            _ => 0.0,
        }
    }

    /// Motor torque on M1 (N m).
    pub fn motor_torque_nm(&self) -> f64 {
        match self.mode.motor {
            MotorMode::Linear => self.mc.controller_torque_nm(&self.u),
            MotorMode::LimitHigh => self.mc.torque_limit_nm,
            MotorMode::LimitLow => -self.mc.torque_limit_nm,
        }
    }

    /// Whether the state is finite, every twist within 1 rad and every relative speed within 10⁴ rad/s.
    #[inline]
    fn within_bounds(&self) -> bool {
        let u = &self.u;
        let twist_ok = (0..4).all(|i| (u[X0 + i] - u[X0 + i + 1]).abs() <= TWIST_LIMIT_RAD);
        let speed_ok = (0..5).all(|i| u[V0 + i].abs() <= SPEED_LIMIT_RAD_S);
        twist_ok && speed_ok && u[VF].is_finite() && u[Z].is_finite()
    }

    /// The error for a state that left its bounds, saying which bound.
    #[cold]
    fn blow_up(&self) -> RigError {
        let u = &self.u;
        let reason = if !u[..N_MECH].iter().all(|v| v.is_finite()) {
            "the state is no longer finite".to_string()
        } else if (0..4).any(|i| (u[X0 + i] - u[X0 + i + 1]).abs() > TWIST_LIMIT_RAD) {
            format!("a shaft or the mesh is twisted by more than {TWIST_LIMIT_RAD} rad")
        } else {
            format!("a speed departs from the set speed by more than {SPEED_LIMIT_RAD_S} rad/s")
        };
        RigError::BlowUp {
            t_s: self.time_at(0.0),
            reason,
            state: u[..10].to_vec(),
        }
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

fn check_config(config: &PlantConfig) -> Result<(), RigError> {
    if !(config.output_rate_hz.is_finite()
        && config.output_rate_hz >= 100.0
        && config.output_rate_hz <= 10.0e6)
    {
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

/// Turns each harmonic pair of `u` by one step: (index of the cos state, cos ωh, sin ωh).
fn rotate(u: &mut [f64; Layout::MAX_LEN], rotations: &[(usize, f64, f64)]) {
    for &(index, cos, sin) in rotations {
        let (c, s) = (u[index], u[index + 1]);
        u[index] = c * cos - s * sin;
        u[index + 1] = s * cos + c * sin;
    }
}
