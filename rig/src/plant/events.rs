//! The switching functions of a mode: linear functions g(u) − target whose crossing from
//! ≤ 0 to > 0 ends the mode. Targets that move as the rig turns (pair-zone ends, the next
//! revolution) are the plant's; the rest are constants folded in through the unit state.

use nalgebra::DMatrix;

use crate::mode::MotorMode;

use super::mode::{Contact, NetMode};
use super::model::NetworkModel;

/// What a crossing means.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NetEvent {
    /// Mesh `.0`, apart, touches a flank (an impact).
    Touch(usize, Contact),
    /// Mesh `.0`'s teeth part.
    Leave(usize),
    /// Mesh `.0`'s force reaches zero while its flanks overlap (no-pull law): clipped.
    Unload(usize),
    /// Mesh `.0`'s clipped force would push again (no-pull law).
    Reload(usize),
    /// Mesh `.0`'s driver turns past the end of its pair zone (followed in contact where
    /// pairs alternate or a tooth is faulted, and while a broken pair leaves no tooth).
    ZoneEnd(usize),
    /// Mesh `.0`'s driver turns back past the start of its pair zone.
    ZoneStart(usize),
    /// The motor's command reaches +limit.
    LimitHigh,
    /// The motor's command reaches −limit.
    LimitLow,
    /// The held command would move back inside the limits.
    LimitRelease,
    /// The motor body turns past its next whole revolution.
    Revolution,
    /// Mesh `.0`'s driver turns past its next tooth boundary (tooth shifting).
    ToothPass(usize),
}

impl NetEvent {
    /// The mesh it belongs to, if any.
    pub fn mesh(&self) -> Option<usize> {
        match *self {
            Self::Touch(i, _)
            | Self::Leave(i)
            | Self::Unload(i)
            | Self::Reload(i)
            | Self::ZoneEnd(i)
            | Self::ZoneStart(i)
            | Self::ToothPass(i) => Some(i),
            Self::LimitHigh | Self::LimitLow | Self::LimitRelease | Self::Revolution => None,
        }
    }
}

/// A moving target the plant supplies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// None: the form's own constant.
    Fixed,
    /// The end of mesh `.0`'s pair zone (rad of its driver).
    ZoneEnd(usize),
    /// Minus the start of mesh `.0`'s pair zone.
    ZoneStartNegated(usize),
    /// The motor body's next revolution (rad).
    Revolution,
    /// Mesh `.0`'s driver's next tooth boundary (rad in its sense of rotation).
    Tooth(usize),
}

/// One switching function: g = terms·u − target, and its rate slope·u along u' = A u.
#[derive(Clone, Debug, PartialEq)]
pub struct EventForm {
    /// What its crossing means.
    pub event: NetEvent,
    /// Sparse coefficients (index, value).
    pub terms: Vec<(usize, f64)>,
    /// The row terms·A, its nonzero entries (index, value).
    pub slope: Vec<(usize, f64)>,
    /// The moving target.
    pub target: Target,
}

impl EventForm {
    fn new(event: NetEvent, terms: Vec<(usize, f64)>, target: Target, a: &DMatrix<f64>) -> Self {
        let slope = (0..a.ncols())
            .map(|col| {
                (
                    col,
                    terms.iter().map(|&(i, c)| c * a[(i, col)]).sum::<f64>(),
                )
            })
            .filter(|&(_, v)| v != 0.0)
            .collect();
        Self {
            event,
            terms,
            slope,
            target,
        }
    }

    /// terms·u (the target not taken off).
    #[inline]
    pub fn value(&self, u: &[f64]) -> f64 {
        sparse_sum(&self.terms, u)
    }

    /// slope·u, the rate of the value.
    #[inline]
    pub fn rate(&self, u: &[f64]) -> f64 {
        sparse_sum(&self.slope, u)
    }
}

/// Σ c·u[i] over the sparse `terms` (index i, coefficient c), summed in their order: the
/// one sum every switching function's value and rate, and every angle they share
/// (`span_ends.rs`), are taken by, so that a shared angle gives a function's own sums.
#[inline(always)]
pub fn sparse_sum(terms: &[(usize, f64)], u: &[f64]) -> f64 {
    terms.iter().map(|&(i, c)| c * u[i]).sum()
}

/// The switching functions of `mode` with A = `a`, the meshes' harmonic pairs turning
/// with the set speed `speed_rad_s`.
pub fn event_forms(
    model: &NetworkModel,
    mode: &NetMode,
    a: &DMatrix<f64>,
    speed_rad_s: f64,
) -> Vec<EventForm> {
    let mut forms = Vec::new();
    let mut push = |event, terms: Vec<(usize, f64)>, target| {
        forms.push(EventForm::new(event, terms, target, a));
    };
    let l = &model.layout;
    for (i, m) in model.meshes.iter().enumerate() {
        // The overlap of a flank: its value terms (the rate is A's business).
        let overlap = |flank: f64, sign: f64| -> Vec<(usize, f64)> {
            model
                .overlap_terms(i, flank, 0.0)
                .into_iter()
                .filter(|&(_, value, _)| value != 0.0)
                .map(|(index, value, _)| (index, sign * value))
                .collect()
        };
        let state = mode.meshes[i];
        match state.contact {
            // No tooth to touch until the next pair comes into mesh.
            Contact::Apart if state.toothless => {}
            Contact::Apart => {
                push(
                    NetEvent::Touch(i, Contact::Drive),
                    overlap(1.0, 1.0),
                    Target::Fixed,
                );
                push(
                    NetEvent::Touch(i, Contact::Back),
                    overlap(-1.0, -1.0),
                    Target::Fixed,
                );
            }
            Contact::Drive => push(NetEvent::Leave(i), overlap(1.0, -1.0), Target::Fixed),
            Contact::Back => push(NetEvent::Leave(i), overlap(-1.0, 1.0), Target::Fixed),
        }
        if m.no_pull && state.contact != Contact::Apart {
            // The push f·F of the flank in contact (its spring as if it pushed): clipped,
            // it pushes again when this rises through 0; else it is clipped when it falls.
            let flank = f64::from(state.contact.sign());
            let pushing = state.unclipped();
            let sign = if state.clipped { flank } else { -flank };
            let force = model
                .force_terms(i, pushing, flank, speed_rad_s)
                .into_iter()
                .map(|(index, v)| (index, sign * v))
                .collect();
            let event = if state.clipped {
                NetEvent::Reload(i)
            } else {
                NetEvent::Unload(i)
            };
            push(event, force, Target::Fixed);
        }
        if m.tooth_shifting && mode.meshes[i].contact != Contact::Apart {
            let sense = m.zone_share.signum();
            let angle = model.zone_angle_terms(i);
            push(
                NetEvent::ToothPass(i),
                angle.into_iter().map(|(j, c)| (j, sense * c)).collect(),
                Target::Tooth(i),
            );
        }
        // Spaced pairs are followed apart too: the gap depends on the pair in mesh.
        let follows_zones = m.alternating || m.faulted || m.spaced();
        if follows_zones && (state.contact != Contact::Apart || state.toothless || m.spaced()) {
            // The angle the tooth periods follow against the zone's bounds.
            let angle = model.zone_angle_terms(i);
            let negated = angle.iter().map(|&(j, c)| (j, -c)).collect();
            push(NetEvent::ZoneEnd(i), angle, Target::ZoneEnd(i));
            push(NetEvent::ZoneStart(i), negated, Target::ZoneStartNegated(i));
        }
    }
    if let Some(m) = &model.motor {
        let (kp, ki, wf) = (m.kp_nms_per_rad, m.ki_nm_per_rad, m.filter_rad_s);
        let command = |sign: f64, limit: f64| {
            vec![
                (l.set_speed(), sign * kp),
                (l.filtered(), -sign * kp),
                (l.integral(), sign * ki),
                (l.unit(), -limit),
            ]
        };
        // Held at a limit, the command leaves it when the unclamped loop would turn it
        // back: its rate kp(Ω' − ω_f') + ki(Ω − ω_f) falls below 0 at +limit.
        let falls_back = |sign: f64| {
            vec![
                (l.speed(m.body), sign * kp * wf),
                (l.filtered(), sign * (ki - kp * wf)),
                (l.set_speed(), -sign * ki),
                (l.set_rate(), -sign * kp),
            ]
        };
        match (mode.motor, m.limit_nm) {
            (_, None) => {}
            (MotorMode::Linear, Some(limit)) => {
                push(NetEvent::LimitHigh, command(1.0, limit), Target::Fixed);
                push(NetEvent::LimitLow, command(-1.0, limit), Target::Fixed);
            }
            (MotorMode::LimitHigh, Some(_)) => {
                push(NetEvent::LimitRelease, falls_back(1.0), Target::Fixed);
            }
            (MotorMode::LimitLow, Some(_)) => {
                push(NetEvent::LimitRelease, falls_back(-1.0), Target::Fixed);
            }
        }
        push(
            NetEvent::Revolution,
            vec![
                (l.angle(m.body), 1.0),
                (l.phase(), model.speed_ratio[m.body]),
            ],
            Target::Revolution,
        );
    }
    forms
}
