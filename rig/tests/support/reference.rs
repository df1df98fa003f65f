//! An independent reference: the rig's equations written out directly in absolute
//! coordinates and integrated with classical RK4 at a tiny fixed step. Contact starts
//! are located by linear interpolation of the overlap between steps.

use rig::RigParams;
use std::f64::consts::PI;

/// Reference integrator state.
pub struct Reference {
    p: RigParams,
    omega: f64,
    load: f64,
    kp: f64,
    ki: f64,
    filter: f64,
    b0: f64,
    pitch: f64,
    /// Pitch radius (m): the transmission errors are arcs there.
    radius: f64,
    /// θ1..θ5 (rad), ω1..ω5 (rad/s), filtered speed (rad/s), speed-error integral (rad).
    pub y: [f64; 12],
    /// Time (s).
    pub t: f64,
    next_tooth: f64,
    /// Times of contact starts (s) with +1 drive / −1 back flank.
    pub impacts: Vec<(f64, i8)>,
    /// Whether each flank (drive, back) counts as touching: overlap ≥ 0, or, right after
    /// a tooth shift left it exactly at zero, still closing.
    touching: [bool; 2],
}

impl Reference {
    /// Starts at relative state `rel` = [X1..X5, V1..V5, Vf, z] at t = 0, speed `rpm`, load `load_nm`.
    pub fn new(p: &RigParams, rpm: f64, load_nm: f64, rel: [f64; 12]) -> Self {
        let omega = rpm * PI / 30.0;
        let j: f64 = p.inertias_kgm2().iter().sum();
        let wn = 2.0 * PI * p.speed_loop_hz;
        let r = p.module_m * f64::from(p.teeth) / 2.0;
        let mut y = rel;
        for v in &mut y[5..11] {
            *v += omega;
        }
        let pitch = 2.0 * PI / f64::from(p.teeth);
        Self {
            p: p.clone(),
            omega,
            load: load_nm,
            kp: 2.0 * p.speed_loop_damping_ratio * wn * j,
            ki: j * wn * wn,
            filter: 2.0 * PI * p.speed_feedback_filter_hz,
            b0: p.centre_distance_shift_m * p.pressure_angle_deg.to_radians().tan() / r,
            pitch,
            radius: r,
            y,
            t: 0.0,
            next_tooth: ((y[1] / pitch).floor() + 1.0) * pitch,
            impacts: Vec::new(),
            touching: [false; 2],
        }
        .with_touching()
    }

    fn with_touching(mut self) -> Self {
        let [drive, back] = self.overlaps(self.t, &self.y);
        self.touching = [drive.0 >= 0.0, back.0 >= 0.0];
        self
    }

    /// Overlaps (drive, back) in rad and their rates at (t, y), the gears' relative angle
    /// taken less the transmission error e = E cos φ + P cos zφ.
    fn overlaps(&self, t: f64, y: &[f64; 12]) -> [(f64, f64); 2] {
        let phase = self.omega * t;
        let c1 = self.p.backlash_variation_c1;
        let b = self.b0 * (1.0 - c1 * phase.cos());
        let b_rate = self.b0 * c1 * self.omega * phase.sin();
        let once = self.p.te_once_per_rev_um * 1e-6 / self.radius;
        let profile = self.p.te_mesh_frequency_um * 1e-6 / self.radius;
        let z = f64::from(self.p.teeth);
        let e = once * phase.cos() + profile * (z * phase).cos();
        let e_rate = -self.omega * (once * phase.sin() + z * profile * (z * phase).sin());
        let d = y[2] - y[1] - e;
        let d_rate = y[7] - y[6] - e_rate;
        [(-d - b, -d_rate - b_rate), (d - b, d_rate - b_rate)]
    }

    fn mesh_torque(&self, t: f64, y: &[f64; 12]) -> f64 {
        let [drive, back] = self.overlaps(t, y);
        let (k, c) = (self.p.k23_mesh_nm_per_rad, self.p.c23_mesh_nms_per_rad);
        if drive.0 >= 0.0 {
            k * drive.0 + c * drive.1
        } else if back.0 >= 0.0 {
            -(k * back.0 + c * back.1)
        } else {
            0.0
        }
    }

    fn rhs(&self, t: f64, y: &[f64; 12]) -> [f64; 12] {
        let p = &self.p;
        let phase = self.omega * t;
        let gear_error =
            -p.gear_error_c2_nm * phase.cos() - p.gear_error_c3_nm * (2.0 * phase).cos();
        let motor = self.kp * (self.omega - y[10]) + self.ki * y[11];
        let t12 = p.k12_input_shaft_nm_per_rad * (y[0] - y[1])
            + p.c12_input_shaft_nms_per_rad * (y[5] - y[6]);
        let t34 = p.k34_intermediate_shaft_nm_per_rad * (y[2] - y[3])
            + p.c34_intermediate_shaft_nms_per_rad * (y[7] - y[8]);
        let t45 = p.k45_final_shaft_nm_per_rad * (y[3] - y[4])
            + p.c45_final_shaft_nms_per_rad * (y[8] - y[9]);
        let mesh = self.mesh_torque(t, y);
        let brake = self.load + p.brake_speed_slope_nms_per_rad * (y[9] - self.omega);
        let torque = [
            motor - t12,
            t12 - mesh + gear_error,
            mesh - t34 + gear_error,
            t34 - t45,
            t45 - brake,
        ];
        let j = p.inertias_kgm2();
        let mut dy = [0.0; 12];
        for i in 0..5 {
            dy[i] = y[5 + i];
            dy[5 + i] = torque[i] / j[i];
        }
        dy[10] = self.filter * (y[5] - y[10]);
        dy[11] = self.omega - y[10];
        dy
    }

    fn rk4(&self, t: f64, y: &[f64; 12], h: f64) -> [f64; 12] {
        let add = |a: &[f64; 12], b: &[f64; 12], s: f64| -> [f64; 12] {
            std::array::from_fn(|i| a[i] + s * b[i])
        };
        let k1 = self.rhs(t, y);
        let k2 = self.rhs(t + h / 2.0, &add(y, &k1, h / 2.0));
        let k3 = self.rhs(t + h / 2.0, &add(y, &k2, h / 2.0));
        let k4 = self.rhs(t + h, &add(y, &k3, h));
        std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
    }

    /// Integrates to `until_s` with step `h_s`, logging contact starts and applying tooth shifting.
    pub fn run(&mut self, until_s: f64, h_s: f64) {
        while self.t < until_s - 0.5 * h_s {
            let before = self.overlaps(self.t, &self.y);
            let y = self.rk4(self.t, &self.y, h_s);
            let t = self.t + h_s;
            let after = self.overlaps(t, &y);
            for (k, flank) in [(0, 1i8), (1, -1)] {
                let (b, a) = (before[k].0, after[k].0);
                if !self.touching[k] && a >= 0.0 {
                    self.impacts
                        .push((self.t + h_s * (-b).max(0.0) / (a - b), flank));
                }
                self.touching[k] = a >= 0.0;
            }
            self.y = y;
            self.t = t;
            if self.p.tooth_shifting && self.y[1] >= self.next_tooth {
                self.next_tooth += self.pitch;
                self.shift_tooth();
            }
        }
    }

    /// Thesis §5.4.5: hand the overlap back half to each gear.
    fn shift_tooth(&mut self) {
        let [drive, back] = self.overlaps(self.t, &self.y);
        if drive.0 > 0.0 {
            self.y[2] += drive.0 / 2.0;
            self.y[1] -= drive.0 / 2.0;
            self.touching[0] = drive.1 > 0.0;
        } else if back.0 > 0.0 {
            self.y[2] -= back.0 / 2.0;
            self.y[1] += back.0 / 2.0;
            self.touching[1] = back.1 > 0.0;
        }
    }
}

/// The relative state [X1..X5 (rad), V1..V5 (rad/s), Vf (rad/s), z (rad)]
/// [`Reference::new`] starts from, of the one plant of the 1983 rig (`rig::preset_rig`):
/// each body in its own sense of rotation, about the set rotation at the plant's set
/// speed. The plant's angles are already less their share of the set rotation; its
/// speeds and filtered speed are absolute.
pub fn relative_state(plant: &rig::NetworkPlant) -> [f64; 12] {
    let state = plant.state_rad();
    let share = plant.speed_ratios();
    assert_eq!(share.len(), 5, "the thesis's five bodies");
    assert_eq!(
        state.len(),
        12,
        "angles, speeds, the speed loop's two states"
    );
    let omega = plant.set_points().speed_rpm * PI / 30.0;
    std::array::from_fn(|i| match i {
        0..5 => share[i].signum() * state[i],
        5..10 => share[i - 5].signum() * state[i] - share[i - 5].abs() * omega,
        10 => state[i] - omega,
        _ => state[i],
    })
}
