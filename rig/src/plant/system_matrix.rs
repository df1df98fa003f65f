//! A of u' = A u in each mode: each coordinate's rate, drag and inertia; the shafts,
//! supports and meshes in contact as generalised forces on the coordinates they read
//! (`model.rs` gives the forms); the harmonic pairs and the gear-error torques; the
//! motor's speed loop or its limit; the brake's load, drag, slope and oscillating load;
//! the forcing states' own rates.

use nalgebra::DMatrix;

use crate::mode::MotorMode;
use crate::topology::Coupling;

use super::mode::{MeshState, NetMode};
use super::model::{NetworkModel, SegmentRates, ShaftModel};

impl NetworkModel {
    /// A of u' = A u in `mode` over a stretch of set points turning at `rates`.
    pub fn system_matrix(&self, mode: &NetMode, rates: &SegmentRates) -> DMatrix<f64> {
        let l = &self.layout;
        let speed_rad_s = rates.harmonic_rad_s;
        let oscillating_rad_s = rates.oscillating_rad_s;
        let mut a = DMatrix::zeros(l.len(), l.len());
        for i in 0..l.coordinates {
            a[(l.angle(i), l.speed(i))] = 1.0;
            a[(l.angle(i), l.set_speed())] = -self.speed_ratio[i];
            a[(l.speed(i), l.speed(i))] -= self.drag_nms_per_rad[i] / self.inertia[i];
        }
        for s in &self.shafts {
            self.add_shaft(&mut a, s);
        }
        for s in &self.supports {
            self.add_support(&mut a, s);
        }
        for i in 0..self.meshes.len() {
            self.add_mesh(&mut a, i, mode.meshes[i], speed_rad_s);
        }
        for (index, mesh, harmonic) in l.harmonics() {
            let w = harmonic * self.meshes[mesh].share * speed_rad_s;
            a[(index, index + 1)] = -w;
            a[(index + 1, index)] = w;
        }
        self.add_gear_errors(&mut a);
        self.add_motor(&mut a, mode.motor);
        self.add_brake(&mut a, rates.brake_characteristic_nms_per_rad);
        a[(l.set_speed(), l.set_rate())] = 1.0;
        a[(l.load(), l.load_rate())] = 1.0;
        a[(l.phase(), l.set_speed())] = 1.0;
        a[(l.oscillating(), l.oscillating() + 1)] = -oscillating_rad_s;
        a[(l.oscillating() + 1, l.oscillating())] = oscillating_rad_s;
        a
    }

    /// Adds a generalised force (a torque on a rotation, a force on a translation) with
    /// `terms`' coefficient of each state, over the coordinate's inertia, to coordinate
    /// `body`'s row.
    fn add_torque(&self, a: &mut DMatrix<f64>, body: usize, terms: &[(usize, f64)]) {
        let row = self.layout.speed(body);
        for &(col, c) in terms {
            a[(row, col)] += c / self.inertia[body];
        }
    }

    /// A support's force −k g·x − c g·v on each coordinate it reads, times its coefficient.
    fn add_support(&self, a: &mut DMatrix<f64>, s: &Coupling) {
        let l = &self.layout;
        for &(j, gj) in &s.terms {
            let terms: Vec<(usize, f64)> = s
                .terms
                .iter()
                .flat_map(|&(i, gi)| {
                    [
                        (l.angle(i), -gj * s.stiffness * gi),
                        (l.speed(i), -gj * s.damping * gi),
                    ]
                })
                .collect();
            self.add_torque(a, j, &terms);
        }
    }

    fn add_shaft(&self, a: &mut DMatrix<f64>, s: &ShaftModel) {
        let l = &self.layout;
        let [i, j] = s.between;
        let (k, c) = (s.stiffness_nm_per_rad, s.damping_nms_per_rad);
        let carried = [
            (l.angle(i), k),
            (l.angle(j), -k),
            (l.speed(i), c),
            (l.speed(j), -c),
            (l.unit(), s.preload_nm),
        ];
        for (body, sign) in [(i, -1.0), (j, 1.0)] {
            let terms: Vec<(usize, f64)> =
                carried.iter().map(|&(col, v)| (col, sign * v)).collect();
            self.add_torque(a, body, &terms);
        }
    }

    /// The mesh's force terms F = k(δ + e − f b + f b C1 cos θ) + c(δ' + e' + f b C1
    /// (cos θ)') (f = +1 on the drive flank, −1 on the back flank), −r_a F on its driver
    /// and −r_b F on its driven gear (−g F on each coordinate of the flank's δ, g its
    /// coefficient: translations too where a gear moves in the plane).
    fn add_mesh(&self, a: &mut DMatrix<f64>, mesh: usize, state: MeshState, speed_rad_s: f64) {
        let Some(flank) = state.pushing_flank() else {
            return;
        };
        let force = self.force_terms(mesh, state, flank, speed_rad_s);
        for (j, g) in self.meshes[mesh].terms(flank) {
            let terms: Vec<(usize, f64)> = force.iter().map(|&(col, f)| (col, -g * f)).collect();
            self.add_torque(a, j, &terms);
        }
    }

    fn add_motor(&self, a: &mut DMatrix<f64>, motor: MotorMode) {
        let Some(m) = &self.motor else {
            return;
        };
        let l = &self.layout;
        let (kp, ki, wf) = (m.kp_nms_per_rad, m.ki_nm_per_rad, m.filter_rad_s);
        a[(l.filtered(), l.speed(m.body))] = wf;
        a[(l.filtered(), l.filtered())] = -wf;
        let limit = m.limit_nm.unwrap_or(f64::INFINITY);
        match motor {
            MotorMode::Linear => {
                let command = [(l.set_speed(), kp), (l.filtered(), -kp), (l.integral(), ki)];
                self.add_torque(a, m.body, &command);
                a[(l.integral(), l.set_speed())] = 1.0;
                a[(l.integral(), l.filtered())] = -1.0;
            }
            MotorMode::LimitHigh | MotorMode::LimitLow => {
                let sign = if motor == MotorMode::LimitHigh {
                    1.0
                } else {
                    -1.0
                };
                self.add_torque(a, m.body, &[(l.unit(), sign * limit)]);
                // The integrator tracks so that the command stays at the limit:
                // ki ż = kp ω̇_f with Ω constant, kp Ω̇ with a ramp.
                let gain = kp / ki;
                a[(l.integral(), l.speed(m.body))] = gain * wf;
                a[(l.integral(), l.filtered())] = -gain * wf;
                a[(l.integral(), l.set_rate())] = -gain;
            }
        }
    }

    /// Each mesh's gear-error torques −C2 cos θ − C3 cos 2θ on both its gears, each in
    /// its own sense of rotation.
    fn add_gear_errors(&self, a: &mut DMatrix<f64>) {
        let l = &self.layout;
        for (i, m) in self.meshes.iter().enumerate() {
            let harmonics = [
                (l.revolution[i], m.gear_error_c2_nm),
                (l.second[i], m.gear_error_c3_nm),
            ];
            for (index, amplitude) in harmonics {
                let Some(cos) = index.filter(|_| amplitude != 0.0) else {
                    continue;
                };
                for body in m.gears {
                    let sense = self.speed_ratio[body].signum();
                    self.add_torque(a, body, &[(cos, -sense * amplitude)]);
                }
            }
        }
    }

    /// The brake's load, drag, slope (the set one plus the characteristic's `characteristic`
    /// at the set point) and oscillating load, all resisting.
    fn add_brake(&self, a: &mut DMatrix<f64>, characteristic: f64) {
        let Some(b) = &self.brake else {
            return;
        };
        let l = &self.layout;
        let dir = b.direction;
        let slope = b.slope_nms_per_rad + characteristic;
        let nominal = self.speed_ratio[b.body];
        let terms = [
            (l.load(), -dir),
            (l.unit(), -dir * b.drag_nm),
            (l.oscillating() + 1, -dir),
            (l.speed(b.body), -slope),
            (l.set_speed(), slope * nominal),
        ];
        self.add_torque(a, b.body, &terms);
    }
}
