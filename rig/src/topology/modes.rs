//! The undamped natural modes of a rig of any topology with every mesh in contact and no
//! speed controller (as the thesis's App. C takes the 1983 rig), the rigid-body modes
//! left out, at zero speed. Each spring of the rig on its coordinates
//! (`coordinates.rs`) adds k g gᵀ to the stiffness matrix, g its deflection's
//! coefficients: in a torsional rig an external pair's δ = r_b1 θ1 + r_b2 θ2 adds
//! k r_b1², k r_b2² to the gears' diagonal entries and k r_b1 r_b2 off the diagonal, a
//! shaft k to each end and −k between; in the plane, Lin & Parker's (1999) K_b + K_m.

use nalgebra::DMatrix;

use super::coordinates::{Coupling, RigCoordinates};
use super::rig_topology::RigTopology;
use crate::modal::{NaturalMode, free_modes};

impl RigTopology {
    /// The stiffness matrix on the rig's coordinates ([`RigCoordinates`]), meshes in
    /// contact (N m/rad, N/m).
    pub fn stiffness_matrix(&self) -> DMatrix<f64> {
        let coordinates = RigCoordinates::of(self);
        stiffness_of(coordinates.len(), &coordinates.couplings(self))
    }

    /// The flexible modes in ascending frequency, each shape over the rig's coordinates
    /// (rad for rotations, m for translations).
    pub fn natural_modes(&self) -> Vec<NaturalMode> {
        let coordinates = RigCoordinates::of(self);
        let couplings = coordinates.couplings(self);
        free_modes(
            &stiffness_of(coordinates.len(), &couplings),
            &coordinates.masses(),
            rigid_motions(&coordinates, &couplings),
        )
    }

    /// The undamped natural frequencies (Hz), ascending, rigid-body modes left out.
    pub fn natural_frequencies_hz(&self) -> Vec<f64> {
        self.natural_modes()
            .iter()
            .map(|m| m.frequency_hz)
            .collect()
    }
}

/// The stiffness matrix of `couplings` on `n` coordinates: Σ k g gᵀ.
fn stiffness_of(n: usize, couplings: &[Coupling]) -> DMatrix<f64> {
    let mut k = DMatrix::zeros(n, n);
    for c in couplings {
        add_coupling(&mut k, &c.terms, c.stiffness);
    }
    k
}

/// How many independent motions of the coordinates no spring resists (the rigid-body
/// modes): the coordinates less the rank of the springs' deflection forms, each scaled to
/// unit length so that the rank does not depend on how stiff they are (a form counts where
/// its singular value exceeds 1e-9 of the largest; a real form's is far above).
pub(crate) fn rigid_motions(coordinates: &RigCoordinates, couplings: &[Coupling]) -> usize {
    let n = coordinates.len();
    if couplings.is_empty() {
        return n;
    }
    let mut forms = DMatrix::<f64>::zeros(couplings.len(), n);
    for (row, c) in couplings.iter().enumerate() {
        let norm = c.terms.iter().map(|&(_, v)| v * v).sum::<f64>().sqrt();
        for &(j, v) in &c.terms {
            forms[(row, j)] += v / norm;
        }
    }
    let singular = forms.singular_values();
    let largest = singular.max();
    n - singular.iter().filter(|&&s| s > 1e-9 * largest).count()
}

/// Adds a spring `spring` on the deflection Σ c_i q_i of `terms` (coordinate, c_i) to
/// the stiffness matrix `k`: spring·c_i·c_j at (i, j). A shaft is [(a, 1), (b, −1)], a
/// torsional mesh [(driver, r_b1), (driven, r_b2)].
pub(crate) fn add_coupling(k: &mut DMatrix<f64>, terms: &[(usize, f64)], spring: f64) {
    for &(x, cx) in terms {
        for &(y, cy) in terms {
            k[(x, y)] += spring * cx * cy;
        }
    }
}
