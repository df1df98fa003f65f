//! Switching functions: linear functions of the augmented state whose sign change ends
//! a linear segment, and the location of their first crossing.

use nalgebra::DMatrix;

use crate::layout::{Layout, REV, UNIT, V0, VF, X0, Z};
use crate::mode::{MeshMode, Mode, MotorMode};
use crate::model::ModelConstants;
use crate::options::ContactLaw;

/// What a crossing means.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EventKind {
    /// Apart → drive-flank contact (an impact).
    TouchDrive,
    /// Apart → back-flank contact (an impact).
    TouchBack,
    /// Drive-flank overlap ends: teeth apart.
    LeaveDrive,
    /// Back-flank overlap ends.
    LeaveBack,
    /// No-pull law: drive-flank torque reaches zero while the teeth still overlap.
    DriveUnloads,
    /// No-pull law: clipped drive-flank torque becomes positive again.
    DriveReloads,
    /// No-pull law: back-flank torque reaches zero.
    BackUnloads,
    /// No-pull law: clipped back-flank torque becomes positive again.
    BackReloads,
    /// The driving gear turns past the end of the current pair zone.
    ZoneEnd,
    /// The driving gear turns back past the start of the current pair zone.
    ZoneStart,
    /// Controller output reaches +limit.
    LimitHigh,
    /// Controller output reaches −limit.
    LimitLow,
    /// Controller output comes back inside the limits.
    LimitRelease,
    /// The driving gear turns past the next tooth boundary.
    ToothPass,
    /// The driving gear turns past the next whole revolution.
    Revolution,
}

/// Terms a form evaluates unrolled; most switching functions have at most this many.
const SMALL_TERMS: usize = 4;

/// A sparse linear form over the augmented state.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SparseRow {
    /// (index, coefficient) pairs.
    pub terms: Vec<(usize, f64)>,
    /// The same terms padded with zeros, when there are at most four (evaluated unrolled).
    small: Option<[(usize, f64); SMALL_TERMS]>,
}

impl SparseRow {
    fn new(terms: &[(usize, f64)]) -> Self {
        let terms: Vec<(usize, f64)> = terms.iter().copied().filter(|&(_, c)| c != 0.0).collect();
        let small = (terms.len() <= SMALL_TERMS)
            .then(|| std::array::from_fn(|k| terms.get(k).copied().unwrap_or((0, 0.0))));
        Self { terms, small }
    }

    /// Value of the form at `u`.
    #[inline(always)]
    pub fn dot(&self, u: &[f64]) -> f64 {
        match &self.small {
            Some(t) => {
                t[0].1 * u[t[0].0] + t[1].1 * u[t[1].0] + t[2].1 * u[t[2].0] + t[3].1 * u[t[3].0]
            }
            None => self.terms.iter().map(|&(i, c)| c * u[i]).sum(),
        }
    }

    /// The form c·A, i.e. the time derivative of c·u along u' = A u.
    fn times(&self, a: &DMatrix<f64>) -> Self {
        let terms: Vec<(usize, f64)> = (0..a.ncols())
            .map(|col| (col, self.terms.iter().map(|&(i, c)| c * a[(i, col)]).sum()))
            .collect();
        Self::new(&terms)
    }

    fn negated(&self) -> Self {
        let terms: Vec<(usize, f64)> = self.terms.iter().map(|&(i, c)| (i, -c)).collect();
        Self::new(&terms)
    }
}

/// One switching function g(u, τ) = value·u + sign·(φ(τ) − target) for angle events.
///
/// The segment ends when g crosses from ≤ 0 to > 0.
#[derive(Clone, Debug, PartialEq)]
pub struct EventFn {
    /// What the crossing means.
    pub kind: EventKind,
    /// g's linear form over u.
    pub value: SparseRow,
    /// dg/dt's linear form over u (c·A).
    pub slope: SparseRow,
    /// For angle events: +1 when g grows with the driving gear's angle θ2 = φ + X2, −1 when it falls.
    pub angle_sign: f64,
}

/// The switching functions active in `mode`.
pub fn mode_events(
    mc: &ModelConstants,
    layout: &Layout,
    law: ContactLaw,
    flags: EventFlags,
    mode: Mode,
    a: &DMatrix<f64>,
    rotation_rad_s: f64,
) -> Vec<EventFn> {
    let mut list: Vec<(EventKind, SparseRow, f64)> = Vec::new();
    let flanks = FlankForms::of(mc, layout, mode, rotation_rad_s);
    mesh_events(&mut list, &flanks, mode.mesh, law);
    motor_events(&mut list, mc, mode.motor);
    angle_events(&mut list, flags, mode.mesh);
    list.into_iter()
        .map(|(kind, value, angle_sign)| EventFn {
            kind,
            slope: value.times(a),
            value,
            angle_sign,
        })
        .collect()
}

/// Each flank's overlap (gap) and pushing torque K δ + C δ' as linear forms over u.
struct FlankForms {
    gap_drive: Vec<(usize, f64)>,
    gap_back: Vec<(usize, f64)>,
    force_drive: Vec<(usize, f64)>,
    force_back: Vec<(usize, f64)>,
}

impl FlankForms {
    /// The forms in `mode` (its mesh stiffness level) at the set rotation `rotation_rad_s`.
    fn of(mc: &ModelConstants, layout: &Layout, mode: Mode, rotation_rad_s: f64) -> Self {
        let (k, c) = mc.mesh_spring(mode.pairs);
        let b0 = mc.half_backlash_rad;
        let bc = b0 * mc.backlash_variation;
        let (x2, x3, v2, v3) = (X0 + 1, X0 + 2, V0 + 1, V0 + 2);
        // The transmission error E cos φ moves both flanks' contact the same way: it adds
        // to the drive flank's overlap and takes from the back flank's.
        let e = mc.te_once_rad;
        let (rev_drive, rev_back) = (bc + e, bc - e);
        let mut forms = Self {
            gap_drive: vec![(x2, 1.0), (x3, -1.0), (UNIT, -b0), (REV, rev_drive)],
            gap_back: vec![(x2, -1.0), (x3, 1.0), (UNIT, -b0), (REV, rev_back)],
            // δ' includes the rates of B₀C1 cos φ and E cos φ.
            force_drive: vec![
                (x2, k),
                (x3, -k),
                (UNIT, -k * b0),
                (REV, k * rev_drive),
                (v3, -c),
                (v2, c),
                (REV + 1, -c * rev_drive * rotation_rad_s),
            ],
            force_back: vec![
                (x2, -k),
                (x3, k),
                (UNIT, -k * b0),
                (REV, k * rev_back),
                (v3, c),
                (v2, -c),
                (REV + 1, -c * rev_back * rotation_rad_s),
            ],
        };
        // The profile error P cos zφ, like E cos φ: to the drive flank's overlap, from the
        // back's.
        if let Some(mesh) = layout.mesh {
            let p = mc.te_mesh_rad;
            let p_rate = p * mc.teeth * rotation_rad_s;
            for (flank, gap, force) in [
                (1.0, &mut forms.gap_drive, &mut forms.force_drive),
                (-1.0, &mut forms.gap_back, &mut forms.force_back),
            ] {
                gap.push((mesh, flank * p));
                force.extend([(mesh, flank * k * p), (mesh + 1, -flank * c * p_rate)]);
            }
        }
        // The spacing error s of the pair in mesh, a displacement like the others
        // (constant between tooth passes: no rate).
        if let Some(spacing) = layout.spacing {
            forms.gap_drive.push((spacing, 1.0));
            forms.gap_back.push((spacing, -1.0));
            forms.force_drive.push((spacing, k));
            forms.force_back.push((spacing, -k));
        }
        forms
    }
}

/// A list of switching functions being assembled: kind, linear form, angle sign.
type EventList = Vec<(EventKind, SparseRow, f64)>;

/// The mesh's switching functions in mesh mode `mesh`: apart, the flanks touching; in
/// contact, the overlap ending (and with the no-pull law the torque's zero).
fn mesh_events(list: &mut EventList, flanks: &FlankForms, mesh: MeshMode, law: ContactLaw) {
    let mut push = |kind, terms: &[(usize, f64)]| list.push((kind, SparseRow::new(terms), 0.0));
    let no_pull = law == ContactLaw::NoPull;
    match mesh {
        MeshMode::Apart => {
            push(EventKind::TouchDrive, &flanks.gap_drive);
            push(EventKind::TouchBack, &flanks.gap_back);
        }
        MeshMode::Drive | MeshMode::DriveClipped => {
            let kinds = [
                EventKind::LeaveDrive,
                EventKind::DriveReloads,
                EventKind::DriveUnloads,
            ];
            let clipped = mesh == MeshMode::DriveClipped;
            let forms = (&flanks.gap_drive[..], &flanks.force_drive[..]);
            flank_events(&mut push, kinds, clipped, no_pull, forms.0, forms.1);
        }
        MeshMode::Back | MeshMode::BackClipped => {
            let kinds = [
                EventKind::LeaveBack,
                EventKind::BackReloads,
                EventKind::BackUnloads,
            ];
            let clipped = mesh == MeshMode::BackClipped;
            let forms = (&flanks.gap_back[..], &flanks.force_back[..]);
            flank_events(&mut push, kinds, clipped, no_pull, forms.0, forms.1);
        }
    }
}

/// The motor's switching functions in motor mode `motor`: the command reaching either
/// torque limit, or leaving the one it is held at.
fn motor_events(list: &mut EventList, mc: &ModelConstants, motor: MotorMode) {
    let mut push = |kind, terms: &[(usize, f64)]| list.push((kind, SparseRow::new(terms), 0.0));
    let limit = mc.torque_limit_nm;
    let (kp, ki) = (mc.kp_nms_per_rad, mc.ki_nm_per_rad);
    // At the limit the command is held there; it leaves when the unclamped controller
    // would move it back inside: −(rate of kp·(−VF) + ki·Z) = kp·ωf·(V1 − VF) + ki·VF > 0.
    let wf = mc.filter_rad_s;
    let falls_back = [(V0, kp * wf), (VF, ki - kp * wf)];
    match motor {
        MotorMode::Linear => {
            push(EventKind::LimitHigh, &[(VF, -kp), (Z, ki), (UNIT, -limit)]);
            push(EventKind::LimitLow, &[(VF, kp), (Z, -ki), (UNIT, -limit)]);
        }
        MotorMode::LimitHigh => push(EventKind::LimitRelease, &falls_back),
        MotorMode::LimitLow => push(
            EventKind::LimitRelease,
            &SparseRow::new(&falls_back).negated().terms,
        ),
    }
}

/// The switching functions on the driving gear's angle: pair-zone ends, tooth passes
/// where they change something, and every revolution.
fn angle_events(list: &mut EventList, flags: EventFlags, mesh: MeshMode) {
    let angle = [(X0 + 1, 1.0)];
    let engaged = matches!(mesh, MeshMode::Drive | MeshMode::Back);
    if flags.alternating_pairs && engaged {
        list.push((EventKind::ZoneEnd, SparseRow::new(&angle), 1.0));
        list.push((EventKind::ZoneStart, SparseRow::new(&angle).negated(), -1.0));
    }
    // Apart, a tooth pass changes nothing unless the pairs differ in spacing: without
    // spacing errors the plant catches up with it at the next contact.
    if flags.spacing_errors || (flags.tooth_shifting && mesh != MeshMode::Apart) {
        list.push((EventKind::ToothPass, SparseRow::new(&angle), 1.0));
    }
    list.push((EventKind::Revolution, SparseRow::new(&angle), 1.0));
}

/// The switching functions while one flank overlaps: the overlap ending (`kinds[0]`), and
/// with the no-pull law the clipped torque coming back (`kinds[1]`) or the torque
/// reaching zero (`kinds[2]`).
fn flank_events(
    push: &mut impl FnMut(EventKind, &[(usize, f64)]),
    kinds: [EventKind; 3],
    clipped: bool,
    no_pull: bool,
    gap: &[(usize, f64)],
    force: &[(usize, f64)],
) {
    push(kinds[0], &SparseRow::new(gap).negated().terms);
    if clipped {
        push(kinds[1], force);
    } else if no_pull {
        push(kinds[2], &SparseRow::new(force).negated().terms);
    }
}

/// Which optional switching functions exist in this plant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EventFlags {
    /// Pair-zone boundaries (contact ratio > 1).
    pub alternating_pairs: bool,
    /// Tooth-pass instants while the teeth touch (numerical tooth shifting).
    pub tooth_shifting: bool,
    /// Tooth-pass instants in every mode (the spacing error of the pair in mesh changes).
    pub spacing_errors: bool,
}
