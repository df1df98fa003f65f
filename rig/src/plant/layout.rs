//! The state of a rig of n coordinates (`topology::RigCoordinates`: each body's rotation,
//! body i's first as coordinate i, then the translations of bodies that move in the
//! plane, then the planets' rotations, then the translations of planets on bearings):
//! x_0..x_{n−1} each coordinate less its share s_i Φ of the set rotation Φ (rad
//! for a rotation, a twist bounded however long the rig runs; m for a translation, whose
//! share is 0 but for a planet's: its pin's r_c s_c e_t, as it rides on the carrier),
//! their absolute rates v_0..v_{n−1} (rad/s, m/s), the speed loop's filtered
//! speed and integral, then the
//! forcing states: 1, the motor body's set speed Ω (rad/s) and its rate (rad/s²), the
//! brake's load (N m) and its rate (N m/s), the oscillating load (A cos ψ, A sin ψ) (N m),
//! and the set rotation Φ (rad; Φ' = Ω, read only by the switching functions of tooth
//! zones and revolutions). Set speed and load ramp exactly: Ω' = rate, load' = rate.
//! Then, for each mesh with a backlash variation or transmission error, the harmonic
//! pairs of its driver's share of the set rotation: (cos θ, sin θ) and, with a
//! mesh-frequency error, (cos zθ, sin zθ), with a gear-error torque twice per revolution
//! (C3), (cos 2θ, sin 2θ); and for each mesh with spacing errors, the
//! error e of the pair in mesh (m along the line of action, e' = 0, set as pairs change).

use crate::topology::{MAX_PLANT_MESHES, RigCoordinates, RigTopology};

/// Where each state sits for a rig of `bodies` bodies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NetLayout {
    /// Number of bodies (their rotations are the first coordinates).
    pub bodies: usize,
    /// Number of coordinates n: the bodies' rotations, then their translations, then the
    /// planets' rotations, then the planets' translations.
    pub coordinates: usize,
    /// The end of the bodies' translations (they start at `bodies`); the planets'
    /// rotations run from here to `planets_turning_end`.
    pub translations_end: usize,
    /// The end of the planets' rotations; the planets' translations (x then y of each
    /// planet on a bearing) run from here to `coordinates`.
    pub planets_turning_end: usize,
    /// Per mesh: where cos θ of its driver's share of the set rotation sits (sin θ
    /// follows), if the mesh is excited.
    pub revolution: [Option<usize>; MAX_PLANT_MESHES],
    /// Per mesh: where cos zθ sits (sin zθ follows), if it has a mesh-frequency error.
    pub tooth: [Option<usize>; MAX_PLANT_MESHES],
    /// Per mesh: where cos 2θ sits (sin 2θ follows), if it has a gear-error torque twice
    /// per revolution (C3).
    pub second: [Option<usize>; MAX_PLANT_MESHES],
    /// Per mesh: where cos θ₂ of its driven gear's turn sits (sin θ₂ follows), if the
    /// driven gear has run-out.
    pub run_out: [Option<usize>; MAX_PLANT_MESHES],
    /// Per mesh: where the spacing error of the pair in mesh sits, if the mesh has
    /// spacing errors.
    pub spacing: [Option<usize>; MAX_PLANT_MESHES],
    /// Per mesh: its driver's teeth z (the harmonic of the mesh-frequency pair).
    driver_teeth: [u32; MAX_PLANT_MESHES],
    /// Per mesh: its driven gear's teeth (its turn is z/z₂ of the driver's).
    driven_teeth: [u32; MAX_PLANT_MESHES],
    len: usize,
}

impl NetLayout {
    /// The layout of `rig`, whose coordinates are `all`.
    pub fn new(rig: &RigTopology, all: &RigCoordinates) -> Self {
        let bodies = rig.bodies.len();
        let coordinates = all.len();
        let translations_end = all.body_translations().end;
        let planets_turning_end = all.planet_rotations().end;
        let mut len = 2 * coordinates + 2 + 8;
        let mut revolution = [None; MAX_PLANT_MESHES];
        let mut tooth = [None; MAX_PLANT_MESHES];
        let mut second = [None; MAX_PLANT_MESHES];
        let mut run_out = [None; MAX_PLANT_MESHES];
        let mut spacing = [None; MAX_PLANT_MESHES];
        let mut driven_teeth = [0; MAX_PLANT_MESHES];
        let mut driver_teeth = [0; MAX_PLANT_MESHES];
        for (i, m) in rig.meshes.iter().enumerate() {
            driver_teeth[i] = m.teeth[0];
            if m.excited() {
                revolution[i] = Some(len);
                len += 2;
            }
            if m.te_mesh_frequency_um != 0.0 {
                tooth[i] = Some(len);
                len += 2;
            }
            if m.gear_error_c3_nm != 0.0 {
                second[i] = Some(len);
                len += 2;
            }
            if m.run_out_driven_um != 0.0 {
                run_out[i] = Some(len);
                driven_teeth[i] = m.teeth[1];
                len += 2;
            }
            if m.tooth_spacing_error_um != 0.0 {
                spacing[i] = Some(len);
                len += 1;
            }
        }
        Self {
            bodies,
            coordinates,
            translations_end,
            planets_turning_end,
            revolution,
            tooth,
            second,
            run_out,
            spacing,
            driver_teeth,
            driven_teeth,
            len,
        }
    }

    /// Whether any mesh turns harmonic pairs (their matrix then depends on the set speed).
    pub fn has_harmonics(&self) -> bool {
        self.revolution.iter().any(Option::is_some)
    }

    /// The harmonic pairs: (index of the cos state, mesh, harmonic of the driver's turn).
    pub fn harmonics(&self) -> Vec<(usize, usize, f64)> {
        let mut pairs = Vec::new();
        for i in 0..MAX_PLANT_MESHES {
            if let Some(index) = self.revolution[i] {
                pairs.push((index, i, 1.0));
            }
            if let Some(index) = self.tooth[i] {
                pairs.push((index, i, f64::from(self.driver_teeth[i])));
            }
            if let Some(index) = self.second[i] {
                pairs.push((index, i, 2.0));
            }
            if let Some(index) = self.run_out[i] {
                let turns = f64::from(self.driver_teeth[i]) / f64::from(self.driven_teeth[i]);
                pairs.push((index, i, turns));
            }
        }
        pairs
    }

    /// Coordinate `i` less its share of the set rotation, x_i = q_i − s_i Φ (body `i`'s
    /// angle for i < bodies).
    pub fn angle(&self, i: usize) -> usize {
        i
    }
    /// Rate of coordinate `i` (body `i`'s speed for i < bodies).
    pub fn speed(&self, i: usize) -> usize {
        self.coordinates + i
    }
    /// The filtered motor speed (rad/s).
    pub fn filtered(&self) -> usize {
        2 * self.coordinates
    }
    /// The speed error's integral (rad).
    pub fn integral(&self) -> usize {
        2 * self.coordinates + 1
    }
    /// The mechanical and controller states (the rest are forcing).
    pub fn mechanical(&self) -> usize {
        2 * self.coordinates + 2
    }
    /// The constant 1.
    pub fn unit(&self) -> usize {
        self.mechanical()
    }
    /// The motor body's set speed Ω (rad/s).
    pub fn set_speed(&self) -> usize {
        self.mechanical() + 1
    }
    /// Ω's rate (rad/s²).
    pub fn set_rate(&self) -> usize {
        self.mechanical() + 2
    }
    /// The brake's load torque (N m).
    pub fn load(&self) -> usize {
        self.mechanical() + 3
    }
    /// The load's rate (N m/s).
    pub fn load_rate(&self) -> usize {
        self.mechanical() + 4
    }
    /// A cos ψ of the oscillating load (N m); A sin ψ follows.
    pub fn oscillating(&self) -> usize {
        self.mechanical() + 5
    }
    /// The set rotation Φ (rad).
    pub fn phase(&self) -> usize {
        self.mechanical() + 7
    }
    /// The turning parts' rotation coordinates: the bodies', then the planets'.
    pub fn turning(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.bodies).chain(self.translations_end..self.planets_turning_end)
    }
    /// How many translations (x and y each) the rig's bodies and planets have.
    pub fn translations(&self) -> usize {
        (self.translations_end - self.bodies) + (self.coordinates - self.planets_turning_end)
    }
    /// Length of the state.
    pub fn len(&self) -> usize {
        self.len
    }
    /// The length rounded up to a multiple of 4: the stored state and each stored column
    /// of a matrix, padded with zeros so that products run in whole vectors.
    pub fn padded(&self) -> usize {
        self.len().div_ceil(4) * 4
    }
}
