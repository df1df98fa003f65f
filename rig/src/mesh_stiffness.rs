//! The mesh stiffness of a spur pair by the potential-energy method: each tooth a
//! non-uniform cantilever on the gear body, its Hertzian, bending, shear and axial
//! compressive energies (Yang & Lin 1987, Tian 2004, as Wu, Zuo & Parey 2008 write them)
//! and the deflection of its fillet foundation (Sainsot, Velex & Duverger 2004), summed
//! in series for the two teeth of a pair; two pairs in parallel where two are in mesh.
//!
//! The energies are integrated over the tooth's true shape: the involute down to the base
//! circle, below it (where the root circle lies lower) a radial flank as thick as at the
//! base circle, built in at the root circle (as Chen & Shao 2011 treat teeth whose base
//! circle lies above the root circle); where the root circle lies above the base circle,
//! the involute from the root circle. Modelling choices, stated: standard gears (no
//! profile shift, dedendum 1.25 m) at the standard centre distance; both gears of one
//! steel; the fillet's own shape left to the foundation's coefficients. Angles in radians, lengths in metres, stiffnesses along the line of action in
//! N/m.

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};

/// A spur pair's geometry and material.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
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
    /// The gears' bore diameter (m), the fillet foundation's inner circle (Sainsot's
    /// r_int is half of it); `None`: each gear's bore radius half its base radius.
    pub bore_diameter_m: Option<f64>,
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

    /// The bore radius of gear `g` (m): half the bore diameter, else half its base radius.
    pub fn bore_radius_m(&self, g: usize) -> f64 {
        self.bore_diameter_m
            .map_or(0.5 * self.base_radius_m(g), |d| 0.5 * d)
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

    /// Root radius of gear `g`: the standard dedendum 1.25 m below the pitch circle (m).
    pub fn root_radius_m(&self, g: usize) -> f64 {
        self.module_m * (f64::from(self.teeth[g]) / 2.0 - 1.25)
    }

    /// The point of gear `g`'s involute whose pressure angle is `phi`: (x along the
    /// tooth's centre line from the gear's centre, y its half-thickness there; m).
    fn flank_point(&self, g: usize, phi: f64) -> (f64, f64) {
        let r = self.base_radius_m(g) / phi.cos();
        let psi = self.half_base_angle(g) - involute(phi);
        (r * psi.cos(), r * psi.sin())
    }

    /// The stiffness (N/m, along the line of action) of one tooth of gear `g` loaded at
    /// the point of its involute whose pressure angle is `alpha_r`: a cantilever built in
    /// at the root circle, its bending, shear and axial compressive energies, in series
    /// with its fillet foundation. Below the base circle (where the root circle lies
    /// lower) the flank is taken radial, the tooth as thick as at the base circle.
    pub fn tooth_stiffness_n_per_m(&self, g: usize, alpha_r: f64) -> f64 {
        self.cracked_tooth_stiffness_n_per_m(g, alpha_r, 0.0)
    }

    /// [`Self::tooth_stiffness_n_per_m`] with a root crack of `crack_share` (0..1) of the
    /// tooth's thickness at the root circle: the crack runs from the loaded flank's root
    /// across the tooth (Tian 2004, Wu, Zuo & Parey 2008), its tip `crack_share` of the
    /// root thickness in from that flank; the material on the cracked side beyond the
    /// tip's line (parallel to the centre line) carries no stress, so each section below
    /// where the flank's half-thickness falls to the tip's keeps h + min(h, h_q) of its
    /// thickness (h_q the tip's signed distance from the centre line).
    pub fn cracked_tooth_stiffness_n_per_m(&self, g: usize, alpha_r: f64, crack_share: f64) -> f64 {
        let rb = self.base_radius_m(g);
        let a2 = self.half_base_angle(g);
        // The force's angle to the normal of the tooth's centre line.
        let a1 = alpha_r.tan() - a2;
        let (s1, c1) = a1.sin_cos();
        let (xc, yc) = self.flank_point(g, alpha_r);
        let e = self.youngs_modulus_pa;
        let shear_modulus = e / (2.0 * (1.0 + self.poisson_ratio));
        let l = self.face_width_m;
        let rf = self.root_radius_m(g);
        let root_half = self.root_half_thickness_m(g);
        let tip = root_half * (1.0 - 2.0 * crack_share);
        // Compliance of a slice dx of half-thickness y at x: its thickness, cracked or not.
        let slice = |x: f64, y: f64| {
            let moment = c1 * (xc - x) - yc * s1;
            let thickness = y + y.min(tip);
            let inertia = thickness.powi(3) * l / 12.0;
            let area = thickness * l;
            moment * moment / (e * inertia)
                + 1.2 * c1 * c1 / (shear_modulus * area)
                + s1 * s1 / (e * area)
        };
        // The involute from where the tooth begins (the base circle, or the root circle
        // above it) to the loaded point, by its pressure angle.
        let phi_start = if rf > rb { (rb / rf).acos() } else { 0.0 };
        let involute_part = simpson(
            |phi| {
                let (x, y) = self.flank_point(g, phi);
                slice(x, y) * self.dx_dphi(g, phi)
            },
            phi_start,
            alpha_r,
        );
        // The radial stretch from the root circle up to the base circle.
        let (xb, yb) = self.flank_point(g, 0.0);
        let radial_part = if rf < rb {
            let xf = (rf * rf - yb * yb).max(0.0).sqrt();
            simpson(|x| slice(x, yb), xf, xb)
        } else {
            0.0
        };
        1.0 / (involute_part + radial_part + self.fillet_compliance(g, a1))
    }

    /// Half the tooth's thickness where it meets the root circle (m).
    fn root_half_thickness_m(&self, g: usize) -> f64 {
        let rb = self.base_radius_m(g);
        let rf = self.root_radius_m(g);
        if rf > rb {
            self.flank_point(g, (rb / rf).acos()).1
        } else {
            self.flank_point(g, 0.0).1
        }
    }

    /// The share of a pair's stiffness it keeps with a root crack of `crack_share` of the
    /// root thickness in the tooth of gear `g` (0 driver, 1 driven): the cracked pair's
    /// mean stiffness over its path of contact (its time in mesh) over the healthy pair's.
    pub fn crack_factor(&self, g: usize, crack_share: f64) -> f64 {
        let (enter, leave) = self.contact_span();
        let [z1, z2] = self.teeth.map(f64::from);
        let t = self.pressure_angle_rad.tan();
        let mut sums = (0.0, 0.0);
        // Evenly along the line of action (in roll, tan α): evenly in time.
        for i in 0..=100 {
            let roll = enter.tan() + (leave.tan() - enter.tan()) * f64::from(i) / 100.0;
            let driver = roll.atan();
            let driven = (((z1 + z2) * t - z1 * driver.tan()) / z2).atan();
            let points = [driver, driven];
            let tooth = |gear: usize, share: f64| {
                self.cracked_tooth_stiffness_n_per_m(gear, points[gear], share)
            };
            let pair = |share: f64| {
                let cracked = |gear: usize| if gear == g { share } else { 0.0 };
                1.0 / (1.0 / self.hertz_stiffness_n_per_m()
                    + 1.0 / tooth(0, cracked(0))
                    + 1.0 / tooth(1, cracked(1)))
            };
            sums.0 += pair(crack_share);
            sums.1 += pair(0.0);
        }
        sums.0 / sums.1
    }

    /// dx/dφ of gear `g`'s involute at pressure angle `phi` (m/rad).
    fn dx_dphi(&self, g: usize, phi: f64) -> f64 {
        let rb = self.base_radius_m(g);
        let psi = self.half_base_angle(g) - involute(phi);
        let (sp, cp) = phi.sin_cos();
        rb * sp / (cp * cp) * psi.cos() + rb / cp * psi.sin() * (sp / cp).powi(2)
    }

    /// The fillet foundation's compliance (m/N) of gear `g`'s tooth, force at angle `a1`
    /// (Sainsot et al. 2004): S_f the tooth's thickness at the root circle, u_f the
    /// distance from there to where the force's line meets the centre line, h_f the root
    /// radius over the bore radius.
    fn fillet_compliance(&self, g: usize, a1: f64) -> f64 {
        let rb = self.base_radius_m(g);
        let rf = self.root_radius_m(g);
        let theta_f = if rf > rb {
            self.half_base_angle(g) - involute((rb / rf).acos())
        } else {
            (self.flank_point(g, 0.0).1 / rf).asin()
        };
        let h_f = rf / self.bore_radius_m(g);
        let [lf, mf, pf, qf] = FILLET.map(|[a, b, c, d, e, f]| {
            a / (theta_f * theta_f) + b * h_f * h_f + c * h_f / theta_f + d / theta_f + e * h_f + f
        });
        let u_f = rb / a1.cos() - rf * theta_f.cos();
        let s_f = 2.0 * rf * theta_f;
        let ratio = u_f / s_f;
        let el = self.youngs_modulus_pa * self.face_width_m;
        a1.cos().powi(2) / el
            * (lf * ratio * ratio + mf * ratio + pf * (1.0 + qf * a1.tan().powi(2)))
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

/// A mesh's stiffness as the exact plant takes it: constant over each pair zone.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LumpedStiffness {
    /// One pair's mean stiffness over the stretch it carries alone (N/m).
    pub single_n_per_m: f64,
    /// Two pairs' mean stiffness over their stretch, over `single_n_per_m`.
    pub double_pair_ratio: f64,
    /// The mean mesh stiffness over a whole tooth period (N/m): one pair always, as the
    /// thesis's model takes it.
    pub cycle_mean_n_per_m: f64,
}

impl PairGeometry {
    /// The mesh's stiffness averaged over its pair zones (400 points a tooth period).
    pub fn lumped(&self) -> LumpedStiffness {
        let points = 400;
        let cycle = self.mesh_cycle_n_per_m(points);
        let split = ((self.contact_ratio() - 1.0) * points as f64).ceil() as usize;
        let mean = |x: &[f64]| x.iter().sum::<f64>() / x.len().max(1) as f64;
        let (double, single) = cycle.split_at(split.min(points));
        let single_n_per_m = mean(single);
        LumpedStiffness {
            single_n_per_m,
            double_pair_ratio: mean(double) / single_n_per_m,
            cycle_mean_n_per_m: mean(&cycle),
        }
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
