//! The states of a run of consecutive samples, held column by column, and the true-signal
//! columns computed from them all at once (so the per-step loop only stores states).

use crate::layout::{Layout, N_MECH, REV, V0, VF, X0, Z};
use crate::mode::{MeshMode, Mode, MotorMode};
use crate::model::ModelConstants;
use crate::signals::SignalBlock;

use super::mesh_position::{flank_overlap, tooth_of_pitches};
use super::segment::Segment;

/// Most samples a run of the fast path stores before they are turned into signals.
pub(super) const CHUNK: usize = 128;

/// Stored per sample: the 12 mechanical states, then cos φ, sin φ and the spacing error
/// of the pair in mesh.
const STORED: usize = N_MECH + 3;
const COS: usize = N_MECH;
const SIN: usize = N_MECH + 1;
const SPACING: usize = N_MECH + 2;

/// States of up to [`CHUNK`] consecutive samples, one array per state.
pub(super) struct StateChunk {
    columns: [[f64; CHUNK]; STORED],
    /// Where the state holds the spacing error, if it does.
    spacing_index: Option<usize>,
}

impl StateChunk {
    /// A zeroed chunk for states laid out with the spacing error at `spacing_index`.
    pub(super) fn new(spacing_index: Option<usize>) -> Box<Self> {
        Box::new(Self {
            columns: [[0.0; CHUNK]; STORED],
            spacing_index,
        })
    }

    /// The spacing error (rad) the state `u` holds; 0 without spacing errors.
    #[inline(always)]
    pub(super) fn spacing_of(&self, u: &[f64; Layout::MAX_LEN]) -> f64 {
        self.spacing_index.map_or(0.0, |i| u[i])
    }

    /// Stores the state `u` as sample `k`.
    #[inline(always)]
    pub(super) fn store(&mut self, k: usize, u: &[f64; Layout::MAX_LEN]) {
        let mut mechanical = [0.0; N_MECH];
        mechanical.copy_from_slice(&u[..N_MECH]);
        let spacing = self.spacing_of(u);
        self.store_parts(k, &mechanical, u[REV], u[REV + 1], spacing);
    }

    /// Stores sample `k` from its mechanical states, cos φ, sin φ and the spacing error.
    #[inline(always)]
    pub(super) fn store_parts(
        &mut self,
        k: usize,
        mechanical: &[f64; N_MECH],
        cos: f64,
        sin: f64,
        spacing: f64,
    ) {
        for (column, &value) in self.columns[..N_MECH].iter_mut().zip(mechanical) {
            column[k] = value;
        }
        self.columns[COS][k] = cos;
        self.columns[SIN][k] = sin;
        // Without spacing errors the column stays zero from the start.
        if self.spacing_index.is_some() {
            self.columns[SPACING][k] = spacing;
        }
    }

    fn column(&self, index: usize, count: usize) -> &[f64] {
        &self.columns[index][..count]
    }
}

/// Everything a sample needs besides the state: mode, set rotation and gear data.
pub(super) struct SampleFrame<'a> {
    pub(super) mc: &'a ModelConstants,
    pub(super) mode: Mode,
    pub(super) segment: Segment,
    pub(super) step_s: f64,
    /// Internal steps from one sample to the next.
    pub(super) steps_per_sample: u64,
    pub(super) tooth_pitch_rad: f64,
    pub(super) teeth: f64,
}

impl SampleFrame<'_> {
    /// Appends to `out` the true signals of the first `count` samples of `chunk`, taken
    /// every `steps_per_sample` internal steps from `first_step`, all in this frame's mode.
    pub(super) fn append(
        &self,
        chunk: &StateChunk,
        count: usize,
        first_step: u64,
        out: &mut SignalBlock,
    ) {
        // Step counts as floats: exact (below 2⁵³), so φ and t are as `phase_rad` gives them.
        let elapsed = (first_step - self.segment.start_step) as f64;
        let step = first_step as f64;
        let per_sample = self.steps_per_sample as f64;
        let mut phase = [0.0; CHUNK];
        let mut time = [0.0; CHUNK];
        for ((p, t), k) in phase[..count].iter_mut().zip(&mut time).zip(COUNTS) {
            let steps = k * per_sample;
            *p = self.segment.phase_after(elapsed + steps, self.step_s);
            *t = (step + steps) * self.step_s;
        }
        let phase = &phase[..count];
        let x = |i: usize| chunk.column(X0 + i, count);
        let v = |i: usize| chunk.column(V0 + i, count);
        out.time_s.extend_from_slice(&time[..count]);
        for i in 0..5 {
            out.angle_rad[i].extend(phase.iter().zip(x(i)).map(|(p, x)| p + x));
            let omega = self.segment.set.speed_rad_s();
            out.speed_rad_s[i].extend(v(i).iter().map(|v| omega + v));
        }
        for (s, (&(i, j), &k)) in self.mc.shafts().enumerate() {
            out.shaft_torque_nm[s].extend(x(i).iter().zip(x(j)).map(|(a, b)| k * (a - b)));
        }
        self.append_mesh_torque(chunk, phase, out);
        self.append_motor_torque(chunk, count, out);
        let contact = self.mode.mesh.contact_code();
        out.contact.extend(std::iter::repeat_n(contact, count));
        self.append_teeth(phase, x(1), out);
    }

    /// The tooth in mesh at each sample: where the whole pitches below θ2 = φ + X2 are the
    /// same throughout (the tooth does not change within most runs), one value for all.
    fn append_teeth(&self, phase: &[f64], x2: &[f64], out: &mut SignalBlock) {
        let pitch = self.tooth_pitch_rad;
        let mut pitches = [0.0; CHUNK];
        for ((n, p), x) in pitches.iter_mut().zip(phase).zip(x2) {
            *n = ((p + x) / pitch).floor();
        }
        let pitches = &pitches[..phase.len()];
        let first = pitches.first().copied().unwrap_or(0.0);
        // A fold without early exit, so that it vectorises.
        if pitches.iter().fold(true, |same, &n| same & (n == first)) {
            let tooth = tooth_of_pitches(first, self.teeth);
            out.tooth.extend(std::iter::repeat_n(tooth, pitches.len()));
        } else {
            out.tooth
                .extend(pitches.iter().map(|&n| tooth_of_pitches(n, self.teeth)));
        }
    }

    /// Mesh torque F_XT (N m): K δ + C δ' of the engaged flank, signed by flank, at the
    /// samples whose set rotation is `phase` (rad).
    fn append_mesh_torque(&self, chunk: &StateChunk, phase: &[f64], out: &mut SignalBlock) {
        let count = phase.len();
        let sign = match self.mode.mesh {
            MeshMode::Drive => 1.0,
            MeshMode::Back => -1.0,
            _ => {
                out.mesh_torque_nm.extend(std::iter::repeat_n(0.0, count));
                return;
            }
        };
        let (k, c) = self.mc.mesh_spring(self.mode.pairs);
        let omega = self.segment.set.speed_rad_s();
        let column = |i| chunk.column(i, count);
        let (x2, x3, v2, v3) = (
            column(X0 + 1),
            column(X0 + 2),
            column(V0 + 1),
            column(V0 + 2),
        );
        let (cos, sin, spacing) = (column(COS), column(SIN), column(SPACING));
        let torque = MeshTorque {
            mc: self.mc,
            omega,
            sign,
            spring: (k, c),
        };
        // Two loops, so that the sine of zφ is only ever computed with a profile error.
        if self.mc.te_mesh_rad != 0.0 {
            let teeth = self.mc.teeth;
            out.mesh_torque_nm.extend((0..count).map(|n| {
                let (sin_z, cos_z) = (teeth * phase[n]).sin_cos();
                let mesh = [x2[n], x3[n], v2[n], v3[n]];
                torque.at(mesh, [cos[n], sin[n], cos_z, sin_z], spacing[n])
            }));
        } else {
            out.mesh_torque_nm.extend((0..count).map(|n| {
                let mesh = [x2[n], x3[n], v2[n], v3[n]];
                torque.at(mesh, [cos[n], sin[n], 0.0, 0.0], spacing[n])
            }));
        }
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

/// The engaged flank's mesh torque K δ + C δ' (N m), signed by flank.
struct MeshTorque<'a> {
    mc: &'a ModelConstants,
    omega: f64,
    sign: f64,
    spring: (f64, f64),
}

impl MeshTorque<'_> {
    /// At the gears' `mesh` = [X2, X3, V2, V3], the `harmonics` and the pair's spacing error.
    #[inline(always)]
    fn at(&self, mesh: [f64; 4], harmonics: [f64; 4], spacing_rad: f64) -> f64 {
        let (overlap, rate) =
            flank_overlap(self.mc, self.omega, self.sign, mesh, harmonics, spacing_rad);
        self.sign * (self.spring.0 * overlap + self.spring.1 * rate)
    }
}

/// 0, 1, 2, … as floats: the offsets of the samples in a chunk.
const COUNTS: [f64; CHUNK] = {
    let mut counts = [0.0; CHUNK];
    let mut k = 0;
    while k < CHUNK {
        counts[k] = k as f64;
        k += 1;
    }
    counts
};
