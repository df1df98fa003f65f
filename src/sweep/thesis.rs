//! What the thesis saw at each point of the campaign (Basmaji 1983, ch. IV), and how a
//! case's result is held against it: the half-order verdict and the judged motion.

use rig::Motion;

use super::case_result::CaseResult;

/// Speed from which the thesis saw the half-order line (rev/min).
pub const HALF_ORDER_FROM_RPM: f64 = 1100.0;
/// Load at which it vanished at high speed (N m) ...
pub const HEAVY_LOAD_NM: f64 = 5.424;
/// ... from this speed up (rev/min).
pub const VANISHES_FROM_RPM: f64 = 1900.0;
/// The measured fundamental natural frequency (Hz).
pub const MEASURED_FUNDAMENTAL_HZ: f64 = 13.33;

/// The running speed (rev/min) at which the thesis places the fundamental (rev/s = f1).
pub const MEASURED_RESONANCE_RPM: f64 = 780.0;

/// Speeds up to 1000 rev/min a grid needs, spanning the resonance's tolerance band on both
/// sides, before its first-order peak is taken as the resonance.
pub const RESONANCE_MIN_SPEEDS: usize = 5;

/// How far (relative) a loaded once-per-revolution peak may lie from
/// [`MEASURED_RESONANCE_RPM`] to count as the measured fundamental (as in
/// `rig/tests/calibration.rs`).
pub const RESONANCE_TOLERANCE: f64 = 0.12;

/// Whether the thesis saw a half-order line at `rpm` and `load_nm`: from 1100 rev/min up,
/// with or without load, except with 5.424 N m from 1900 rev/min up.
pub fn thesis_expects_half_order(rpm: f64, load_nm: f64) -> bool {
    rpm >= HALF_ORDER_FROM_RPM && !(load_nm >= HEAVY_LOAD_NM - 1e-6 && rpm >= VANISHES_FROM_RPM)
}

/// The motion the thesis saw at `rpm` and `load_nm`, as issue 26 decides the campaign's
/// points: period 1 below 1000 rev/min (only running-speed harmonics, Figs 4.34–4.35),
/// period 2 from 1100 rev/min up (the half-order line, a time trace repeating every two
/// revolutions, Fig 4.39) except with 5.424 N m from 1900 rev/min (line gone: period 1);
/// `None` at 1000 rev/min and between 1000 and 1100, where the thesis says "about".
pub fn thesis_motion(rpm: f64, load_nm: f64) -> Option<Motion> {
    if rpm < PERIOD_ONE_BELOW_RPM {
        Some(Motion::Periodic(1))
    } else if rpm < HALF_ORDER_FROM_RPM {
        None
    } else if thesis_expects_half_order(rpm, load_nm) {
        Some(Motion::Periodic(2))
    } else {
        Some(Motion::Periodic(1))
    }
}

/// Below this speed the thesis saw only the running speed and its multiples (rev/min).
pub const PERIOD_ONE_BELOW_RPM: f64 = 1000.0;

/// Whether the judge's motion at a case is the thesis's there: the same period, and for
/// period 2 a half-order line standing clear of the broadband floor.
pub fn physics_match(c: &CaseResult) -> bool {
    match thesis_motion(c.rpm, c.load_nm) {
        None => false,
        Some(Motion::Periodic(2)) => {
            c.motion.motion == Motion::Periodic(2) && c.motion.half_order_clear()
        }
        Some(expected) => c.motion.motion == expected,
    }
}

/// Decided points whose judged motion matches the thesis, of the decided points.
pub fn physics_score(cases: &[CaseResult]) -> (usize, usize) {
    let decided: Vec<&CaseResult> = cases
        .iter()
        .filter(|c| thesis_motion(c.rpm, c.load_nm).is_some())
        .collect();
    let hits = decided.iter().filter(|c| physics_match(c)).count();
    (hits, decided.len())
}

/// Points whose half-order verdict matches the thesis, of all points.
pub fn score(cases: &[CaseResult]) -> (usize, usize) {
    let hits = cases
        .iter()
        .filter(|c| c.half_order_present == thesis_expects_half_order(c.rpm, c.load_nm))
        .count();
    (hits, cases.len())
}

/// The lab's score: decided points at which the thesis's motion is among those the
/// point held, whichever way it was reached (run up, run down, from the static load), of
/// the decided points (each point, load and parameter variant once).
pub fn lab_score(cases: &[CaseResult]) -> (usize, usize) {
    let mut points: Vec<(&CaseResult, bool)> = Vec::new();
    for c in cases
        .iter()
        .filter(|c| thesis_motion(c.rpm, c.load_nm).is_some())
    {
        let same =
            |p: &CaseResult| p.rpm == c.rpm && p.load_nm == c.load_nm && p.values == c.values;
        match points.iter_mut().find(|(p, _)| same(p)) {
            Some((_, hit)) => *hit |= physics_match(c),
            None => points.push((c, physics_match(c))),
        }
    }
    let hits = points.iter().filter(|(_, hit)| *hit).count();
    (hits, points.len())
}
