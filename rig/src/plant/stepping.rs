//! The stepping loop: the fast exact step, the checks for switches within it, and the
//! exact path that locates every switch and continues from it.

use crate::error::RigError;
use crate::events::{EventFn, EventKind};
use crate::fused_step::{FUSED_ROWS, FusedRows, MAX_ROW_EVENTS};
use crate::jump_response::GEAR_ANGLES;
use crate::layout::{Layout, N_MECH, V0, X0};
use crate::propagator::ModeSystem;
use crate::roots::{first_crossing, may_cross};
use crate::taylor::TAYLOR_ORDER;

use super::segment_start::rotate;
use super::state::{Plant, RESYNC_STEPS, SWITCH_LIMIT};

impl Plant {
    /// One internal step, handling every switch inside it.
    pub(super) fn advance_step(&mut self) -> Result<(), RigError> {
        if Some(self.step_index) == self.segment.end_step {
            self.begin_segment();
        } else if self.step_index.is_multiple_of(RESYNC_STEPS) {
            self.resync_harmonics(0.0);
        }
        self.cache.ensure(self.mode);
        let system = self.cache.built(self.mode);
        let fused = system.step(&self.u);
        let start = self
            .edge
            .unwrap_or_else(|| system.row_event_values(&self.u));
        let targets = self.angle_targets(system);
        let crossing = StepEnds {
            start: &start,
            end: &fused,
            u0: &self.u,
            phase_rad: self.phase_rad(0.0),
            speed_rad_s: self.segment.set.speed_rad_s(),
            step_s: self.step_s,
        };
        let mut end = self.u;
        end[..N_MECH].copy_from_slice(&fused[..N_MECH]);
        rotate(&mut end, self.cache.rotations());
        if crossing.may_switch(&targets) {
            self.edge = None;
            self.advance_exactly(end)?;
        } else {
            self.u = end;
            let mut edge = [0.0; 2 * MAX_ROW_EVENTS];
            edge.copy_from_slice(&fused[N_MECH..FUSED_ROWS]);
            self.edge = Some(edge);
        }
        self.step_index += 1;
        Ok(())
    }

    pub(super) fn event_may_cross(
        &self,
        event: &EventFn,
        u0: &[f64],
        u1: &[f64],
        tau_s: f64,
        delta_s: f64,
    ) -> bool {
        let (offset, rate) = self.angle_terms(event.kind, event.angle_sign, tau_s);
        let g1 = event.value.dot(u1) + offset + rate * delta_s;
        if g1 > 0.0 {
            return true;
        }
        let g0 = event.value.dot(u0) + offset;
        let d0 = (event.slope.dot(u0) + rate) * delta_s;
        let d1 = (event.slope.dot(u1) + rate) * delta_s;
        may_cross(g0.min(0.0), d0, g1, d1)
    }

    /// Offset and rate of an angle event's φ term at `tau_s` into the step: sign·(φ − target), sign·Ω.
    pub(super) fn angle_terms(&self, kind: EventKind, sign: f64, tau_s: f64) -> (f64, f64) {
        if sign == 0.0 {
            return (0.0, 0.0);
        }
        let phase = self.phase_rad(tau_s);
        (
            sign * (phase - self.angle_target(kind)),
            sign * self.segment.set.speed_rad_s(),
        )
    }

    /// The nearest angles ahead and behind at which an angle event of `system` fires.
    pub(super) fn angle_targets(&self, system: &ModeSystem) -> AngleTargets {
        let mut targets = AngleTargets {
            ahead_rad: f64::INFINITY,
            behind_rad: f64::NEG_INFINITY,
        };
        for &k in &system.angle_events {
            let event = &system.events[k];
            let target = self.angle_target(event.kind);
            if event.angle_sign > 0.0 {
                targets.ahead_rad = targets.ahead_rad.min(target);
            } else {
                targets.behind_rad = targets.behind_rad.max(target);
            }
        }
        targets
    }

    /// The driving-gear angle an angle event waits for (rad).
    pub(super) fn angle_target(&self, kind: EventKind) -> f64 {
        match kind {
            EventKind::ToothPass => self.next_tooth_rad,
            EventKind::Revolution => self.next_rev_rad,
            EventKind::ZoneEnd => self.zone_bounds().1,
            EventKind::ZoneStart => self.zone_bounds().0,
            _ => 0.0,
        }
    }

    /// Redoes the current step on the Taylor expansion, switching at every crossing;
    /// `step_end` is the state at the step's end without a switch (e^{A h} u).
    #[inline(never)]
    pub(super) fn advance_exactly(
        &mut self,
        step_end: [f64; Layout::MAX_LEN],
    ) -> Result<(), RigError> {
        let mut step_end = Some(step_end);
        let mut tau = 0.0;
        for _ in 0..SWITCH_LIMIT {
            let delta = self.step_s - tau;
            self.cache.ensure(self.mode);
            let system = self.cache.built(self.mode);
            let order = system.taylor(&self.u, delta, &mut self.taylor);
            // Until the first switch, the end is the step's own; after it, the expansion's.
            let end = step_end.take().unwrap_or_else(|| {
                let mut end = [0.0; Layout::MAX_LEN];
                system.taylor_state(&self.taylor, order, 1.0, &mut end);
                end
            });
            match self.first_event(system, &end, order, tau, delta) {
                None => {
                    self.u = end;
                    return Ok(());
                }
                Some((s, kind)) => {
                    let mut at = [0.0; Layout::MAX_LEN];
                    system.taylor_state(&self.taylor, order, s, &mut at);
                    self.u = at;
                    tau += s * delta;
                    self.switch_count += 1;
                    let mode = self.mode;
                    self.handle(kind, tau);
                    if self.mode == mode
                        && let Some(jumped) = self.end_after_jump(&at, &end, tau)
                    {
                        self.u = jumped;
                        return Ok(());
                    }
                }
            }
        }
        Err(RigError::Chatter {
            t_s: self.time_at(tau),
            limit: SWITCH_LIMIT,
        })
    }

    /// The step's end after a switch at `tau_s` that kept the mode and moved at most the
    /// gear angles (a tooth pass, a revolution sample), by linearity: `end` (the step's
    /// end from `before`, the state just ahead of the switch) plus e^{A (h − τ)} Δ, Δ the
    /// jump to the state now. None when the switch moved anything else, or when some
    /// switching function may cross in the rest of the step: the expansion from the new
    /// state then decides.
    fn end_after_jump(
        &self,
        before: &[f64; Layout::MAX_LEN],
        end: &[f64; Layout::MAX_LEN],
        tau_s: f64,
    ) -> Option<[f64; Layout::MAX_LEN]> {
        let moved_elsewhere = (0..Layout::MAX_LEN)
            .filter(|i| !GEAR_ANGLES.contains(i))
            .any(|i| self.u[i] != before[i]);
        if moved_elsewhere {
            return None;
        }
        let system = self.cache.built(self.mode);
        let rest_s = self.step_s - tau_s;
        let mut jumped = *end;
        let jump = GEAR_ANGLES.map(|i| self.u[i] - before[i]);
        let order = system.taylor_order(rest_s);
        system
            .jump_response
            .add_to(jump, rest_s / self.step_s, order, &mut jumped);
        let may_cross = system
            .events
            .iter()
            .any(|event| self.event_may_cross(event, &self.u, &jumped, tau_s, rest_s));
        (!may_cross).then_some(jumped)
    }

    /// The earliest crossing (fraction s of the remaining `delta_s`, kind) of any switching
    /// function, given the Taylor vectors from the state now and the state `end` at `delta_s`.
    pub(super) fn first_event(
        &self,
        system: &ModeSystem,
        end: &[f64],
        order: usize,
        tau_s: f64,
        delta_s: f64,
    ) -> Option<(f64, EventKind)> {
        let mut best: Option<(f64, EventKind)> = None;
        let mut buffer = [0.0; TAYLOR_ORDER + 1];
        let coeffs = &mut buffer[..=order];
        for event in &system.events {
            if !self.event_may_cross(event, &self.u, end, tau_s, delta_s) {
                continue;
            }
            for (c, v) in coeffs.iter_mut().zip(self.taylor.iter()) {
                *c = event.value.dot(v);
            }
            let (offset, rate) = self.angle_terms(event.kind, event.angle_sign, tau_s);
            coeffs[0] += offset;
            coeffs[1] += rate * delta_s;
            if let Some(s) = first_crossing(coeffs)
                && best.is_none_or(|(b, _)| s < b)
            {
                best = Some((s, event.kind));
            }
        }
        best
    }
}

/// The driving-gear angles at which the nearest angle events fire. Checking the nearest
/// target ahead (and behind) suffices: a farther one cannot be reached without passing it.
#[derive(Clone, Copy, Debug)]
pub(super) struct AngleTargets {
    /// Smallest target of the events that fire as θ2 rises past it (rad; +∞ if none).
    ahead_rad: f64,
    /// Largest target of the events that fire as θ2 falls past it (rad; −∞ if none).
    behind_rad: f64,
}

/// One whole step as the fast path sees it, for the switch checks.
pub(super) struct StepEnds<'a> {
    /// Row events' values and slopes at the step's start.
    pub start: &'a [f64; 2 * MAX_ROW_EVENTS],
    /// The fused step: state and row events at the step's end.
    pub end: &'a FusedRows,
    /// The augmented state at the step's start.
    pub u0: &'a [f64; Layout::MAX_LEN],
    /// Set rotation φ at the step's start (rad).
    pub phase_rad: f64,
    /// Set speed Ω (rad/s).
    pub speed_rad_s: f64,
    /// Internal step (s).
    pub step_s: f64,
}

impl StepEnds<'_> {
    /// Whether any switching function may cross within the step: a row event from its
    /// values and slopes at both ends, an angle event from the driving gear's angle
    /// θ2 = φ + X2 and its rate at both ends.
    #[inline]
    pub(super) fn may_switch(&self, targets: &AngleTargets) -> bool {
        let (start, end, h) = (self.start, self.end, self.step_s);
        for j in 0..MAX_ROW_EVENTS {
            let (g1, d1) = (end[N_MECH + j], end[N_MECH + MAX_ROW_EVENTS + j] * h);
            if g1 > 0.0 {
                return true;
            }
            // ≤ 0 at both ends: an interior maximum needs rising at the start, falling at the end.
            let d0 = start[MAX_ROW_EVENTS + j] * h;
            if d0 > 0.0 && d1 < 0.0 && may_cross(start[j].min(0.0), d0, g1, d1) {
                return true;
            }
        }
        let omega = self.speed_rad_s;
        let theta0 = self.phase_rad + self.u0[X0 + 1];
        let theta1 = self.phase_rad + omega * h + end[X0 + 1];
        let (rate0, rate1) = (omega + self.u0[V0 + 1], omega + end[V0 + 1]);
        [(1.0, targets.ahead_rad), (-1.0, targets.behind_rad)]
            .into_iter()
            .filter(|(_, target)| target.is_finite())
            .any(|(sign, target)| {
                let g1 = sign * (theta1 - target);
                if g1 > 0.0 {
                    return true;
                }
                let d1 = sign * rate1 * h;
                d1 < 0.0
                    && may_cross(
                        (sign * (theta0 - target)).min(0.0),
                        sign * rate0 * h,
                        g1,
                        d1,
                    )
            })
    }
}
