//! One internal step of the exact plant: e^{A h} u in the current mode, then every
//! switching function checked. Where one may have crossed (a sign change, or a Hermite
//! cubic through both ends coming near zero), the step's Taylor expansion
//! u(s h) = Σ (A h)^k u / k! s^k (ρh ≤ 0.5: order 16 is exact to rounding) gives each
//! function as a polynomial; the first crossing of any is the switch, the state there is
//! the expansion's, and the rest of the step runs on in the new mode.

use std::f64::consts::PI;

use crate::error::RigError;
use crate::mode::MotorMode;
use crate::plant::SWITCH_LIMIT;
use crate::roots::{first_crossing, may_cross};
use crate::taylor::TAYLOR_ORDER;

use super::block::NetworkImpact;
use super::events::{EventForm, NetEvent, Target};
use super::mode::Contact;
use super::plant::NetworkPlant;
use super::system::ModeSystem;

impl NetworkPlant {
    /// Advances one internal step, switching wherever a function crosses.
    pub(super) fn step(&mut self) -> Result<(), RigError> {
        let mut left = 1.0;
        for _ in 0..SWITCH_LIMIT {
            let system = self.cache.get(&self.model, &self.mode);
            let span_s = left * self.step_s;
            if left == 1.0 {
                column_major_product(&system.step, &self.u, &mut self.next);
            } else {
                self.expand(&system, span_s);
                self.next = self.evaluate(1.0);
            }
            let Some((s, event)) = self.first_switch(&system, span_s, left == 1.0) else {
                std::mem::swap(&mut self.u, &mut self.next);
                return Ok(());
            };
            self.u = self.evaluate(s);
            let at_s = self.step_start_s + (1.0 - left + s * left) * self.step_s;
            self.switch(event, at_s);
            left *= 1.0 - s;
            if left <= f64::EPSILON {
                return Ok(());
            }
        }
        Err(RigError::Chatter {
            t_s: self.step_start_s,
            limit: SWITCH_LIMIT,
        })
    }

    /// The earliest crossing (fraction of the span, event) of any switching function
    /// over the span from `self.u` to `self.next`; expands the span when one may cross.
    fn first_switch(
        &mut self,
        system: &ModeSystem,
        span_s: f64,
        need_expansion: bool,
    ) -> Option<(f64, NetEvent)> {
        let mut expanded = !need_expansion;
        let mut best: Option<(f64, NetEvent)> = None;
        for form in &system.events {
            let target = self.target(form);
            let raw = form.value(&self.u) - target;
            let g0 = raw.min(0.0);
            let g1 = form.value(&self.next) - target;
            let d0 = form.rate(&self.u) * span_s;
            let d1 = form.rate(&self.next) * span_s;
            if !may_cross(g0, d0, g1, d1) {
                continue;
            }
            if !expanded {
                self.expand(system, span_s);
                expanded = true;
            }
            if let Some(s) = first_crossing(&self.coefficients(form, target))
                && best.is_none_or(|(b, _)| s < b)
            {
                best = Some((s, form.event));
            }
        }
        best
    }

    /// The value a form's target takes now.
    fn target(&self, form: &EventForm) -> f64 {
        match form.target {
            Target::Fixed => 0.0,
            Target::ZoneEnd(i) => self.zone_bounds(i, self.zones[i]).1,
            Target::ZoneStartNegated(i) => -self.zone_bounds(i, self.zones[i]).0,
            Target::Revolution => self.next_revolution_rad,
        }
    }

    /// The Taylor vectors v_k = (A τ)^k u / k! of a span τ = `span_s`.
    fn expand(&mut self, system: &ModeSystem, span_s: f64) {
        let n = self.u.len();
        self.taylor[0].copy_from_slice(&self.u);
        for k in 1..=TAYLOR_ORDER {
            let (done, rest) = self.taylor.split_at_mut(k);
            let previous = &done[k - 1];
            let out = &mut rest[0];
            out.fill(0.0);
            let scale = span_s / k as f64;
            for (col, &x) in previous.iter().enumerate() {
                if x == 0.0 {
                    continue;
                }
                let column = &system.a.as_slice()[col * n..(col + 1) * n];
                for (o, a) in out.iter_mut().zip(column) {
                    *o += a * x * scale;
                }
            }
        }
    }

    /// u(s τ) from the Taylor vectors.
    fn evaluate(&self, s: f64) -> Vec<f64> {
        let mut u = self.taylor[TAYLOR_ORDER].clone();
        for v in self.taylor[..TAYLOR_ORDER].iter().rev() {
            for (x, c) in u.iter_mut().zip(v) {
                *x = *x * s + c;
            }
        }
        u
    }

    /// The polynomial in s of a form over the expanded span, target taken off.
    fn coefficients(&self, form: &EventForm, target: f64) -> [f64; TAYLOR_ORDER + 1] {
        let mut c: [f64; TAYLOR_ORDER + 1] = std::array::from_fn(|k| form.value(&self.taylor[k]));
        c[0] -= target;
        c
    }

    /// Carries out a switch at `at_s`.
    fn switch(&mut self, event: NetEvent, at_s: f64) {
        match event {
            NetEvent::Touch(i, flank) => {
                let (_, approach_m_s) = self.model.deflection(i, &self.u);
                self.impacts.push(NetworkImpact {
                    time_s: at_s,
                    mesh: i,
                    flank,
                    approach_m_s,
                });
                self.zones[i] = self.zone_at(i);
                self.mode.meshes[i].contact = flank;
                self.mode.meshes[i].two_pairs =
                    self.model.meshes[i].alternating && self.zones[i] % 2 == 0;
            }
            NetEvent::Leave(i) => {
                self.mode.meshes[i].contact = Contact::Apart;
                self.mode.meshes[i].two_pairs = false;
            }
            NetEvent::ZoneEnd(i) | NetEvent::ZoneStart(i) => {
                self.zones[i] += if matches!(event, NetEvent::ZoneEnd(_)) {
                    1
                } else {
                    -1
                };
                self.mode.meshes[i].two_pairs = self.zones[i] % 2 == 0;
            }
            NetEvent::LimitHigh => self.mode.motor = MotorMode::LimitHigh,
            NetEvent::LimitLow => self.mode.motor = MotorMode::LimitLow,
            NetEvent::LimitRelease => self.mode.motor = MotorMode::Linear,
            NetEvent::Revolution => {
                self.revolutions_s.push(at_s);
                self.next_revolution_rad += 2.0 * PI;
            }
        }
    }
}

/// out = M u for a square column-major M.
fn column_major_product(m: &[f64], u: &[f64], out: &mut [f64]) {
    let n = u.len();
    out.fill(0.0);
    for (col, &x) in u.iter().enumerate() {
        if x == 0.0 {
            continue;
        }
        for (o, a) in out.iter_mut().zip(&m[col * n..(col + 1) * n]) {
            *o += a * x;
        }
    }
}
