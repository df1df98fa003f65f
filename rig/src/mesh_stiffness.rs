//! The mesh stiffness of a spur pair by the potential-energy method: each tooth a
//! non-uniform cantilever on the gear body, its Hertzian, bending, shear and axial
//! compressive energies (Yang & Lin 1987, Tian 2004, as Wu, Zuo & Parey 2008 write them)
//! and the deflection of its fillet foundation (Sainsot, Velex & Duverger 2004), summed
//! in series for the two teeth of a pair; two pairs in parallel where two are in mesh.
//!
//! Modelling choices, stated: the involute runs down to the base circle and the tooth is
//! built in there (Tian's simplification; the fillet below it is the foundation's);
//! standard gears (no profile shift) at the standard centre distance; both gears of one
//! steel. Angles in radians, lengths in metres, stiffnesses along the line of action in
//! N/m.

use std::f64::consts::PI;

/// A spur pair's geometry and material.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PairGeometry {
    /// Teeth of the driver and the driven gear.
    pub teeth: [u32; 2],
    /// Module (m).
    pub module_m: f64,
    /// Pressure angle (rad).
    pub pressure_angle_rad: f64,
    /// Face width (m).
    pub face_width_m: f64,
    /// Addendum over the module (standard: 1).
    pub addendum_coefficient: f64,
    /// Young's modulus (Pa).
    pub youngs_modulus_pa: f64,
    /// Poisson's ratio.
    pub poisson_ratio: f64,
    /// Each gear's bore over its base radius (the fillet foundation's inner radius).
    pub bore_ratio: f64,
}

/// Sainsot's fillet-foundation coefficients (A, B, C, D, E, F) of L*, M*, P*, Q*, each
/// X* = A/θf² + B hf² + C hf/θf + D/θf + E hf + F.
const FILLET: [[f64; 6]; 4] = [
    [-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045],
    [60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086],
    [-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236],
    [
        -6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904,
    ],
];

/// Intervals of the Simpson rule over a tooth's height.
const INTERVALS: usize = 400;

fn involute(alpha: f64) -> f64 {
    alpha.tan() - alpha
}

impl PairGeometry {
    /// Base radius of gear `g` (0 driver, 1 driven; m).
    pub fn base_radius_m(&self, g: usize) -> f64 {
        self.module_m * f64::from(self.teeth[g]) * self.pressure_angle_rad.cos() / 2.0
    }

    /// Half the tooth's angle at the base circle of gear `g`: π/(2z) + inv α (rad).
    fn half_base_angle(&self, g: usize) -> f64 {
        PI / (2.0 * f64::from(self.teeth[g])) + involute(self.pressure_angle_rad)
    }

    /// Tip pressure angle of gear `g`: arccos(r_b / r_a) (rad).
    fn tip_pressure_angle(&self, g: usize) -> f64 {
        let z = f64::from(self.teeth[g]);
        let tip = self.module_m * (z / 2.0 + self.addendum_coefficient);
        (self.base_radius_m(g) / tip).acos()
    }

    /// The stiffness (N/m, along the line of action) of one tooth of gear `g` loaded at
    /// the point of its involute whose pressure angle is `alpha_r`: bending, shear, axial
    /// compression and fillet foundation in series.
    pub fn tooth_stiffness_n_per_m(&self, g: usize, alpha_r: f64) -> f64 {
        let a2 = self.half_base_angle(g);
        // The force's angle to the normal of the tooth's centre line.
        let a1 = alpha_r.tan() - a2;
        let el = self.youngs_modulus_pa * self.face_width_m;
        let nu = self.poisson_ratio;
        let (s1, c1) = a1.sin_cos();
        let integrand = |a: f64| {
            let (s, c) = a.sin_cos();
            let arm = a2 - a;
            let section = s + arm * c;
            let bending =
                3.0 * (1.0 + c1 * (arm * s - c)).powi(2) * arm * c / (2.0 * el * section.powi(3));
            let shear = 1.2 * (1.0 + nu) * arm * c * c1 * c1 / (el * section);
            let axial = arm * c * s1 * s1 / (2.0 * el * section);
            bending + shear + axial
        };
        let compliance = simpson(integrand, -a1, a2) + self.fillet_compliance(g, a1);
        1.0 / compliance
    }

    /// The fillet foundation's compliance (m/N) of gear `g`'s tooth, force at angle `a1`.
    fn fillet_compliance(&self, g: usize, a1: f64) -> f64 {
        let rb = self.base_radius_m(g);
        let a2 = self.half_base_angle(g);
        let root_radius = rb;
        let theta_f = a2;
        let h_f = 1.0 / self.bore_ratio;
        let [l, m, p, q] = FILLET.map(|[a, b, c, d, e, f]| {
            a / (theta_f * theta_f) + b * h_f * h_f + c * h_f / theta_f + d / theta_f + e * h_f + f
        });
        // Where the force's line meets the tooth's centre line, above the root section.
        let u_f = rb / a1.cos() - root_radius * a2.cos();
        let s_f = 2.0 * root_radius * a2.sin();
        let ratio = u_f / s_f;
        let el = self.youngs_modulus_pa * self.face_width_m;
        a1.cos().powi(2) / el * (l * ratio * ratio + m * ratio + p * (1.0 + q * a1.tan().powi(2)))
    }

    /// The Hertzian contact stiffness of a pair, π E L / (4 (1 − ν²)) (N/m).
    pub fn hertz_stiffness_n_per_m(&self) -> f64 {
        PI * self.youngs_modulus_pa * self.face_width_m / (4.0 * (1.0 - self.poisson_ratio.powi(2)))
    }

    /// One pair's stiffness (N/m) with the driver loaded at its involute's pressure angle
    /// `alpha_driver` (the driven gear's point follows along the line of action).
    pub fn pair_stiffness_n_per_m(&self, alpha_driver: f64) -> f64 {
        let [z1, z2] = self.teeth.map(f64::from);
        let t = self.pressure_angle_rad.tan();
        let driven = (((z1 + z2) * t - z1 * alpha_driver.tan()) / z2).atan();
        let compliance = 1.0 / self.hertz_stiffness_n_per_m()
            + 1.0 / self.tooth_stiffness_n_per_m(0, alpha_driver)
            + 1.0 / self.tooth_stiffness_n_per_m(1, driven);
        1.0 / compliance
    }

    /// The driver's pressure angles where its tooth enters and leaves mesh (rad).
    pub fn contact_span(&self) -> (f64, f64) {
        let [z1, z2] = self.teeth.map(f64::from);
        let t = self.pressure_angle_rad.tan();
        let enter = ((z1 + z2) * t - z2 * self.tip_pressure_angle(1).tan()) / z1;
        (enter.atan(), self.tip_pressure_angle(0))
    }

    /// The transverse contact ratio ε: the contact span in base pitches.
    pub fn contact_ratio(&self) -> f64 {
        let (enter, leave) = self.contact_span();
        f64::from(self.teeth[0]) * (leave.tan() - enter.tan()) / (2.0 * PI)
    }

    /// The mesh stiffness over one tooth period (N/m at `points` driver positions): the
    /// pair that entered at the period's start, and for the first ε − 1 of it the pair
    /// before it too.
    pub fn mesh_cycle_n_per_m(&self, points: usize) -> Vec<f64> {
        let (enter, _) = self.contact_span();
        let z1 = f64::from(self.teeth[0]);
        let pitch_roll = 2.0 * PI / z1;
        let epsilon = self.contact_ratio();
        (0..points)
            .map(|i| {
                let s = i as f64 / points as f64;
                let roll = enter.tan() + s * pitch_roll;
                let mut k = self.pair_stiffness_n_per_m(roll.atan());
                if s < epsilon - 1.0 {
                    k += self.pair_stiffness_n_per_m((roll + pitch_roll).atan());
                }
                k
            })
            .collect()
    }
}

/// ∫ f from `a` to `b` by Simpson's rule on [`INTERVALS`] intervals.
fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let h = (b - a) / INTERVALS as f64;
    let inner: f64 = (1..INTERVALS)
        .map(|i| {
            let weight = if i % 2 == 1 { 4.0 } else { 2.0 };
            weight * f(a + i as f64 * h)
        })
        .sum();
    (f(a) + inner + f(b)) * h / 3.0
}
