//! What each switch does: contact starts (impacts), separations, clipped torque, pair
//! zones, motor limits, tooth shifting and revolution samples.

use std::f64::consts::TAU;

use crate::events::EventKind;
use crate::layout::{X0, Z};
use crate::mode::{MeshMode, MotorMode, PairZone};
use crate::options::ContactLaw;
use crate::records::{Flank, Impact, RevolutionSample};

use super::output::flank_gap;
use super::state::Plant;

/// How far inside the torque limit a released controller command starts (N m): far above
/// the rounding of the command (~1e-13 N m), far below anything measurable.
pub const RELEASE_MARGIN_NM: f64 = 1e-9;

impl Plant {
    /// Applies the consequences of a crossing at `tau_s` into the current step.
    pub(super) fn handle(&mut self, kind: EventKind, tau_s: f64) {
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
            EventKind::LimitRelease => self.release_controller(),
            EventKind::ToothPass => self.tooth_pass(tau_s),
            EventKind::Revolution => self.revolution(tau_s),
        }
    }

    pub(super) fn touch(&mut self, flank: Flank, tau_s: f64) {
        debug_assert!(self.gap(flank).0.abs() < 1e-9);
        self.engage(flank, tau_s);
    }

    /// A contact start on `flank` now: logged as an impact with its closing speed, and
    /// the mesh engaged.
    fn engage(&mut self, flank: Flank, tau_s: f64) {
        let (_, closing) = self.gap(flank);
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
        self.catch_up_tooth_pass(theta2);
        self.set_mesh(mesh, tau_s);
    }

    /// Moves the next tooth pass past the teeth that passed while the gears were apart
    /// (apart, a pass changes nothing, so it is not tracked as an event): the first
    /// multiple of the pitch above the driving gear's angle `theta2`, never backwards.
    fn catch_up_tooth_pass(&mut self, theta2: f64) {
        let pitch = self.geometry.tooth_pitch_rad;
        let ahead = ((theta2 / pitch).floor() + 1.0) * pitch;
        self.next_tooth_rad = self.next_tooth_rad.max(ahead);
    }

    /// Overlap of `flank` (rad, > 0 when the teeth overlap) and its rate (rad/s) now.
    pub(super) fn gap(&self, flank: Flank) -> (f64, f64) {
        flank_gap(
            &self.mc,
            &self.layout,
            self.segment.set.speed_rad_s(),
            &self.u,
            flank,
        )
    }

    pub(super) fn set_mesh(&mut self, mesh: MeshMode, tau_s: f64) {
        self.mode.mesh = mesh;
        self.set_zone_from_angle(tau_s);
    }

    /// A tooth pass: the next pair comes into mesh. With spacing errors its error
    /// replaces the last pair's (the flanks' overlap jumps by the difference: a pair that
    /// stands proud strikes at once, one that stands back lets go). With the thesis's
    /// numerical tooth shifting (§5.4.5) a loaded pair hands its deflection back, so that
    /// the new pair starts undeflected (X2, X3 each move by half the overlap).
    pub(super) fn tooth_pass(&mut self, tau_s: f64) {
        let pitch = self.geometry.tooth_pitch_rad;
        let entering = self.tooth_at(self.next_tooth_rad + 0.5 * pitch);
        self.next_tooth_rad += pitch;
        if let Some(index) = self.layout.spacing {
            self.u[index] = self.mc.spacing_of_tooth(entering);
        }
        let flank = match self.mode.mesh {
            MeshMode::Drive | MeshMode::DriveClipped => Flank::Drive,
            MeshMode::Back | MeshMode::BackClipped => Flank::Back,
            MeshMode::Apart => return self.engage_if_overlapping(tau_s),
        };
        let (overlap, rate) = self.gap(flank);
        let (still_touching, force) = if self.flags.tooth_shifting {
            let half = 0.5 * overlap.max(0.0);
            let sign = if flank == Flank::Drive { 1.0 } else { -1.0 };
            self.u[X0 + 2] += sign * half;
            self.u[X0 + 1] -= sign * half;
            let (_, closing) = self.gap(flank);
            (
                closing > 0.0,
                closing * self.mc.mesh_spring(self.mode.pairs).1,
            )
        } else {
            let (k, c) = self.mc.mesh_spring(self.mode.pairs);
            (
                overlap > 0.0 || (overlap == 0.0 && rate > 0.0),
                k * overlap + c * rate,
            )
        };
        let mesh = match (
            flank,
            still_touching,
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

    /// Apart at a tooth pass whose new pair stands proud of a flank: it strikes now.
    fn engage_if_overlapping(&mut self, tau_s: f64) {
        for flank in [Flank::Drive, Flank::Back] {
            if self.gap(flank).0 > 0.0 {
                return self.engage(flank, tau_s);
            }
        }
    }

    /// Puts the speed controller in the mode its command calls for after a jump (a speed
    /// set-point step, the start): beyond a limit, the output clamp holds the command at
    /// the limit, so the integrator takes the value that puts it there.
    pub(super) fn clamp_controller(&mut self) {
        let command = self.mc.controller_torque_nm(&self.u);
        let limit = self.mc.torque_limit_nm;
        let (motor, held) = if command >= limit {
            (MotorMode::LimitHigh, limit)
        } else if command <= -limit {
            (MotorMode::LimitLow, -limit)
        } else {
            (MotorMode::Linear, command)
        };
        if self.mc.ki_nm_per_rad > 0.0 {
            self.u[Z] += (held - command) / self.mc.ki_nm_per_rad;
        }
        self.mode.motor = motor;
    }

    /// Leaves the limit: the command, held there up to rounding, starts just inside it
    /// (by [`RELEASE_MARGIN_NM`]) so that rounding cannot put it straight back.
    fn release_controller(&mut self) {
        let limit = self.mc.torque_limit_nm;
        let inside = match self.mode.motor {
            MotorMode::LimitHigh => limit - RELEASE_MARGIN_NM,
            MotorMode::LimitLow => -limit + RELEASE_MARGIN_NM,
            MotorMode::Linear => return,
        };
        if self.mc.ki_nm_per_rad > 0.0 {
            let command = self.mc.controller_torque_nm(&self.u);
            self.u[Z] += (inside - command) / self.mc.ki_nm_per_rad;
        }
        self.mode.motor = MotorMode::Linear;
    }

    pub(super) fn revolution(&mut self, tau_s: f64) {
        self.next_rev_rad += TAU;
        let mut state = [0.0; 10];
        state.copy_from_slice(&self.u[..10]);
        self.revolutions.push(RevolutionSample {
            time_s: self.time_at(tau_s),
            state,
            shaft_torque_nm: self.mc.shaft_torques_nm(&self.u)[1],
        });
    }

    /// Start and end (rad of θ2) of the current pair zone (see [`crate::pair_zones`]).
    pub(super) fn zone_bounds(&self) -> (f64, f64) {
        let pitch = self.geometry.tooth_pitch_rad;
        let (start, end) = self.zones.bounds(self.zone_index);
        (start * pitch, end * pitch)
    }

    pub(super) fn set_zone_from_angle(&mut self, tau_s: f64) {
        let engaged = matches!(self.mode.mesh, MeshMode::Drive | MeshMode::Back);
        if !(self.flags.alternating_pairs && engaged) {
            self.mode.pairs = PairZone::ONE;
            return;
        }
        let theta2 = self.driving_gear_angle_rad(tau_s);
        self.zone_index = self.zones.zone_at(theta2 / self.geometry.tooth_pitch_rad);
        self.apply_zone();
    }

    pub(super) fn move_zone(&mut self, by: i64) {
        self.zone_index += by;
        self.apply_zone();
    }

    pub(super) fn apply_zone(&mut self) {
        self.mode.pairs = self.zones.level(self.zone_index);
    }
}
