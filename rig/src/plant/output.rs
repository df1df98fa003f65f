//! The samples a run writes: each sample's state stored column by column in a chunk, and
//! the block's signals computed from a whole chunk at once. In one mode (and one stretch
//! of set points) every signal is a linear form of the state: a body's angle and speed, a
//! shaft's torque, a mesh's force, the motor's torque. So each signal is a few sums over
//! the chunk in whole vectors (written one sample at a time, the signals cost the plant
//! as much as its steps): those of the mode over each mode's samples, the rest over the
//! whole chunk.

use super::block::NetworkBlock;
use super::mode::NetMode;
use super::model::NetworkModel;

/// Most samples a chunk holds before its signals are computed.
pub const CHUNK: usize = 128;

/// A mode's signals as linear forms of the state (index, coefficient).
#[derive(Clone, Debug, Default)]
pub struct OutputForms {
    /// Each turning part's angle in its sense of rotation (rad): the bodies', then the
    /// planets'.
    pub angle: Vec<Vec<(usize, f64)>>,
    /// Each turning part's speed in its sense of rotation (rad/s).
    pub speed: Vec<Vec<(usize, f64)>>,
    /// Each shaft's torque (N m), in its first body's sense of rotation, then each shaft
    /// to the frame's (the torque the housing holds its body with: a held ring's reaction).
    pub shaft_torque: Vec<Vec<(usize, f64)>>,
    /// Each mesh's force along its line of action (N).
    pub mesh_force: Vec<Vec<(usize, f64)>>,
    /// Each mesh's contact: +1 drive, −1 back, 0 apart.
    pub contact: Vec<i8>,
    /// The motor's torque (N m): its loop's command, or the limit it is held at.
    pub motor_torque: Vec<(usize, f64)>,
    /// x then y (m) of each body that moves in the plane, then of each planet on its pin.
    pub translation: Vec<Vec<(usize, f64)>>,
}

impl OutputForms {
    /// The signals of `model` in `mode`, the harmonic pairs turning with the set speed
    /// `speed_rad_s`.
    pub fn of(model: &NetworkModel, mode: &NetMode, speed_rad_s: f64) -> Self {
        let l = &model.layout;
        let sense = |body: usize| model.speed_ratio[body].signum();
        let angle = l
            .turning()
            .map(|i| {
                vec![
                    (l.angle(i), sense(i)),
                    (l.phase(), sense(i) * model.speed_ratio[i]),
                ]
            })
            .collect();
        let speed = l.turning().map(|i| vec![(l.speed(i), sense(i))]).collect();
        let shaft_torque = model
            .shafts
            .iter()
            .map(|s| {
                let [a, b] = s.between;
                let (k, sign) = (s.stiffness_nm_per_rad, sense(a));
                vec![
                    (l.angle(a), sign * k),
                    (l.angle(b), -sign * k),
                    (l.unit(), sign * s.preload_nm),
                ]
            })
            .chain(model.supports[..model.frame_shafts].iter().map(|s| {
                s.terms
                    .iter()
                    .flat_map(|&(j, c)| {
                        let k = c * s.stiffness;
                        [(l.angle(j), k), (l.phase(), k * model.speed_ratio[j])]
                    })
                    .collect()
            }))
            .collect();
        let mesh_force = (0..model.meshes.len())
            .map(|i| {
                let state = mode.meshes[i];
                state.pushing_flank().map_or_else(Vec::new, |flank| {
                    model.force_terms(i, state, flank, speed_rad_s)
                })
            })
            .collect();
        let contact = (0..model.meshes.len())
            .map(|i| mode.meshes[i].contact.sign())
            .collect();
        // The bodies' translations, x then y, then each planet's on its pin: its bearing's
        // deflection.
        let translation = (l.bodies..l.translations_end)
            .map(|j| vec![(l.angle(j), 1.0)])
            .chain(
                model.supports[model.planet_bearings..]
                    .iter()
                    .map(|c| c.terms.iter().map(|&(j, g)| (l.angle(j), g)).collect()),
            )
            .collect();
        Self {
            angle,
            speed,
            shaft_torque,
            mesh_force,
            contact,
            motor_torque: model.motor_torque_terms(mode.motor),
            translation,
        }
    }
}

/// The states of up to [`CHUNK`] consecutive samples, one array per state; those whose
/// mode-dependent signals are not yet written all in one mode. The signals that do not depend on the mode (time, angles, speeds,
/// shaft torques, translations) are computed for the whole chunk at once; those that do
/// (mesh forces and contacts, the motor's torque) for each mode's samples as the mode
/// changes: where modes change every few samples (an in-phase planetary stage's pair
/// zones), a chunk per mode made the whole of each flush's cost a column's overhead.
#[derive(Clone, Debug)]
pub struct SampleChunk {
    /// State i of sample k at `i * CHUNK + k`.
    states: Vec<f64>,
    /// States per sample.
    len: usize,
    count: usize,
    first_sample: u64,
    /// The first sample (in the chunk) whose mode-dependent signals are not yet written:
    /// from it on, every sample is in `mode`.
    mode_start: usize,
    mode: NetMode,
}

impl SampleChunk {
    /// An empty chunk for states of `len` entries.
    pub fn new(len: usize) -> Self {
        Self {
            states: vec![0.0; len * CHUNK],
            len,
            count: 0,
            first_sample: 0,
            mode_start: 0,
            mode: NetMode::apart(0),
        }
    }

    /// Whether the next sample, `sample`, can join the chunk (in whatever mode: see
    /// [`Self::takes_mode`]).
    #[inline]
    pub fn takes(&self, sample: u64) -> bool {
        self.count == 0 || (self.count < CHUNK && self.first_sample + self.count as u64 == sample)
    }

    /// Whether a sample in `mode` can join the chunk's samples whose mode-dependent
    /// signals are unwritten (none held, or all in `mode`).
    #[inline]
    pub fn takes_mode(&self, mode: &NetMode) -> bool {
        self.count == self.mode_start || self.mode == *mode
    }

    /// Whether it holds [`CHUNK`] samples, as many as it can.
    pub fn is_full(&self) -> bool {
        self.count == CHUNK
    }

    /// Whether it holds no sample.
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// The mode of its samples whose mode-dependent signals are unwritten.
    pub fn mode(&self) -> &NetMode {
        &self.mode
    }

    /// Adds sample `sample`, the state `u` in `mode` (the chunk must take it, and its
    /// mode: [`Self::takes`], [`Self::takes_mode`]).
    #[inline]
    pub fn store(&mut self, sample: u64, mode: &NetMode, u: &[f64]) {
        if self.count == 0 {
            self.first_sample = sample;
        }
        if self.count == self.mode_start {
            self.mode = *mode;
        }
        let k = self.count;
        assert!(k < CHUNK, "a sample stored in a full chunk");
        for (column, &x) in self.states.chunks_exact_mut(CHUNK).zip(&u[..self.len]) {
            column[k] = x;
        }
        self.count += 1;
    }

    /// Appends the mode-dependent signals of the samples in [`Self::mode`] to `block` (by
    /// `forms`, the forms of that mode): the chunk then takes samples of another mode.
    pub fn flush_mode(&mut self, forms: &OutputForms, block: &mut NetworkBlock) {
        self.write(forms, None, block);
    }

    /// Appends the chunk's samples to `block` (their signals by `forms`, the forms of
    /// [`Self::mode`], whose signals that do not depend on the mode are every mode's;
    /// sample n at n · `output_step_s`), and empties it.
    pub fn flush(&mut self, forms: &OutputForms, output_step_s: f64, block: &mut NetworkBlock) {
        self.write(forms, Some(output_step_s), block);
    }

    /// [`Self::flush_mode`], then with `whole` (the output step, s) [`Self::flush`]'s
    /// other signals: compiled for AVX2 where the CPU has it, its sums four samples a
    /// vector (each product and sum rounded alone, as in baseline x86-64: the same bytes).
    fn write(&mut self, forms: &OutputForms, whole: Option<f64>, block: &mut NetworkBlock) {
        #[cfg(target_arch = "x86_64")]
        if crate::fma::available() {
            // SAFETY: the CPU has AVX2 and FMA, checked at run time.
            return unsafe { self.write_v3(forms, whole, block) };
        }
        self.write_any(forms, whole, block);
    }

    /// [`Self::write_any`] compiled for AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn write_v3(&mut self, forms: &OutputForms, whole: Option<f64>, block: &mut NetworkBlock) {
        self.write_any(forms, whole, block);
    }

    /// The sums of [`Self::write`].
    #[inline(always)]
    fn write_any(&mut self, forms: &OutputForms, whole: Option<f64>, block: &mut NetworkBlock) {
        self.write_mode(forms, block);
        if let Some(output_step_s) = whole {
            self.write_whole(forms, output_step_s, block);
        }
    }

    /// The mode-dependent signals of the samples in [`Self::mode`].
    #[inline(always)]
    fn write_mode(&mut self, forms: &OutputForms, block: &mut NetworkBlock) {
        let (from, to) = (self.mode_start, self.count);
        if from == to {
            return;
        }
        let append = |terms: &[(usize, f64)], column: &mut Vec<f64>| {
            self.sum(terms, from..to, column);
        };
        for (terms, column) in forms.mesh_force.iter().zip(&mut block.mesh_force_n) {
            append(terms, column);
        }
        append(&forms.motor_torque, &mut block.motor_torque_nm);
        for (&sign, column) in forms.contact.iter().zip(&mut block.contact) {
            column.extend(std::iter::repeat_n(sign, to - from));
        }
        self.mode_start = to;
    }

    /// The signals of every mode of the chunk's samples, and the chunk emptied.
    #[inline(always)]
    fn write_whole(&mut self, forms: &OutputForms, output_step_s: f64, block: &mut NetworkBlock) {
        let n = self.count;
        if n == 0 {
            return;
        }
        let first = self.first_sample;
        block
            .time_s
            .extend((0..n as u64).map(|k| (first + k) as f64 * output_step_s));
        let append = |terms: &[(usize, f64)], column: &mut Vec<f64>| self.sum(terms, 0..n, column);
        for (terms, column) in forms.angle.iter().zip(&mut block.angle_rad) {
            append(terms, column);
        }
        for (terms, column) in forms.speed.iter().zip(&mut block.speed_rad_s) {
            append(terms, column);
        }
        for (terms, column) in forms.shaft_torque.iter().zip(&mut block.shaft_torque_nm) {
            append(terms, column);
        }
        for (terms, column) in forms.translation.iter().zip(&mut block.translation_m) {
            append(terms, column);
        }
        self.count = 0;
        self.mode_start = 0;
    }

    /// Appends to `column`, for each sample k of `samples` (in the chunk), Σ c · state i
    /// of sample k over the terms (i, c): the first term's products appended, the others
    /// added in place.
    #[inline(always)]
    fn sum(&self, terms: &[(usize, f64)], samples: std::ops::Range<usize>, column: &mut Vec<f64>) {
        let state = |i: usize| &self.states[i * CHUNK + samples.start..i * CHUNK + samples.end];
        let start = column.len();
        let Some((&(i, c), rest)) = terms.split_first() else {
            column.resize(start + samples.len(), 0.0);
            return;
        };
        // + 0.0: a zero signal is +0, as a sum from zero gives it.
        column.extend(state(i).iter().map(|&x| c * x + 0.0));
        let out = &mut column[start..];
        for &(i, c) in rest {
            for (o, &x) in out.iter_mut().zip(state(i)) {
                *o += c * x;
            }
        }
    }
}
