//! The motions each operating point held: a sweep's cases grouped by point (speed, load,
//! parameter variant), each motion the judge named there with the approaches that reached
//! it. Where a point holds more than one, its motions coexist.

use super::case_result::CaseResult;
use super::sequence::Direction;

/// One operating point and the motions its cases settled to.
#[derive(Clone, Debug)]
pub struct HeldMotions<'a> {
    /// The point's first case (its speed, load and parameter values).
    pub point: &'a CaseResult,
    /// Each motion (as the judge names it) with the approaches that reached it, in the
    /// order of the cases.
    pub motions: Vec<(String, Vec<Direction>)>,
}

impl HeldMotions<'_> {
    /// Whether the approaches settled to more than one motion.
    pub fn coexist(&self) -> bool {
        self.motions.len() > 1
    }

    /// "period-2 (up, down), period-1 (rest, repeat ×2)".
    pub fn describe(&self) -> String {
        let held: Vec<String> = self
            .motions
            .iter()
            .map(|(motion, by)| format!("{motion} ({})", count_directions(by)))
            .collect();
        held.join(", ")
    }
}

/// Every point of `cases` with the motions held there, in the order points first appear.
pub fn held_motions(cases: &[CaseResult]) -> Vec<HeldMotions<'_>> {
    let mut points: Vec<HeldMotions> = Vec::new();
    for c in cases {
        let same =
            |p: &CaseResult| p.rpm == c.rpm && p.load_nm == c.load_nm && p.values == c.values;
        let at = match points.iter().position(|h| same(h.point)) {
            Some(at) => at,
            None => {
                points.push(HeldMotions {
                    point: c,
                    motions: Vec::new(),
                });
                points.len() - 1
            }
        };
        let motion = c.motion.motion.to_string();
        let motions = &mut points[at].motions;
        match motions.iter_mut().find(|(m, _)| *m == motion) {
            Some((_, by)) => by.push(c.direction),
            None => motions.push((motion, vec![c.direction])),
        }
    }
    points
}

/// "rest, repeat ×2": each approach once, with its count where above one.
fn count_directions(by: &[Direction]) -> String {
    let mut counted: Vec<(Direction, usize)> = Vec::new();
    for d in by {
        match counted.iter_mut().find(|(e, _)| e == d) {
            Some((_, n)) => *n += 1,
            None => counted.push((*d, 1)),
        }
    }
    counted
        .iter()
        .map(|(d, n)| match n {
            1 => d.to_string(),
            n => format!("{d} ×{n}"),
        })
        .collect::<Vec<_>>()
        .join(", ")
}
