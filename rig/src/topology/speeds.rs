//! The speeds a rig's joints set: each body's share of the motor's speed, spread from the
//! bodies the frame holds still (0) and then from the first body left (1) through shafts
//! (1), external meshes (−z₁/z₂) and planetary stages (rolling on the base circles once
//! two of sun, ring and carrier are known). `check.rs` refuses a rig they leave unset or
//! whose loops they do not close.

use super::rig_topology::RigTopology;

impl RigTopology {
    /// Each body's speed per unit speed of the first body not held to the frame (held
    /// ones 0), propagated through shafts (1), meshes (−z₁/z₂) and planetary stages
    /// (Willis's equation, once two of sun, ring and carrier are known); `None` for a
    /// body not reached.
    pub fn relative_speeds(&self) -> Vec<Option<f64>> {
        let mut speed: Vec<Option<f64>> = vec![None; self.bodies.len()];
        for s in &self.frame_shafts {
            speed[s.body] = Some(0.0);
        }
        // What the frame holds still first, then the first body left turns at 1.
        self.propagate_speeds(&mut speed);
        let Some(reference) = speed.iter().position(Option::is_none) else {
            return speed;
        };
        speed[reference] = Some(1.0);
        self.propagate_speeds(&mut speed);
        speed
    }

    /// Spreads the known speeds in `speed` through every joint and stage until none
    /// changes.
    fn propagate_speeds(&self, speed: &mut [Option<f64>]) {
        loop {
            let mut changed = false;
            for (a, b, ratio) in self.joints() {
                match (speed[a], speed[b]) {
                    (Some(x), None) => {
                        speed[b] = Some(x * ratio);
                        changed = true;
                    }
                    (None, Some(y)) => {
                        speed[a] = Some(y / ratio);
                        changed = true;
                    }
                    _ => {}
                }
            }
            for stage in &self.planetary {
                let known = [stage.sun, stage.ring, stage.carrier].map(|b| speed[b]);
                if known.iter().all(Option::is_some) {
                    continue;
                }
                if let Some(all) = stage.willis(known[0], known[1], known[2]) {
                    for (body, v) in [stage.sun, stage.ring, stage.carrier].into_iter().zip(all) {
                        speed[body] = Some(v);
                    }
                    changed = true;
                }
            }
            if !changed {
                return;
            }
        }
    }

    /// Every joint as (body, body, speed of the second per unit speed of the first).
    pub(super) fn joints(&self) -> impl Iterator<Item = (usize, usize, f64)> + '_ {
        let shafts = self
            .shafts
            .iter()
            .map(|s| (s.between[0], s.between[1], 1.0));
        let meshes = self
            .meshes
            .iter()
            .map(|m| (m.gears[0], m.gears[1], m.speed_ratio()));
        shafts.chain(meshes)
    }
}
