//! The states of a run of consecutive samples, held column by column, and the true-signal
//! columns computed from them all at once (so the per-step loop only stores states).

use crate::layout::{Layout, N_MECH, REV, V0, VF, X0, Z};
use crate::mode::{MeshMode, Mode, MotorMode};
use crate::model::ModelConstants;
use crate::signals::SignalBlock;

use super::output::flank_overlap;

/// Most samples a run of the fast path stores before they are turned into signals.
pub(super) const CHUNK: usize = 64;

/// Stored per sample: the 12 mechanical states, then cos φ and sin φ.
const STORED: usize = N_MECH + 2;
const COS: usize = N_MECH;
const SIN: usize = N_MECH + 1;

/// States of up to [`CHUNK`] consecutive samples, one array per state.
pub(super) struct StateChunk {
    columns: [[f64; CHUNK]; STORED],
}

impl StateChunk {
    /// A zeroed chunk.
    pub(super) fn new() -> Box<Self> {
        Box::new(Self {
            columns: [[0.0; CHUNK]; STORED],
        })
    }

    /// Stores the state `u` as sample `k`.
    #[inline(always)]
    pub(super) fn store(&mut self, k: usize, u: &[f64; Layout::MAX_LEN]) {
        let mut mechanical = [0.0; N_MECH];
        mechanical.copy_from_slice(&u[..N_MECH]);
        self.store_parts(k, &mechanical, u[REV], u[REV + 1]);
    }

    /// Stores sample `k` from its mechanical states and cos φ, sin φ.
    #[inline(always)]
    pub(super) fn store_parts(&mut self, k: usize, mechanical: &[f64; N_MECH], cos: f64, sin: f64) {
        for (column, &value) in self.columns[..N_MECH].iter_mut().zip(mechanical) {
            column[k] = value;
        }
        self.columns[COS][k] = cos;
        self.columns[SIN][k] = sin;
    }

    fn column(&self, index: usize, count: usize) -> &[f64] {
        &self.columns[index][..count]
    }
}

/// Everything a sample needs besides the state: mode, set rotation and gear data.
pub(super) struct SampleFrame<'a> {
    pub(super) mc: &'a ModelConstants,
    pub(super) mode: Mode,
    pub(super) speed_rad_s: f64,
    pub(super) step_s: f64,
    pub(super) segment_phase_rad: f64,
    pub(super) segment_start: u64,
    pub(super) tooth_pitch_rad: f64,
    pub(super) teeth: f64,
}

impl SampleFrame<'_> {
    /// Set rotation φ (rad) at internal step `step`.
    #[inline]
    pub(super) fn phase_rad(&self, step: u64) -> f64 {
        let elapsed = (step - self.segment_start) as f64 * self.step_s;
        self.segment_phase_rad + self.speed_rad_s * elapsed
    }

    /// Tooth of the driving gear in mesh at its angle `theta2` (rad), 0..teeth.
    #[inline]
    pub(super) fn tooth_at(&self, theta2: f64) -> u32 {
        tooth_at(theta2, self.tooth_pitch_rad, self.teeth)
    }

    /// Appends to `out` the true signals of the first `count` samples of `chunk`, taken
    /// at the consecutive internal steps from `first_step`, all in this frame's mode.
    pub(super) fn append(
        &self,
        chunk: &StateChunk,
        count: usize,
        first_step: u64,
        out: &mut SignalBlock,
    ) {
        let mut phase = [0.0; CHUNK];
        for (k, p) in phase[..count].iter_mut().enumerate() {
            *p = self.phase_rad(first_step + k as u64);
        }
        let phase = &phase[..count];
        let x = |i: usize| chunk.column(X0 + i, count);
        let v = |i: usize| chunk.column(V0 + i, count);
        let h = self.step_s;
        out.time_s
            .extend((first_step..first_step + count as u64).map(|s| s as f64 * h));
        for i in 0..5 {
            out.angle_rad[i].extend(phase.iter().zip(x(i)).map(|(p, x)| p + x));
            let omega = self.speed_rad_s;
            out.speed_rad_s[i].extend(v(i).iter().map(|v| omega + v));
        }
        for (s, (&(i, j), &k)) in self.mc.shafts().enumerate() {
            out.shaft_torque_nm[s].extend(x(i).iter().zip(x(j)).map(|(a, b)| k * (a - b)));
        }
        self.append_mesh_torque(chunk, count, out);
        self.append_motor_torque(chunk, count, out);
        let contact = self.mode.mesh.contact_code();
        out.contact.extend(std::iter::repeat_n(contact, count));
        let (pitch, teeth) = (self.tooth_pitch_rad, self.teeth);
        out.tooth.extend(
            phase
                .iter()
                .zip(x(1))
                .map(|(p, x)| tooth_at(p + x, pitch, teeth)),
        );
    }

    /// Mesh torque F_XT (N m): K δ + C δ' of the engaged flank, signed by flank.
    fn append_mesh_torque(&self, chunk: &StateChunk, count: usize, out: &mut SignalBlock) {
        let sign = match self.mode.mesh {
            MeshMode::Drive => 1.0,
            MeshMode::Back => -1.0,
            _ => {
                out.mesh_torque_nm.extend(std::iter::repeat_n(0.0, count));
                return;
            }
        };
        let (k, c) = self.mc.mesh_spring(self.mode.pairs);
        let omega = self.speed_rad_s;
        let column = |i| chunk.column(i, count);
        let (x2, x3, v2, v3) = (
            column(X0 + 1),
            column(X0 + 2),
            column(V0 + 1),
            column(V0 + 2),
        );
        let (cos, sin) = (column(COS), column(SIN));
        out.mesh_torque_nm.extend((0..count).map(|n| {
            let mesh = [x2[n], x3[n], v2[n], v3[n], cos[n], sin[n]];
            let (overlap, rate) = flank_overlap(self.mc, omega, sign, mesh);
            sign * (k * overlap + c * rate)
        }));
    }

    /// Motor torque on M1 (N m): the controller's command, or the limit it is held at.
    fn append_motor_torque(&self, chunk: &StateChunk, count: usize, out: &mut SignalBlock) {
        let limit = self.mc.torque_limit_nm;
        let held = match self.mode.motor {
            MotorMode::Linear => {
                let (kp, ki) = (self.mc.kp_nms_per_rad, self.mc.ki_nm_per_rad);
                let (vf, z) = (chunk.column(VF, count), chunk.column(Z, count));
                out.motor_torque_nm
                    .extend(vf.iter().zip(z).map(|(vf, z)| -kp * vf + ki * z));
                return;
            }
            MotorMode::LimitHigh => limit,
            MotorMode::LimitLow => -limit,
        };
        out.motor_torque_nm.extend(std::iter::repeat_n(held, count));
    }
}

/// Tooth in mesh (0..teeth) at driving-gear angle `theta2` (rad), for a pitch in rad:
/// the whole pitches below θ2, modulo the teeth, in floating point (exact for any angle
/// below 2⁵² pitches).
#[inline]
pub(super) fn tooth_at(theta2: f64, pitch_rad: f64, teeth: f64) -> u32 {
    let pitches = (theta2 / pitch_rad).floor();
    (pitches - teeth * (pitches / teeth).floor()) as u32
}
