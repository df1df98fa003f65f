//! A mesh's teeth as the plant follows them: the pair zone its driver is in (and the
//! spacing error that zone's pairs carry), the next tooth boundary, the thesis's tooth
//! shifting at a tooth pass, and the no-pull law's clipping decided again there.

use crate::mode::PairZone;

use super::mode::Contact;
use super::network_plant::NetworkPlant;

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
            self.reclip(i);
        }
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
