//! Per mode: A, e^{A h} and the switching functions, built when the mode is first met
//! and kept until the oscillating load's frequency changes.

use std::collections::HashMap;
use std::sync::Arc;

use nalgebra::DMatrix;

use crate::matrix_exp::{exp_powers_balanced, forcing_scales, spectral_radius};

use super::events::{EventForm, event_forms};
use super::mode::NetMode;
use super::model::NetworkModel;

/// One mode's linear system.
#[derive(Debug)]
pub struct ModeSystem {
    /// A of u' = A u.
    pub a: DMatrix<f64>,
    /// e^{A h}, column-major.
    pub step: Vec<f64>,
    /// The switching functions.
    pub events: Vec<EventForm>,
}

/// The modes met so far.
#[derive(Debug)]
pub struct SystemCache {
    systems: HashMap<NetMode, Arc<ModeSystem>>,
    step_s: f64,
    rho: f64,
    oscillating_rad_s: f64,
}

impl SystemCache {
    /// An empty cache for steps of `step_s`, ρ the fastest rate of any mode (rad/s).
    pub fn new(step_s: f64, rho: f64) -> Self {
        Self {
            systems: HashMap::new(),
            step_s,
            rho,
            oscillating_rad_s: 0.0,
        }
    }

    /// Sets the oscillating load's frequency (rad/s); a change empties the cache.
    pub fn set_oscillating(&mut self, rad_s: f64) {
        if rad_s != self.oscillating_rad_s {
            self.systems.clear();
            self.oscillating_rad_s = rad_s;
        }
    }

    /// The system of `mode`, built if new.
    pub fn get(&mut self, model: &NetworkModel, mode: &NetMode) -> Arc<ModeSystem> {
        if let Some(s) = self.systems.get(mode) {
            return Arc::clone(s);
        }
        let a = model.system_matrix(mode, self.oscillating_rad_s);
        let step = exp_step(model, &a, self.step_s, self.rho);
        let events = event_forms(model, mode, &a);
        let system = Arc::new(ModeSystem { a, step, events });
        self.systems.insert(*mode, Arc::clone(&system));
        system
    }
}

/// e^{A h} column-major, balanced as the 1983 plant's: angles and the integral at 1,
/// speeds and the filtered speed at ρ, forcing states scaled to ρ, the oscillating
/// load's two states alike.
fn exp_step(model: &NetworkModel, a: &DMatrix<f64>, step_s: f64, rho: f64) -> Vec<f64> {
    let l = model.layout;
    let rho = rho.max(1.0);
    let mechanical: Vec<f64> = (0..l.mechanical())
        .map(|i| {
            if (l.speed(0)..l.speed(0) + l.bodies).contains(&i) || i == l.filtered() {
                rho
            } else {
                1.0
            }
        })
        .collect();
    let mut scale = forcing_scales(a, &mechanical, rho);
    // The oscillating pair turns one into the other: one scale for both, else the
    // balanced rotation's entries would be as large as their ratio.
    let pair = l.oscillating();
    let shared = scale[pair].max(scale[pair + 1]);
    scale[pair] = shared;
    scale[pair + 1] = shared;
    exp_powers_balanced(a, step_s, &scale, 1)
        .remove(0)
        .as_slice()
        .to_vec()
}

/// The fastest rate (rad/s) of `model`: A's spectral radius with every mesh on its drive
/// flank with two pairs where pairs alternate (the stiffest mode).
pub fn fastest_rate(model: &NetworkModel) -> f64 {
    let mut mode = NetMode::apart();
    for (state, m) in mode.meshes.iter_mut().zip(&model.meshes) {
        state.contact = super::mode::Contact::Drive;
        state.two_pairs = m.alternating;
    }
    spectral_radius(&model.system_matrix(&mode, 0.0))
}
