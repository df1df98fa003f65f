//! A mesh's constants as the equations take them: its gears and base radii, one pair's
//! stiffness and damping, free play and its variation, the transmission errors and
//! run-outs, its pair zones, and each tooth's stiffness factor where a tooth is faulted.

use crate::mesh_stiffness::PairGeometry;
use crate::mode::PairZone;
use crate::options::MeshPairs;
use crate::pair_zones::PairZones;
use crate::spacing::mesh_spacing_m;
use crate::tooth_fault::{FaultedGear, ToothFault, tooth_factors};
use crate::topology::{Mesh, MeshForm, PlanetaryStage};

use super::mode::MeshState;

/// A mesh's constants.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshModel {
    /// Driver and driven body.
    pub gears: [usize; 2],
    /// Their base radii (m), both negated where the driver turns against the motor, so
    /// that δ = r_a θa + r_b θb > 0 presses the driver's drive flank whichever way the
    /// pair turns.
    pub radii_m: [f64; 2],
    /// The deflection's part whose sign follows the flank (coordinate, m per unit of
    /// it), negated with the radii: r_a θa + r_b θb and, where a gear moves in the plane,
    /// its translations along the tangent (`topology::MeshForm`).
    pub turning: Vec<(usize, f64)>,
    /// The translations along the centre line, which part the gears on either flank.
    pub radial: Vec<(usize, f64)>,
    /// A constant displacement along the line of action (m; a planet's pin error, −e cos α
    /// on both its meshes, negated with the radii; 0 for an external mesh).
    pub offset_m: f64,
    /// One pair's stiffness along the line of action (N/m).
    pub stiffness_n_per_m: f64,
    /// One pair's damping along the line of action (N s/m).
    pub damping_ns_per_m: f64,
    /// Half the free play along the line of action (m).
    pub half_backlash_m: f64,
    /// Whether one and two pairs alternate.
    pub alternating: bool,
    /// Two pairs' stiffness and damping over one pair's.
    pub double_pair_ratio: f64,
    /// The driver's tooth pitch (rad).
    pub pitch_rad: f64,
    /// The pair zones of a tooth period: two pairs over the first ε − 1 of it (each
    /// change a staircase where the stiffness is smoothed), one pair over the rest.
    pub zones: PairZones,
    /// The angle the tooth periods follow (rad of the driver; period p from p pitches):
    /// Σ c θ_j over these (coordinate, c), plus `zone_offset_rad`. An external mesh's
    /// driver's angle; a stage mesh's driver's turn against the carrier, phased by the
    /// planet's place (`topology::StageMeshPhase`).
    pub zone_angle: Vec<(usize, f64)>,
    /// That angle's speed per unit set speed (signed).
    pub zone_share: f64,
    /// That angle's constant part (rad).
    pub zone_offset_rad: f64,
    /// The driver's and the driven gear's tooth in mesh in period 0, less one.
    pub tooth_offsets: [i64; 2],
    /// The driver's teeth z.
    pub teeth: f64,
    /// The driver's speed per unit set speed (signed).
    pub share: f64,
    /// Half the free play times its variation, b·C1 (m).
    pub variation_m: f64,
    /// Transmission error once per revolution of the driver, E (m along the line of
    /// action; the driver's run-out included).
    pub te_once_m: f64,
    /// Transmission error at mesh frequency, P (m along the line of action).
    pub te_mesh_m: f64,
    /// The driven gear's run-out, R (m along the line of action), once per its turn.
    pub run_out_driven_m: f64,
    /// The driven gear's turns per turn of the driver, z₁/z₂.
    pub driven_turns: f64,
    /// The thesis's numerical tooth shifting at each tooth pass in contact.
    pub tooth_shifting: bool,
    /// The no-pull law: the force clipped at zero while the flanks still overlap.
    pub no_pull: bool,
    /// Gear-error torque once per revolution of the driver, C2 (N m).
    pub gear_error_c2_nm: f64,
    /// Gear-error torque twice per revolution of the driver, C3 (N m).
    pub gear_error_c3_nm: f64,
    /// Each tooth's stiffness factor on the driver and on the driven gear over its pair's
    /// whole time in mesh (1 healthy; a crack or a broken-off share less), teeth numbered
    /// from the pair in mesh at angle 0.
    pub tooth_factors: [Vec<f64>; 2],
    /// Each tooth's further factor over its pair's single-contact stretch only (a pit).
    pub single_stretch_factors: [Vec<f64>; 2],
    /// Whether any tooth is faulted (the pair zones are then followed in contact).
    pub faulted: bool,
    /// Each tooth's spacing error on the driver and on the driven gear (m along the line
    /// of action; empty without spacing errors, `spacing::mesh_spacing_m`).
    pub spacing_m: [Vec<f64>; 2],
}

impl MeshModel {
    /// The constants of mesh `m`, each body's speed per unit motor speed `speed_ratio`,
    /// its deflection's `form` for a driver turning positive.
    pub fn of(m: &Mesh, speed_ratio: &[f64], form: MeshForm) -> Self {
        let sense = speed_ratio[m.gears[0]].signum();
        let geometry = CrackGeometry {
            teeth: m.teeth,
            module_m: m.module_m,
            pressure_angle_deg: m.pressure_angle_deg,
            addendum_coefficient: m.addendum_coefficient,
        };
        let faults = FaultFactors::of(&m.faults, &geometry);
        MeshModel {
            gears: m.gears,
            radii_m: m.base_radii_m().map(|r| r * sense),
            turning: form.sensed(sense),
            radial: form.radial,
            offset_m: 0.0,
            stiffness_n_per_m: m.stiffness_n_per_m,
            damping_ns_per_m: m.damping_ns_per_m,
            half_backlash_m: m.half_backlash_m(),
            alternating: m.pairs == MeshPairs::Alternating,
            double_pair_ratio: m.double_pair_ratio,
            pitch_rad: 2.0 * std::f64::consts::PI / f64::from(m.teeth[0]),
            zones: PairZones::new(
                (m.contact_ratio() - 1.0).clamp(0.0, 1.0),
                m.stiffness_smoothing,
            ),
            zone_angle: vec![(m.gears[0], 1.0)],
            zone_share: speed_ratio[m.gears[0]],
            zone_offset_rad: 0.0,
            tooth_offsets: [0, 0],
            teeth: f64::from(m.teeth[0]),
            share: speed_ratio[m.gears[0]],
            variation_m: m.half_backlash_m() * m.backlash_variation,
            te_once_m: (m.te_once_per_rev_um + m.run_out_driver_um) * 1e-6,
            run_out_driven_m: m.run_out_driven_um * 1e-6,
            driven_turns: f64::from(m.teeth[0]) / f64::from(m.teeth[1]),
            te_mesh_m: m.te_mesh_frequency_um * 1e-6,
            tooth_shifting: m.tooth_shifting,
            no_pull: m.contact_law == crate::options::ContactLaw::NoPull,
            gear_error_c2_nm: m.gear_error_c2_nm,
            gear_error_c3_nm: m.gear_error_c3_nm,
            tooth_factors: faults.whole,
            single_stretch_factors: faults.single_stretch,
            faulted: faults.any,
            spacing_m: mesh_spacing_m(m),
        }
    }

    /// A planetary stage's mesh between planet `k` and the sun (`ring` false) or the
    /// ring: its deflection's `form` for the sun turning forward against the carrier,
    /// negated by `sense` (−1 where it turns back), its gears the sun and the planet's
    /// rotation coordinate `planet` (or the planet and the ring) with their shares in
    /// `speed_ratio`, the planet's pin error along both lines; its tooth periods follow
    /// the sun's (or the planet's) turn against the carrier, phased by the planet's place,
    /// and its teeth carry the stage's faults on the teeth it brings together.
    pub fn of_stage(
        stage: &PlanetaryStage,
        ring: bool,
        (k, planet): (usize, usize),
        form: MeshForm,
        sense: f64,
        speed_ratio: &[f64],
    ) -> Self {
        let r = stage.radii_m();
        // The pin e ahead along e_t: the planet's centre's e cos α along both lines.
        let pin_error_m = stage.planet_pin_errors_um.get(k).copied().unwrap_or(0.0) * 1e-6;
        let offset_m = -sense * pin_error_m * stage.pressure_angle_deg.to_radians().cos();
        let carrier = stage.carrier;
        let (mesh, gears, radii, teeth, zone_angle) = if ring {
            let t = [stage.teeth.planet, stage.teeth.ring];
            let angle = vec![(planet, -1.0), (carrier, 1.0)];
            (
                &stage.ring_planet,
                [planet, stage.ring],
                [-r.planet, r.ring],
                t,
                angle,
            )
        } else {
            let t = [stage.teeth.sun, stage.teeth.planet];
            let angle = vec![(stage.sun, 1.0), (carrier, -1.0)];
            (
                &stage.sun_planet,
                [stage.sun, planet],
                [r.sun, r.planet],
                t,
                angle,
            )
        };
        let phase = stage.mesh_phase(k, ring);
        let pitch_rad = 2.0 * std::f64::consts::PI / f64::from(teeth[0]);
        let geometry = CrackGeometry {
            teeth,
            module_m: stage.module_m,
            pressure_angle_deg: stage.pressure_angle_deg,
            addendum_coefficient: 1.0,
        };
        let faults = FaultFactors::of(&stage.mesh_faults(k, ring), &geometry);
        let half_backlash_m =
            0.5 * mesh.backlash_mm * 1e-3 * stage.pressure_angle_deg.to_radians().cos();
        MeshModel {
            gears,
            radii_m: radii.map(|x| x * sense),
            turning: form.sensed(sense),
            radial: form.radial,
            offset_m,
            stiffness_n_per_m: mesh.stiffness_n_per_m,
            damping_ns_per_m: mesh.damping_ns_per_m,
            half_backlash_m,
            alternating: mesh.pairs == MeshPairs::Alternating,
            double_pair_ratio: mesh.double_pair_ratio,
            pitch_rad,
            zones: PairZones::new(
                (phase.contact_ratio - 1.0).clamp(0.0, 1.0),
                mesh.stiffness_smoothing,
            ),
            zone_share: zone_angle.iter().map(|&(j, c)| c * speed_ratio[j]).sum(),
            zone_angle,
            zone_offset_rad: -phase.start_periods * pitch_rad,
            tooth_offsets: phase.tooth_offsets,
            teeth: f64::from(teeth[0]),
            share: speed_ratio[gears[0]],
            variation_m: 0.0,
            te_once_m: 0.0,
            run_out_driven_m: 0.0,
            driven_turns: f64::from(teeth[0]) / f64::from(teeth[1]),
            te_mesh_m: 0.0,
            tooth_shifting: false,
            no_pull: false,
            gear_error_c2_nm: 0.0,
            gear_error_c3_nm: 0.0,
            tooth_factors: faults.whole,
            single_stretch_factors: faults.single_stretch,
            faulted: faults.any,
            spacing_m: [Vec::new(), Vec::new()],
        }
    }

    /// The deflection's terms on `flank` (+1 drive, −1 back): turning + flank · radial.
    pub fn terms(&self, flank: f64) -> impl Iterator<Item = (usize, f64)> + '_ {
        let radial = self.radial.iter().map(move |&(j, c)| (j, flank * c));
        self.turning.iter().copied().chain(radial)
    }

    /// The constant part of the overlap of `flank` (+1 drive, −1 back) with the driver
    /// at angle 0 of its share of the set rotation (m): −f b (1 − C1) + E + P + R, and
    /// the spacing error of the pair in mesh there.
    pub fn start_offset_m(&self, flank: f64) -> f64 {
        -flank * (self.half_backlash_m - self.variation_m)
            + self.offset_m
            + self.te_once_m
            + self.te_mesh_m
            + self.run_out_driven_m
            + self.zone_spacing_m(self.zones.zone_at(0.0))
    }

    /// The stiffness level in pair zone `zone`: one pair, two, or a step between (one
    /// pair always where pairs do not alternate).
    pub fn level(&self, zone: i64) -> PairZone {
        if self.alternating {
            self.zones.level(zone)
        } else {
            PairZone::ONE
        }
    }

    /// The pair that comes into mesh in pair zone `zone`'s tooth period (the one that
    /// strikes in a double-pair stretch).
    pub fn pair_of_zone(&self, zone: i64) -> i64 {
        self.zones.sharp(zone).div_euclid(2)
    }

    /// Stiffness (N/m) and damping (N s/m) in `state`.
    pub fn spring(&self, state: MeshState) -> (f64, f64) {
        let ratio = 1.0 + (self.double_pair_ratio - 1.0) * state.level.share_of_second_pair();
        let factor = state.factor();
        (
            ratio * self.stiffness_n_per_m * factor,
            ratio * self.damping_ns_per_m * factor,
        )
    }

    /// The stiffness factor of pair `pair` (the pair that comes into mesh at the start of
    /// the driver's tooth period `pair`) over its whole time in mesh: its driver tooth's
    /// times its driven tooth's.
    pub fn pair_factor(&self, pair: i64) -> f64 {
        self.factor_of(&self.tooth_factors, pair)
    }

    /// Whether the pairs differ in spacing (the pair zones are then followed apart too).
    pub fn spaced(&self) -> bool {
        !self.spacing_m[0].is_empty()
    }

    /// The spacing error of pair `pair` (m): its driver tooth's plus its driven tooth's.
    pub fn pair_spacing_m(&self, pair: i64) -> f64 {
        let tooth = |errors: &Vec<f64>| {
            errors
                .get(pair.rem_euclid(errors.len().max(1) as i64) as usize)
                .copied()
                .unwrap_or(0.0)
        };
        tooth(&self.spacing_m[0]) + tooth(&self.spacing_m[1])
    }

    /// The spacing error in pair zone `zone` (m), by the sharp zone holding it: its
    /// pair's, or where two pairs share the
    /// load, their mean weighted by their stiffness factors (both pairs touching).
    pub fn zone_spacing_m(&self, zone: i64) -> f64 {
        let zone = self.zones.sharp(zone);
        let pair = zone.div_euclid(2);
        if !(self.alternating && zone.rem_euclid(2) == 0) {
            return self.pair_spacing_m(pair);
        }
        let (f0, f1) = (self.pair_factor(pair - 1), self.pair_factor(pair));
        if f0 + f1 == 0.0 {
            return 0.5 * (self.pair_spacing_m(pair - 1) + self.pair_spacing_m(pair));
        }
        (f0 * self.pair_spacing_m(pair - 1) + f1 * self.pair_spacing_m(pair)) / (f0 + f1)
    }

    /// The teeth (1..=z, driver's and driven's) of pair `pair`.
    pub fn pair_teeth(&self, pair: i64) -> [u32; 2] {
        let [driver, driven] = &self.tooth_factors;
        let [a, b] = self.tooth_offsets;
        [(driver.len(), a), (driven.len(), b)]
            .map(|(z, offset)| (pair + offset).rem_euclid(z as i64) as u32 + 1)
    }

    /// The stiffness factor in pair zone `zone`, by the sharp zone holding it (2p: pairs
    /// p − 1 and p share the load
    /// where pairs alternate, pair p alone over the first ε − 1 of its period where one
    /// pair is modelled; 2p + 1: pair p alone over the rest, its single-contact stretch,
    /// where a pit acts too).
    pub fn zone_factor(&self, zone: i64) -> f64 {
        let zone = self.zones.sharp(zone);
        let pair = zone.div_euclid(2);
        if zone.rem_euclid(2) == 1 {
            self.pair_factor(pair) * self.factor_of(&self.single_stretch_factors, pair)
        } else if self.alternating {
            0.5 * (self.pair_factor(pair - 1) + self.pair_factor(pair))
        } else {
            self.pair_factor(pair)
        }
    }

    /// Pair `pair`'s factor in `factors` (the driver's and the driven gear's teeth): the
    /// product of its two teeth's.
    fn factor_of(&self, factors: &[Vec<f64>; 2], pair: i64) -> f64 {
        let [driver, driven] = factors;
        let [a, b] = self.tooth_offsets;
        driver[(pair + a).rem_euclid(driver.len() as i64) as usize]
            * driven[(pair + b).rem_euclid(driven.len() as i64) as usize]
    }
}

/// What a pair's faults need of its gears for a crack's stiffness factor.
struct CrackGeometry {
    /// The driver's and the driven gear's teeth.
    teeth: [u32; 2],
    /// Module (m).
    module_m: f64,
    /// Pressure angle (degrees).
    pressure_angle_deg: f64,
    /// Addendum over the module.
    addendum_coefficient: f64,
}

/// Each tooth's stiffness factors on a pair's two gears by its faults.
struct FaultFactors {
    /// Over its pair's whole time in mesh (a crack, a broken-off share).
    whole: [Vec<f64>; 2],
    /// Over its pair's single-contact stretch only (a pit).
    single_stretch: [Vec<f64>; 2],
    /// Whether any tooth is faulted.
    any: bool,
}

impl FaultFactors {
    /// The factors of `faults` on a pair of `geometry`.
    fn of(faults: &[ToothFault], geometry: &CrackGeometry) -> Self {
        let (single, whole): (Vec<ToothFault>, Vec<ToothFault>) = faults
            .iter()
            .cloned()
            .partition(ToothFault::single_stretch_only);
        let crack = geometry.crack();
        let pair = |faults: &[ToothFault]| {
            [
                tooth_factors(faults, FaultedGear::Driver, geometry.teeth[0], &crack),
                tooth_factors(faults, FaultedGear::Driven, geometry.teeth[1], &crack),
            ]
        };
        let (whole, single_stretch) = (pair(&whole), pair(&single));
        let any = whole
            .iter()
            .chain(&single_stretch)
            .flatten()
            .any(|&f| f != 1.0);
        Self {
            whole,
            single_stretch,
            any,
        }
    }
}

impl CrackGeometry {
    /// A cracked pair's stiffness factor: the potential-energy method on its gears
    /// (steel's Poisson's ratio 0.3, a bore of half the base radius; face width and
    /// Young's modulus cancel in the ratio).
    fn crack(&self) -> impl Fn(FaultedGear, f64) -> f64 {
        let geometry = PairGeometry {
            teeth: self.teeth,
            module_m: self.module_m,
            pressure_angle_rad: self.pressure_angle_deg.to_radians(),
            face_width_m: 1.0,
            addendum_coefficient: self.addendum_coefficient,
            youngs_modulus_pa: 206e9,
            poisson_ratio: 0.3,
            bore_diameter_m: None,
        };
        move |gear, share| {
            let g = match gear {
                FaultedGear::Driver => 0,
                FaultedGear::Driven => 1,
            };
            geometry.crack_factor(g, share)
        }
    }
}
