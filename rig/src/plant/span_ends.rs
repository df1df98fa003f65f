//! Where each switching function's value and rate at a span's end come from: a row event
//! (a function of fixed target) from the fused product's rows; a function of the set
//! rotation (its target moves) from the few angles such functions read. A mesh's zone
//! end and zone start read its driver's angle with opposite signs and its tooth pass the
//! same angle; a planetary stage's sun meshes all read the sun's turn against the
//! carrier, each with its own offset (the planet's place, `zone_offset_rad`) as a last
//! term on the unit state. Each distinct angle is evaluated once a span: on the planetary
//! bench, every mesh in contact, 5 evaluations (the sun's turn, each planet's, the
//! revolution) for its 13 such functions.
//!
//! Each function's end is read the same way, without a branch ([`EndRead`]): a signed
//! row plus its last term. A function that reads angle a, negated or not, with or
//! without a last term c·1, has the value ±(Σ terms of a) + c·1 and the rate
//! ±(Σ slope of a): the sums its own sparse terms give, bit for bit (a negated product
//! and a negated sum round alike; Rust's sum of f64 starts from −0), but for the sign of
//! a value or rate that is exactly zero. Functions are grouped only where their terms and
//! slopes are those of the angle to the bit.

use super::events::{EventForm, sparse_sum};

/// How one switching function's value and rate at a span's end are read from the span's
/// end rows (the fused product's rows, then each distinct angle's value and rate, each
/// value with its rate in the next row): value = `sign` · rows[`row`] + `last` · u_unit,
/// rate = `sign` · rows[`row` + 1]. A row event reads its own rows with sign 1 and last
/// −0: with the unit state positive and finite (it holds 1), −0 · u_unit = −0 adds
/// nothing to any value, −0, +0 and NaN included, so it reads its fused rows exactly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EndRead {
    /// The row of its value (a row event's, or its angle's); its rate's is the next.
    pub row: usize,
    /// 1, or −1 for a function that reads its angle negated.
    pub sign: f64,
    /// The coefficient of its last term on the unit state (−0 if none).
    pub last: f64,
}

impl EndRead {
    /// Its value and rate from the end rows `rows` and the unit state's value `unit`.
    #[inline(always)]
    pub fn read(&self, rows: &[f64], unit: f64) -> (f64, f64) {
        let pair = &rows[self.row..self.row + 2];
        (self.sign * pair[0] + self.last * unit, self.sign * pair[1])
    }
}

/// Where a mode's switching functions' ends come from.
#[derive(Clone, Debug, PartialEq)]
pub struct SpanEnds<'a> {
    /// Per function, how its end is read.
    pub reads: Vec<EndRead>,
    /// The row events' forms, in slot order.
    pub rows: Vec<&'a EventForm>,
    /// The distinct angles the functions of the set rotation read.
    pub angles: Vec<SharedAngle>,
    /// Rows of the fused product (mechanical, then each row event's value and rate side
    /// by side, rounded up to a multiple of 4); the angles' values and rates follow alike.
    pub fused_rows: usize,
}

/// A linear form several switching functions of the set rotation read: terms on the
/// state and its rate along u' = A u (its slope).
#[derive(Clone, Debug, PartialEq)]
pub struct SharedAngle {
    /// Sparse coefficients (index, value), the first positive.
    pub terms: Vec<(usize, f64)>,
    /// Its rate's coefficients (index, value).
    pub slope: Vec<(usize, f64)>,
}

impl SharedAngle {
    /// Its value and rate at the state `u`, each summed as [`EventForm::value`] and
    /// [`EventForm::rate`] sum them ([`sparse_sum`]).
    #[inline(always)]
    pub fn value_rate(&self, u: &[f64]) -> (f64, f64) {
        (sparse_sum(&self.terms, u), sparse_sum(&self.slope, u))
    }
}

/// Where each function of `events` reads its end, for `mechanical` mechanical states: a
/// row event if its terms do not read the set rotation `phase`, else a distinct angle
/// with its sign and its last term on the `unit` state.
pub fn span_ends(
    events: &[EventForm],
    mechanical: usize,
    phase: usize,
    unit: usize,
) -> SpanEnds<'_> {
    let rows: Vec<&EventForm> = events
        .iter()
        .filter(|form| !reads_phase(form, phase))
        .collect();
    let fused_rows = (mechanical + 2 * rows.len()).div_ceil(4) * 4;
    let mut angles: Vec<SharedAngle> = Vec::new();
    let mut slot = 0;
    let reads = events
        .iter()
        .map(|form| {
            if !reads_phase(form, phase) {
                slot += 1;
                return EndRead {
                    row: mechanical + 2 * (slot - 1),
                    sign: 1.0,
                    last: -0.0,
                };
            }
            let (angle, negated, last) = canonical(form, unit);
            let k = angles
                .iter()
                .position(|a| same_bits(a, &angle))
                .unwrap_or_else(|| {
                    angles.push(angle);
                    angles.len() - 1
                });
            EndRead {
                row: fused_rows + 2 * k,
                sign: if negated { -1.0 } else { 1.0 },
                last: last.unwrap_or(-0.0),
            }
        })
        .collect();
    SpanEnds {
        reads,
        rows,
        angles,
        fused_rows,
    }
}

/// Whether functions of two or more meshes among `events` read one shared angle (their
/// ends read by `reads`, the angles' rows from `fused_rows` on): the sun meshes of a
/// stage, each with its planet's offset. A switch of one may then bring the others due
/// at the same instant (every planet of an in-phase stage).
pub fn meshes_share_an_angle(events: &[EventForm], reads: &[EndRead], fused_rows: usize) -> bool {
    let of_angles: Vec<(usize, Option<usize>)> = reads
        .iter()
        .zip(events)
        .filter(|(read, _)| read.row >= fused_rows)
        .map(|(read, form)| (read.row, form.event.mesh()))
        .collect();
    of_angles.iter().enumerate().any(|(k, &(row, mesh))| {
        of_angles[k + 1..]
            .iter()
            .any(|&(other_row, other)| other_row == row && other != mesh)
    })
}

/// Whether `form` reads the set rotation (its target moves with it).
fn reads_phase(form: &EventForm, phase: usize) -> bool {
    form.terms.iter().any(|&(i, _)| i == phase)
}

/// `form`'s terms without a last one on `unit` and its slope, signed so that the first
/// term is positive; whether that negated them; the last term on `unit`, if any.
fn canonical(form: &EventForm, unit: usize) -> (SharedAngle, bool, Option<f64>) {
    let (terms, last) = match form.terms.split_last() {
        Some((&(i, c), rest)) if i == unit && !rest.is_empty() => (rest, Some(c)),
        _ => (form.terms.as_slice(), None),
    };
    let negated = terms.first().is_some_and(|&(_, c)| c < 0.0);
    let sign = |list: &[(usize, f64)]| -> Vec<(usize, f64)> {
        list.iter()
            .map(|&(i, c)| (i, if negated { -c } else { c }))
            .collect()
    };
    let angle = SharedAngle {
        terms: sign(terms),
        slope: sign(&form.slope),
    };
    (angle, negated, last)
}

/// Whether two angles have the same terms and slopes, coefficient for coefficient to the
/// bit.
fn same_bits(a: &SharedAngle, b: &SharedAngle) -> bool {
    let same = |x: &[(usize, f64)], y: &[(usize, f64)]| {
        x.len() == y.len()
            && x.iter()
                .zip(y)
                .all(|(p, q)| p.0 == q.0 && p.1.to_bits() == q.1.to_bits())
    };
    same(&a.terms, &b.terms) && same(&a.slope, &b.slope)
}

#[cfg(test)]
mod tests {
    use super::{SpanEnds, meshes_share_an_angle, span_ends};
    use crate::plant::events::{EventForm, NetEvent, Target};

    fn form(event: NetEvent, terms: Vec<(usize, f64)>, slope: Vec<(usize, f64)>) -> EventForm {
        EventForm {
            event,
            terms,
            slope,
            target: Target::Fixed,
        }
    }

    /// A state of every size and sign, the unit state 1.
    fn state(unit: usize) -> Vec<f64> {
        let mut u: Vec<f64> = (0..12)
            .map(|k| (k as f64 * 1.37 - 5.1) * 10f64.powi(k % 5 - 2))
            .collect();
        u[unit] = 1.0;
        u
    }

    /// The end rows at `u` as the plant fills them: each row event's value and rate at
    /// its rows (the fused product's, here its own sums), then each angle's.
    fn end_rows(ends: &SpanEnds, mechanical: usize, u: &[f64]) -> Vec<f64> {
        let mut rows = vec![f64::NAN; ends.fused_rows + 2 * ends.angles.len()];
        for (j, form) in ends.rows.iter().enumerate() {
            rows[mechanical + 2 * j] = form.value(u);
            rows[mechanical + 2 * j + 1] = form.rate(u);
        }
        for (k, angle) in ends.angles.iter().enumerate() {
            (
                rows[ends.fused_rows + 2 * k],
                rows[ends.fused_rows + 2 * k + 1],
            ) = angle.value_rate(u);
        }
        rows
    }

    #[test]
    fn zone_ends_starts_and_phased_meshes_share_one_angle_and_read_their_own_sums() {
        let (mechanical, phase, unit) = (6, 10, 11);
        let angle = vec![(0, 1.0), (3, -1.0), (phase, 0.8)];
        let slope = vec![(4, 1.0), (7, -1.0)];
        let negate = |v: &[(usize, f64)]| v.iter().map(|&(i, c)| (i, -c)).collect::<Vec<_>>();
        let with_offset = |v: &[(usize, f64)], c: f64| {
            let mut v = v.to_vec();
            v.push((unit, c));
            v
        };
        let events = vec![
            form(
                NetEvent::Leave(0),
                vec![(1, 2.0), (2, -2.0)],
                vec![(5, 2.0)],
            ),
            form(
                NetEvent::ZoneEnd(0),
                with_offset(&angle, -0.3),
                slope.clone(),
            ),
            form(
                NetEvent::ZoneStart(0),
                negate(&with_offset(&angle, -0.3)),
                negate(&slope),
            ),
            form(
                NetEvent::ZoneEnd(1),
                with_offset(&angle, 0.7),
                slope.clone(),
            ),
            form(NetEvent::ToothPass(0), angle.clone(), slope.clone()),
            form(NetEvent::ToothPass(1), negate(&angle), negate(&slope)),
            form(
                NetEvent::Revolution,
                vec![(0, 1.0), (phase, 1.0)],
                vec![(4, 1.0)],
            ),
            form(NetEvent::Leave(1), vec![(2, 3.0)], vec![(6, -3.0)]),
        ];
        let ends = span_ends(&events, mechanical, phase, unit);
        assert_eq!(ends.rows.len(), 2);
        assert_eq!(
            ends.fused_rows, 12,
            "6 mechanical rows and 2 × 2 padded to 12"
        );
        assert_eq!(ends.angles.len(), 2, "the mesh angle and the revolution");
        assert!(
            meshes_share_an_angle(&events, &ends.reads, ends.fused_rows),
            "meshes 0 and 1 read one angle"
        );
        // Mesh 0's zone end, zone start and tooth pass read one angle, and the
        // revolution its own: no two meshes share one.
        let alone: Vec<EventForm> = [0, 1, 2, 4, 6].map(|k| events[k].clone()).to_vec();
        let alone_ends = span_ends(&alone, mechanical, phase, unit);
        assert_eq!(alone_ends.angles.len(), 2);
        assert!(!meshes_share_an_angle(
            &alone,
            &alone_ends.reads,
            alone_ends.fused_rows
        ));
        let u = state(unit);
        let rows = end_rows(&ends, mechanical, &u);
        for (form, read) in events.iter().zip(&ends.reads) {
            let (value, rate) = read.read(&rows, u[unit]);
            assert_eq!(
                value.to_bits(),
                form.value(&u).to_bits(),
                "{:?}",
                form.event
            );
            assert_eq!(rate.to_bits(), form.rate(&u).to_bits(), "{:?}", form.event);
        }
    }

    #[test]
    fn a_row_event_reads_its_rows_exactly_zeros_and_nan_included() {
        let (mechanical, phase, unit) = (2, 10, 11);
        let events = vec![form(NetEvent::Leave(0), vec![(1, 2.0)], vec![(5, 2.0)])];
        let ends = span_ends(&events, mechanical, phase, unit);
        let [read] = ends.reads[..] else {
            panic!("one function, one read");
        };
        for value in [
            0.0,
            -0.0,
            f64::NAN,
            -f64::NAN,
            f64::INFINITY,
            -3.5e-310,
            7.25,
        ] {
            let mut rows = vec![f64::NAN; ends.fused_rows];
            rows[read.row] = value;
            rows[read.row + 1] = -value;
            let (v, r) = read.read(&rows, 1.0);
            assert_eq!(v.to_bits(), value.to_bits(), "value {value:e}");
            assert_eq!(r.to_bits(), (-value).to_bits(), "rate {:e}", -value);
        }
    }

    #[test]
    fn functions_whose_slopes_differ_keep_angles_of_their_own() {
        let (phase, unit) = (10, 11);
        let events = vec![
            form(
                NetEvent::ZoneEnd(0),
                vec![(0, 1.0), (phase, 0.5)],
                vec![(4, 1.0)],
            ),
            form(
                NetEvent::ZoneEnd(1),
                vec![(0, 1.0), (phase, 0.5)],
                vec![(4, 1.0 + f64::EPSILON)],
            ),
        ];
        assert_eq!(span_ends(&events, 4, phase, unit).angles.len(), 2);
    }
}
