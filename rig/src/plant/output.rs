//! The samples a run writes: each sample's state stored column by column in a chunk, and
//! the block's signals computed from a whole chunk at once. In one mode (and one stretch
//! of set points) every signal is a linear form of the state: a body's angle and speed, a
//! shaft's torque, a mesh's force, the motor's torque. So a chunk holds the samples of one
//! mode, and each signal is a few sums over it in whole vectors (written one sample at a
//! time, the signals cost the plant as much as its steps).

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

/// The states of up to [`CHUNK`] consecutive samples in one mode, one array per state.
#[derive(Clone, Debug)]
pub struct SampleChunk {
    /// State i of sample k at `i * CHUNK + k`.
    states: Vec<f64>,
    /// States per sample.
    len: usize,
    count: usize,
    first_sample: u64,
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
            mode: NetMode::apart(0),
        }
    }

    /// Whether the next sample, `sample` in `mode`, can join the chunk.
    #[inline]
    pub fn takes(&self, sample: u64, mode: &NetMode) -> bool {
        self.count == 0
            || (self.count < CHUNK
                && self.mode == *mode
                && self.first_sample + self.count as u64 == sample)
    }

    /// Whether it holds [`CHUNK`] samples, as many as it can.
    pub fn is_full(&self) -> bool {
        self.count == CHUNK
    }

    /// Whether it holds no sample.
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// The mode its samples were taken in.
    pub fn mode(&self) -> &NetMode {
        &self.mode
    }

    /// Adds sample `sample`, the state `u` in `mode` (the chunk must take it).
    #[inline]
    pub fn store(&mut self, sample: u64, mode: &NetMode, u: &[f64]) {
        if self.count == 0 {
            self.first_sample = sample;
            self.mode = *mode;
        }
        let k = self.count;
        assert!(k < CHUNK, "a sample stored in a full chunk");
        for (column, &x) in self.states.chunks_exact_mut(CHUNK).zip(&u[..self.len]) {
            column[k] = x;
        }
        self.count += 1;
    }

    /// Appends the chunk's samples to `block` (their signals by `forms`, the forms of the
    /// chunk's mode; sample n at n · `output_step_s`), and empties it.
    pub fn flush(&mut self, forms: &OutputForms, output_step_s: f64, block: &mut NetworkBlock) {
        let n = self.count;
        if n == 0 {
            return;
        }
        let first = self.first_sample;
        block
            .time_s
            .extend((0..n as u64).map(|k| (first + k) as f64 * output_step_s));
        let append = |terms: &[(usize, f64)], column: &mut Vec<f64>| self.sum(terms, n, column);
        for (terms, column) in forms.angle.iter().zip(&mut block.angle_rad) {
            append(terms, column);
        }
        for (terms, column) in forms.speed.iter().zip(&mut block.speed_rad_s) {
            append(terms, column);
        }
        for (terms, column) in forms.shaft_torque.iter().zip(&mut block.shaft_torque_nm) {
            append(terms, column);
        }
        for (terms, column) in forms.mesh_force.iter().zip(&mut block.mesh_force_n) {
            append(terms, column);
        }
        for (terms, column) in forms.translation.iter().zip(&mut block.translation_m) {
            append(terms, column);
        }
        append(&forms.motor_torque, &mut block.motor_torque_nm);
        for (&sign, column) in forms.contact.iter().zip(&mut block.contact) {
            column.extend(std::iter::repeat_n(sign, n));
        }
        self.count = 0;
    }

    /// Appends to `column`, for each of the first `n` samples k, Σ c · state i of sample
    /// k over the terms (i, c): the first term's products appended, the others added in
    /// place.
    #[inline]
    fn sum(&self, terms: &[(usize, f64)], n: usize, column: &mut Vec<f64>) {
        let state = |i: usize| &self.states[i * CHUNK..i * CHUNK + n];
        let start = column.len();
        let Some((&(i, c), rest)) = terms.split_first() else {
            column.resize(start + n, 0.0);
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
