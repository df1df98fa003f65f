//! One internal step of the exact plant: e^{A h} u in the current mode, then every
//! switching function checked. Where one may have crossed (a sign change, or a Hermite
//! cubic through both ends coming near zero), the step's Taylor expansion
//! u(s h) = Σ (A h)^k u / k! s^k (to the order ρh needs to be exact to rounding) gives each
//! function as a polynomial; the first crossing of any is the switch, the state there is
//! the expansion's, and the rest of the step runs on in the new mode.

use std::f64::consts::PI;

use crate::error::RigError;
use crate::mode::{MotorMode, PairZone};
use crate::roots::{AT_START, DUE_NOW, due_at_start, first_crossing};
use crate::taylor::{TAYLOR_ORDER, taylor_order};

use super::block::NetworkImpact;
use super::events::{EventForm, NetEvent, Target};
use super::mode::{Contact, MeshState};
use super::network_plant::NetworkPlant;
use super::products;
use super::span_gaps::SpanGaps;
use super::system::ModeSystem;
use super::system_cache::SystemCache;

/// Most switches handled within one internal step before the run is declared chattering.
pub const SWITCH_LIMIT: usize = 64;

/// How far inside the torque limit a released controller command starts (N m): far above
/// the rounding of the command (~1e-13 N m), far below anything measurable.
pub const RELEASE_MARGIN_NM: f64 = 1e-9;

impl NetworkPlant {
    /// Advances one internal step, switching wherever a function crosses.
    pub(super) fn step(&mut self) -> Result<(), RigError> {
        let Some(mut cache) = self.cache.take() else {
            return Err(RigError::Schedule(
                "a step began inside another (the plant's cache was out)".into(),
            ));
        };
        let result = self.step_with(&mut cache);
        self.cache = Some(cache);
        result
    }

    /// [`Self::step`] with the cache of modes held apart from the plant.
    fn step_with(&mut self, cache: &mut SystemCache) -> Result<(), RigError> {
        let mut left = 1.0;
        let mut system = cache.get(&self.model, &self.mode);
        for _ in 0..SWITCH_LIMIT {
            let span_s = left * self.step_s;
            let found = if left == 1.0 {
                self.fused_step(system);
                self.first_switch(system, span_s, true)
            } else {
                self.rest_of_step(system, span_s)
            };
            let Some((s, event)) = found else {
                self.take_span_end();
                return Ok(());
            };
            evaluate(&self.taylor[..=self.taylor_order], s, &mut self.u);
            self.edge.clear();
            let at_s = self.step_start_s + (1.0 - left + s * left) * self.step_s;
            self.switch(event, at_s);
            // The mode switched into, and its targets (held until the next switch).
            system = cache.get(&self.model, &self.mode);
            self.fill_targets(system);
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

    /// The rest of a step after a switch, `span_s` long, in the new mode: where meshes
    /// share an angle (`ModeSystem::meshes_share_an_angle`), a function due at once
    /// (another switch at the same instant, as every planet's mesh of an in-phase stage)
    /// is found from the expansion's first two vectors ([`due_at_start`]) and taken
    /// without the rest of it; else the span is expanded, its end state and functions'
    /// ends written, and its first crossing sought.
    fn rest_of_step(&mut self, system: &ModeSystem, span_s: f64) -> Option<(f64, NetEvent)> {
        self.expand_first(system, span_s);
        if system.meshes_share_an_angle
            && let Some(event) = self.due_at_once(system, span_s)
        {
            return Some((AT_START, event));
        }
        self.expand_rest(system, span_s);
        evaluate(&self.taylor[..=self.taylor_order], 1.0, &mut self.next);
        system.ends_at(
            &self.next,
            self.model.layout.unit(),
            &mut self.fused_out,
            &mut self.next_edge,
        );
        self.first_switch(system, span_s, false)
    }

    /// The switching function [`Self::first_switch`] would take at the start of the span
    /// of `span_s` expanded to its first order, where that is sure without the rest of
    /// the expansion: the first (in the mode's order, as it takes ties) at or past its
    /// target that [`due_at_start`] finds due and whose rate at the start is rising (so
    /// that the search's check, [`SpanGaps::may_reach`], lets it through), if every
    /// function before it is short of its target or found not due. Only functions of the
    /// set rotation (zone ends and starts, tooth passes, revolutions) are decided so: their
    /// first coefficient is a gear's turn over the span, far from zero while it turns. A
    /// contact or limit function at or past its target (one grazing it: its peak within
    /// 10⁻¹¹ of a step, which the search cannot resolve) and any function [`due_at_start`]
    /// leaves undecided give none: the whole expansion decides. Reads the targets from
    /// `self.targets`.
    fn due_at_once(&self, system: &ModeSystem, span_s: f64) -> Option<NetEvent> {
        for (form, target) in system.events.iter().zip(&self.targets) {
            let start = form.value(&self.taylor[0]) - target;
            if start < 0.0 {
                continue;
            }
            if form.target == Target::Fixed {
                return None;
            }
            match due_at_start(start, form.value(&self.taylor[1])) {
                Some(true) if form.rate(&self.u) * span_s > 0.0 => return Some(form.event),
                Some(false) => {}
                _ => return None,
            }
        }
        None
    }

    /// A whole step in one product: `self.next` the state at its end (the forcing states
    /// advanced apart), `self.next_edge` each switching function's value and rate there.
    pub(super) fn fused_step(&mut self, system: &ModeSystem) {
        let mechanical = self.model.layout.mechanical();
        if self.fused_out.len() < system.end_rows() {
            self.fused_out.resize(system.end_rows(), 0.0);
        }
        products::rows(
            &system.step.fused,
            system.fused_rows,
            &self.u,
            1.0,
            &mut self.fused_out,
        );
        products::copy_short(&mut self.next[..mechanical], &self.fused_out[..mechanical]);
        if self.forcing_out.len() < system.forcing_rows {
            self.forcing_out.resize(system.forcing_rows, 0.0);
        }
        let forcing = self.next.len().min(mechanical + system.forcing_rows) - mechanical;
        products::rows(
            &system.step.forcing,
            system.forcing_rows,
            &self.u[mechanical..],
            1.0,
            &mut self.forcing_out,
        );
        self.next[mechanical..mechanical + forcing].copy_from_slice(&self.forcing_out[..forcing]);
        self.fill_next_edge(system);
    }

    /// Each switching function's value and rate at `self.next` into `self.next_edge`.
    fn fill_next_edge(&mut self, system: &ModeSystem) {
        system.read_ends(
            &self.next,
            self.model.layout.unit(),
            &mut self.fused_out,
            &mut self.next_edge,
        );
    }

    /// Moves to the end of the span just taken: `self.next` and `self.next_edge` become
    /// the state and the functions' values and rates (the old ones left as scratch).
    /// The edges swap first: the other order made the second swap's load overlap the
    /// first's stores, a stall that cost the fast run 13 % (measured).
    #[inline(always)]
    pub(super) fn take_span_end(&mut self) {
        std::mem::swap(&mut self.edge, &mut self.next_edge);
        std::mem::swap(&mut self.u, &mut self.next);
    }

    /// The earliest crossing (fraction of the span, event) of any switching function
    /// over the span from `self.u` to `self.next` (their values and rates there in
    /// `self.next_edge`, kept for the next step); expands the span when one may cross.
    fn first_switch(
        &mut self,
        system: &ModeSystem,
        span_s: f64,
        need_expansion: bool,
    ) -> Option<(f64, NetEvent)> {
        debug_assert_eq!(
            self.targets.len(),
            system.events.len(),
            "the mode's targets"
        );
        let mut expanded = !need_expansion;
        let mut best: Option<(f64, NetEvent)> = None;
        let known = self.edge.len() == system.events.len();
        for (k, form) in system.events.iter().enumerate() {
            let target = self.targets[k];
            let (value_0, rate_0) = if known {
                self.edge[k]
            } else {
                (form.value(&self.u), form.rate(&self.u))
            };
            let gaps = SpanGaps::of((value_0, rate_0), self.next_edge[k], target, span_s);
            if !gaps.may_reach(false) {
                continue;
            }
            if !expanded {
                self.expand(system, span_s);
                expanded = true;
            }
            // The polynomial to the expansion's order: Horner over the zeros above it
            // gives +0 and changes no bit, only costs time (a fifth of the search's on
            // the planetary bench).
            let coefficients = self.coefficients(form, target);
            let before = best.map_or(f64::INFINITY, |(b, _)| b);
            if let Some(s) = first_crossing(&coefficients[..=self.taylor_order], before) {
                best = Some((s, form.event));
            }
        }
        best
    }

    /// The value a form's target takes now.
    pub(super) fn target(&self, form: &EventForm) -> f64 {
        match form.target {
            Target::Fixed => 0.0,
            Target::ZoneEnd(i) => self.zone_bounds(i, self.zones[i]).1,
            Target::ZoneStartNegated(i) => -self.zone_bounds(i, self.zones[i]).0,
            Target::Revolution => self.next_revolution_rad,
            Target::Tooth(i) => self.next_tooth_rad[i],
        }
    }

    /// Mesh `i`'s `flank` meets the pair in mesh at `at_s` (its zone known): an impact,
    /// the flank in contact with the zone's pairs; where the pair in mesh is broken
    /// through, no tooth is there to meet, and the mesh stays apart until the next pair.
    fn engage(&mut self, i: usize, flank: Contact, at_s: f64) {
        let m = &self.model.meshes[i];
        let zone = self.zones[i];
        let factor = m.zone_factor(zone);
        let state = &mut self.mode.meshes[i];
        state.level = m.level(zone);
        state.factor_bits = factor.to_bits();
        if factor == 0.0 {
            state.contact = Contact::Apart;
            state.toothless = true;
            state.clipped = false;
            return;
        }
        state.contact = flank;
        state.toothless = false;
        state.clipped = false;
        let (_, approach_m_s) = self.model.deflection(i, f64::from(flank.sign()), &self.u);
        // The pair that strikes: the one coming into mesh in a double-pair stretch.
        let m = &self.model.meshes[i];
        let teeth = m.pair_teeth(m.pair_of_zone(zone));
        self.impacts.push(NetworkImpact {
            time_s: at_s,
            mesh: i,
            flank,
            approach_m_s,
            teeth,
        });
    }

    /// Mesh `i`'s driver has turned into a new pair zone: the pairs in mesh take their
    /// stiffness and spacing error. In contact, a zone whose pair is broken through parts
    /// the teeth, as does a pair whose spacing error opens the gap; after a broken pair,
    /// or apart where the new pair's spacing error closes the gap, the pair strikes
    /// wherever the gears have closed on a flank.
    pub(super) fn enter_zone(&mut self, i: usize, at_s: f64) {
        self.set_spacing(i);
        let m = &self.model.meshes[i];
        let zone = self.zones[i];
        let factor = m.zone_factor(zone);
        let state = self.mode.meshes[i];
        if state.toothless || (state.contact == Contact::Apart && m.spaced()) {
            if factor == 0.0 {
                return;
            }
            let speed = self.harmonic_speed_rad_s;
            let drive = self.model.overlap(i, 1.0, &self.u, speed).0 > 0.0;
            let back = self.model.overlap(i, -1.0, &self.u, speed).0 < 0.0;
            self.mode.meshes[i].toothless = false;
            if drive || back {
                // Struck at a pair's entry: that tooth pass is behind it (no shifting).
                self.pass_tooth_here(i);
            }
            match (drive, back) {
                (true, _) => self.engage(i, Contact::Drive, at_s),
                (false, true) => self.engage(i, Contact::Back, at_s),
                (false, false) => self.mode.meshes[i] = MeshState::APART,
            }
            return;
        }
        let spaced = m.spaced();
        let state = &mut self.mode.meshes[i];
        state.level = m.level(zone);
        state.factor_bits = factor.to_bits();
        if factor == 0.0 {
            state.contact = Contact::Apart;
            state.level = PairZone::ONE;
            state.toothless = true;
            state.clipped = false;
            return;
        }
        let flank = state.contact.sign();
        // At a tooth pass with the thesis's tooth shifting, the pass itself decides
        // whether the new pair stays in contact (`shift_tooth`, next at this instant).
        let tooth_pass_decides = m.tooth_shifting && m.zones.starts_period(zone);
        if spaced && flank != 0 && !tooth_pass_decides {
            let flank = f64::from(flank);
            let speed = self.harmonic_speed_rad_s;
            if flank * self.model.overlap(i, flank, &self.u, speed).0 < 0.0 {
                self.mode.meshes[i] = MeshState::APART;
            } else {
                self.reclip(i);
            }
        }
    }

    /// Leaves the motor's limit: the command, held there up to rounding, starts just
    /// inside it (by [`RELEASE_MARGIN_NM`]) so that rounding
    /// cannot put it straight back (a tangency of the command with the limit would else
    /// switch at zero progress until the step gave up).
    fn release_motor(&mut self) {
        let Some(m) = &self.model.motor else {
            return;
        };
        let Some(limit) = m.limit_nm else {
            return;
        };
        let inside = match self.mode.motor {
            MotorMode::LimitHigh => limit - RELEASE_MARGIN_NM,
            MotorMode::LimitLow => -limit + RELEASE_MARGIN_NM,
            MotorMode::Linear => return,
        };
        let (ki, integral) = (m.ki_nm_per_rad, self.model.layout.integral());
        if ki > 0.0 {
            let command = self.model.controller_nm(&self.u);
            self.u[integral] += (inside - command) / ki;
        }
        self.mode.motor = MotorMode::Linear;
    }

    /// The Taylor vectors v_k = (A τ)^k u / k! of a span τ = `span_s`, up to the order
    /// the mode's fastest motion needs over the span (`taylor_order`).
    fn expand(&mut self, system: &ModeSystem, span_s: f64) {
        self.expand_first(system, span_s);
        self.expand_rest(system, span_s);
    }

    /// The order of [`Self::expand`] and its vectors v_0 and v_1.
    fn expand_first(&mut self, system: &ModeSystem, span_s: f64) {
        self.taylor_order = taylor_order(system.rho_rad_s * span_s);
        self.taylor[0].copy_from_slice(&self.u);
        self.expand_orders(system, span_s, 1..=1);
    }

    /// [`Self::expand`]'s vectors after [`Self::expand_first`]'s, v_2 to its order.
    fn expand_rest(&mut self, system: &ModeSystem, span_s: f64) {
        self.expand_orders(system, span_s, 2..=self.taylor_order);
    }

    /// The Taylor vectors v_k = (A τ) v_{k−1} / k of the orders `orders`, each from the
    /// one before it.
    fn expand_orders(
        &mut self,
        system: &ModeSystem,
        span_s: f64,
        orders: std::ops::RangeInclusive<usize>,
    ) {
        for k in orders {
            let (done, rest) = self.taylor.split_at_mut(k);
            let out = &mut rest[0];
            let scale = span_s / k as f64;
            system.a.product(&done[k - 1], scale, out);
        }
    }

    /// The polynomial in s of a form over the expanded span, target taken off.
    fn coefficients(&self, form: &EventForm, target: f64) -> [f64; TAYLOR_ORDER + 1] {
        let order = self.taylor_order;
        let mut c: [f64; TAYLOR_ORDER + 1] = std::array::from_fn(|k| {
            if k <= order {
                form.value(&self.taylor[k])
            } else {
                0.0
            }
        });
        c[0] -= target;
        c
    }

    /// Carries out a switch at `at_s`.
    fn switch(&mut self, event: NetEvent, at_s: f64) {
        match event {
            NetEvent::Touch(i, flank) => {
                self.zones[i] = self.zone_at(i);
                self.set_spacing(i);
                self.catch_up_tooth(i);
                self.engage(i, flank, at_s);
            }
            NetEvent::Leave(i) => {
                self.mode.meshes[i].contact = Contact::Apart;
                self.mode.meshes[i].level = PairZone::ONE;
                self.mode.meshes[i].clipped = false;
            }
            NetEvent::Unload(i) => self.mode.meshes[i].clipped = true,
            NetEvent::Reload(i) => self.mode.meshes[i].clipped = false,
            NetEvent::ZoneEnd(i) | NetEvent::ZoneStart(i) => {
                self.zones[i] += if matches!(event, NetEvent::ZoneEnd(_)) {
                    1
                } else {
                    -1
                };
                self.enter_zone(i, at_s);
            }
            NetEvent::LimitHigh => self.mode.motor = MotorMode::LimitHigh,
            NetEvent::LimitLow => self.mode.motor = MotorMode::LimitLow,
            NetEvent::LimitRelease => self.release_motor(),
            NetEvent::ToothPass(i) => self.shift_tooth(i, at_s),
            NetEvent::Revolution => {
                self.revolutions_s.push(at_s);
                self.next_revolution_rad += 2.0 * PI;
            }
        }
    }
}

/// u(s τ) from the Taylor vectors `taylor` (v_0 to the expansion's order), written into
/// `u` (Horner). At s below [`DUE_NOW`] (a switch due at the span's start, s the least
/// positive number) u is v_0 to rounding, and is copied: Horner's products by a
/// subnormal s each took a microcode assist, over half the exact path's time on an
/// in-phase planetary stage (measured).
fn evaluate(taylor: &[Vec<f64>], s: f64, u: &mut [f64]) {
    if s < DUE_NOW {
        u.copy_from_slice(&taylor[0]);
        return;
    }
    let (last, lower) = taylor.split_last().expect("v_0 at least");
    u.copy_from_slice(last);
    for v in lower.iter().rev() {
        for (x, c) in u.iter_mut().zip(v) {
            *x = *x * s + c;
        }
    }
}
