//! Layout of the augmented state vector: mechanical states, then the forcing states.
//!
//! Mechanical part (relative to the set rotation φ(t), Ω = dφ/dt):
//! X1..X5 angles (rad), V1..V5 speeds (rad/s), Vf the controller's filtered speed
//! (rad/s), z the integral of the speed error (rad). The forcing part holds what drives
//! the equations: a unit constant, the brake load torque (N m), and harmonic pairs
//! (cos, sin) of the set rotation's phase, its double, its tooth multiple and the
//! oscillating load, and the spacing error of the pair in mesh.

/// Index of X1; X_i is at `X0 + i`.
pub const X0: usize = 0;
/// Index of V1; V_i is at `V0 + i`.
pub const V0: usize = 5;
/// Index of the filtered speed Vf.
pub const VF: usize = 10;
/// Index of the speed-error integral z.
pub const Z: usize = 11;
/// Number of mechanical (controller included) states.
pub const N_MECH: usize = 12;
/// Index of the unit constant.
pub const UNIT: usize = 12;
/// Index of the brake load torque (N m).
pub const LOAD: usize = 13;
/// Index of cos φ; sin φ follows.
pub const REV: usize = 14;

/// Where the optional harmonic pairs sit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// Index of cos 2φ (sin 2φ follows), if the twice-per-rev gear error is on.
    pub rev2: Option<usize>,
    /// Index of A cos ψ (A sin ψ follows), if an oscillating load is scheduled.
    pub osc: Option<usize>,
    /// Index of cos zφ (sin zφ follows, z the teeth), if the profile error at mesh
    /// frequency is on.
    pub mesh: Option<usize>,
    /// Index of the spacing error of the pair in mesh (rad; constant between tooth
    /// passes, set at each), if tooth spacing errors are on.
    pub spacing: Option<usize>,
    /// Length of the augmented state.
    pub len: usize,
}

impl Layout {
    /// Lays out the states: the twice-per-rev pair, the oscillating-load pair, the
    /// mesh-frequency pair and the spacing error only when used.
    pub fn new(with_rev2: bool, with_osc: bool, with_mesh: bool, with_spacing: bool) -> Self {
        let mut len = REV + 2;
        let mut place = |used: bool| {
            used.then(|| {
                len += 2;
                len - 2
            })
        };
        let rev2 = place(with_rev2);
        let osc = place(with_osc);
        let mesh = place(with_mesh);
        let spacing = with_spacing.then(|| {
            len += 1;
            len - 1
        });
        Self {
            rev2,
            osc,
            mesh,
            spacing,
            len,
        }
    }

    /// Largest augmented length a plant takes: every option but one (the spacing error
    /// needs a slot that the twice-per-rev pair, the oscillating load and the profile
    /// error leave free when all three are on). Growing it by one cost the exact path
    /// about a quarter of its speed (measured), so that combination is refused instead.
    pub const MAX_LEN: usize = REV + 8;

    /// Whether the layout fits [`Self::MAX_LEN`].
    pub fn fits(&self) -> bool {
        self.len <= Self::MAX_LEN
    }
}
