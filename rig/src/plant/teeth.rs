//! A mesh's teeth as the plant follows them: the pair zone its driver is in (and the
//! spacing error that zone's pairs carry), the next tooth boundary, the thesis's tooth
//! shifting at a tooth pass, and the no-pull law's clipping decided again there.

use crate::mode::PairZone;

use super::mode::Contact;
use super::network_plant::NetworkPlant;

/// Most ulps [`NetworkPlant::touch_after_hand_back`] moves a gear by: the hand-back's
/// rounding is an ulp or two of each angle.
const MAX_NUDGES: usize = 8;

impl NetworkPlant {
    /// Each alternating mesh's pair zone from its driver's angle, and its next tooth
    /// boundary.
    pub(super) fn set_zones_from_angles(&mut self) {
        for i in 0..self.model.meshes.len() {
            self.zones[i] = self.zone_at(i);
            self.set_spacing(i);
            self.next_tooth_rad[i] = f64::NEG_INFINITY;
            self.catch_up_tooth(i);
        }
    }

    /// Mesh `i`'s spacing-error state takes the pair zone's error (no change without
    /// spacing errors).
    pub(super) fn set_spacing(&mut self, i: usize) {
        if let Some(index) = self.model.layout.spacing[i] {
            self.u[index] = self.model.meshes[i].zone_spacing_m(self.zones[i]);
        }
    }

    /// Mesh `i`'s next tooth boundary the one after the boundary its driver stands at (a
    /// pair engaged at its entry: no tooth pass there).
    pub(super) fn pass_tooth_here(&mut self, i: usize) {
        let m = &self.model.meshes[i];
        let angle = m.zone_share.signum() * self.model.zone_angle_rad(i, &self.u);
        self.next_tooth_rad[i] = ((angle / m.pitch_rad).round() + 1.0) * m.pitch_rad;
    }

    /// Moves mesh `i`'s next tooth boundary to the first above its driver's angle (in
    /// its sense of rotation), never backwards: apart, a tooth pass changes nothing.
    pub(super) fn catch_up_tooth(&mut self, i: usize) {
        let m = &self.model.meshes[i];
        let angle = m.zone_share.signum() * self.model.zone_angle_rad(i, &self.u);
        let ahead = ((angle / m.pitch_rad).floor() + 1.0) * m.pitch_rad;
        self.next_tooth_rad[i] = self.next_tooth_rad[i].max(ahead);
    }

    /// A tooth pass of mesh `i` in contact with tooth shifting (thesis §5.4.5): the
    /// loaded pair hands its overlap back, each gear moving by half of it along the line
    /// of action; the next pair stays in contact only while the flanks close.
    pub(super) fn shift_tooth(&mut self, i: usize, at_s: f64) {
        let pitch = self.model.meshes[i].pitch_rad;
        self.next_tooth_rad[i] += pitch;
        if self.model.meshes[i].spaced() {
            // The next pair takes its spacing error first (its zone entered here, not a
            // rounding later), then hands back the overlap, as the thesis's pass does.
            self.zones[i] = self.zone_after_pass(i);
            self.enter_zone(i, at_s);
        }
        let l = &self.model.layout;
        let m = &self.model.meshes[i];
        let flank = match self.mode.meshes[i].contact {
            Contact::Drive => 1.0,
            Contact::Back => -1.0,
            Contact::Apart => return,
        };
        let speed = self.harmonic_speed_rad_s;
        let (overlap, rate) = self.model.overlap(i, flank, &self.u, speed);
        if flank * overlap > 0.0 {
            let [ga, gb] = m.gears;
            self.u[l.angle(ga)] -= 0.5 * overlap / m.radii_m[0];
            self.u[l.angle(gb)] -= 0.5 * overlap / m.radii_m[1];
        }
        if flank * rate <= 0.0 {
            self.mode.meshes[i].contact = Contact::Apart;
            self.mode.meshes[i].level = PairZone::ONE;
            self.mode.meshes[i].clipped = false;
        } else {
            self.touch_after_hand_back(i, flank);
            self.reclip(i);
        }
    }

    /// The flanks of mesh `i` (`flank` +1 drive, −1 back) kept touching after a hand-back:
    /// it leaves the overlap at 0 to the rounding of the angles (an ulp of ~400 rad is
    /// 6e-14 rad, a few 1e-15 m at the teeth), and a residual on the apart side with the
    /// teeth at relative rest had them leave and strike again nanoseconds later, an
    /// impact of rounding's (seen on the 1983 rig at 600 rev/min, docs/plant-numerics.md).
    /// The driven gear's angle moves by single ulps until the overlap is ≥ 0 (a few at
    /// most).
    fn touch_after_hand_back(&mut self, i: usize, flank: f64) {
        let m = &self.model.meshes[i];
        let driven = m.gears[1];
        let Some((_, c)) = m.terms(flank).find(|&(j, _)| j == driven) else {
            return;
        };
        let angle = self.model.layout.angle(driven);
        let speed = self.harmonic_speed_rad_s;
        for _ in 0..MAX_NUDGES {
            let (overlap, _) = self.model.overlap(i, flank, &self.u, speed);
            if flank * overlap >= 0.0 {
                return;
            }
            let theta = self.u[angle];
            self.u[angle] = if flank * c > 0.0 {
                theta.next_up()
            } else {
                theta.next_down()
            };
        }
        debug_assert!(
            flank * self.model.overlap(i, flank, &self.u, speed).0 >= 0.0,
            "mesh {i}: the flanks still apart after {MAX_NUDGES} ulps"
        );
    }

    /// With the no-pull law, mesh `i` on a flank is clipped where its spring would not
    /// push there now (as the thesis decides at a tooth pass).
    pub(super) fn reclip(&mut self, i: usize) {
        let state = self.mode.meshes[i];
        if !self.model.meshes[i].no_pull || state.contact == Contact::Apart {
            return;
        }
        let flank = f64::from(state.contact.sign());
        let speed = self.harmonic_speed_rad_s;
        let force = self
            .model
            .mesh_force_n(i, state.unclipped(), &self.u, speed);
        self.mode.meshes[i].clipped = flank * force <= 0.0;
    }

    /// The pair zone mesh `i`'s driver enters at a tooth pass: the next period's first
    /// (its driver turning forward), or the last period's single stretch (backward).
    fn zone_after_pass(&self, i: usize) -> i64 {
        let m = &self.model.meshes[i];
        let period = (self.model.zone_angle_rad(i, &self.u) / m.pitch_rad).round();
        let entering = m.zones.entering(period as i64);
        if m.zone_share > 0.0 {
            entering
        } else {
            entering - 1
        }
    }

    /// The pair zone mesh `i`'s driver is in (`rig::pair_zones`: without smoothing 2k
    /// over the first ε − 1 of period k, 2k + 1 over the rest).
    pub(super) fn zone_at(&self, i: usize) -> i64 {
        let m = &self.model.meshes[i];
        let phase = self.model.zone_angle_rad(i, &self.u) / m.pitch_rad;
        m.zones.zone_at(phase)
    }

    /// The start and end (rad of the driver) of pair zone `zone` of mesh `i`.
    pub(super) fn zone_bounds(&self, i: usize, zone: i64) -> (f64, f64) {
        let m = &self.model.meshes[i];
        let (start, end) = m.zones.bounds(zone);
        (start * m.pitch_rad, end * m.pitch_rad)
    }
}

#[cfg(test)]
mod tests {
    use rand::{RngExt, SeedableRng};

    use super::super::mode::Contact;
    use super::super::network_plant::{NetworkPlant, NetworkStart};
    use crate::{Schedule, preset, preset_rig};

    /// A tooth pass on the 1983 rig in steady motion, the teeth closing slowly
    /// (3.5e-8 m/s, as seen at 600 rev/min): the hand-back leaves the flanks touching,
    /// overlap ≥ 0, wherever rounding puts it. Each trial moves the gears by a few ulps
    /// first, so that the hand-back's rounding falls on either side of zero (it did, half
    /// the time, before the flanks were kept touching).
    #[test]
    fn a_hand_back_leaves_the_flanks_touching_whatever_the_rounding() {
        hand_backs_keep_the_flanks_touching(2.712, Contact::Drive);
    }

    /// The same on the back flank: the brake driving the rig (a negative load), the
    /// driven gear nudged the other way.
    #[test]
    fn a_hand_back_on_the_back_flank_leaves_the_flanks_touching() {
        hand_backs_keep_the_flanks_touching(-2.712, Contact::Back);
    }

    /// 200 hand-backs at 600 rev/min under `load_nm`, the teeth on `flank`: each leaves
    /// the flanks touching, and rounding had left them apart in some and not in others.
    fn hand_backs_keep_the_flanks_touching(load_nm: f64, flank: Contact) {
        let sign = f64::from(flank.sign());
        let params = preset("basmaji-1983").expect("preset");
        let rig = preset_rig("test", "the 1983 rig", &params);
        let schedule = Schedule::constant(600.0, load_nm);
        let mut steady =
            NetworkPlant::new(&rig, schedule, 10_240.0, NetworkStart::Steady).expect("plant");
        steady.skip(1).expect("runs");
        // Sixty turns on, as at 6 s of a run from rest: an ulp of the angles is then a few
        // 1e-15 m at the teeth (near 0 rad, the hand-back's rounding is far finer).
        let turns = 60.0 * std::f64::consts::TAU;
        for (j, ratio) in steady.model.speed_ratio.clone().into_iter().enumerate() {
            let angle = steady.model.layout.angle(j);
            steady.u[angle] += turns * ratio;
        }
        let mut rng = rand_pcg::Pcg64Mcg::seed_from_u64(47);
        let mesh = 0;
        let [driver, driven] = steady.model.meshes[mesh].gears;
        let l = &steady.model.layout;
        let (driver_angle, driven_angle) = (l.angle(driver), l.angle(driven));
        let driven_speed = l.speed(driven);
        let radius_m = steady.model.meshes[mesh].radii_m[1];
        // The overlap's rate per unit speed of the driven gear (m).
        let lever_m = steady.model.meshes[mesh]
            .terms(sign)
            .find(|&(j, _)| j == driven)
            .map(|(_, c)| c)
            .expect("the driven gear turns the overlap");
        let speed = steady.harmonic_speed_rad_s;
        let in_mesh = sign * steady.model.overlap(mesh, sign, &steady.u, speed).0;
        assert!(
            in_mesh > 1e-8,
            "turned on, the teeth carry the load: {in_mesh:e} m"
        );
        let mut nudged = 0;
        for _ in 0..200 {
            let mut plant = steady.clone();
            assert_eq!(plant.mode.meshes[mesh].contact, flank);
            for _ in 0..rng.random_range(0..8) {
                plant.u[driver_angle] = plant.u[driver_angle].next_up();
            }
            // The driven gear's speed set so that the flanks close at 3.5e-8 m/s.
            let (_, rate) = plant.model.overlap(mesh, sign, &plant.u, speed);
            plant.u[driven_speed] += (sign * 3.5e-8 - rate) / lever_m;
            let (_, rate) = plant.model.overlap(mesh, sign, &plant.u, speed);
            assert!(
                sign * rate > 0.0,
                "the flanks must close: rate {rate:e} m/s"
            );
            // Where the hand-back alone would leave the driven gear (as `shift_tooth`
            // computes it): moved from there, the flanks had been left apart.
            let (before, _) = plant.model.overlap(mesh, sign, &plant.u, speed);
            let handed_back = plant.u[driven_angle] - 0.5 * before / radius_m;
            plant.shift_tooth(mesh, 0.0);
            nudged += usize::from(plant.u[driven_angle] != handed_back);
            let (overlap, _) = plant.model.overlap(mesh, sign, &plant.u, speed);
            assert_eq!(plant.mode.meshes[mesh].contact, flank);
            assert!(
                (0.0..1e-13).contains(&(sign * overlap)),
                "after the hand-back: overlap {overlap:e} m"
            );
        }
        // Both sides of zero came up: the rounding left the flanks apart in some trials
        // and in mesh in others.
        assert!(
            (20..=180).contains(&nudged),
            "{nudged} of 200 hand-backs left the flanks apart"
        );
    }
}
