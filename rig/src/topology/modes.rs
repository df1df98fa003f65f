//! The undamped natural modes of a rig of any topology with every mesh in contact and no
//! speed controller (as the thesis's App. C takes the 1983 rig), the rigid-body mode left
//! out. In absolute angles an external pair's deflection along the line of action is
//! δ = r_b1 θ1 + r_b2 θ2, so its stiffness k adds k r_b1², k r_b2² to the gears' diagonal
//! entries and k r_b1 r_b2 off the diagonal; a shaft adds k to each end and −k between.

use nalgebra::DMatrix;

use super::rig_topology::RigTopology;
use crate::modal::{NaturalMode, free_modes};

impl RigTopology {
    /// The stiffness matrix in the bodies' absolute angles, meshes in contact (N m/rad).
    pub fn stiffness_matrix(&self) -> DMatrix<f64> {
        let n = self.bodies.len();
        let mut k = DMatrix::zeros(n, n);
        for s in &self.shafts {
            let [a, b] = s.between;
            add_coupling(&mut k, &[(a, 1.0), (b, -1.0)], s.stiffness_nm_per_rad);
        }
        for m in &self.meshes {
            let [a, b] = m.gears;
            let [ra, rb] = m.base_radii_m();
            add_coupling(&mut k, &[(a, ra), (b, rb)], m.stiffness_n_per_m);
        }
        k
    }

    /// The flexible modes in ascending frequency (a checked rig: one connected body).
    pub fn natural_modes(&self) -> Vec<NaturalMode> {
        let inertia: Vec<f64> = self.bodies.iter().map(|b| b.inertia_kgm2).collect();
        free_modes(&self.stiffness_matrix(), &inertia)
    }

    /// The undamped natural frequencies (Hz), ascending, rigid-body mode left out.
    pub fn natural_frequencies_hz(&self) -> Vec<f64> {
        self.natural_modes()
            .iter()
            .map(|m| m.frequency_hz)
            .collect()
    }
}

/// Adds a spring `spring` on the deflection Σ c_i θ_i of `terms` (body, c_i) to the
/// stiffness matrix `k`: spring·c_i·c_j at (i, j). A shaft is [(a, 1), (b, −1)], a mesh
/// [(driver, r_b1), (driven, r_b2)].
pub(crate) fn add_coupling(k: &mut DMatrix<f64>, terms: &[(usize, f64)], spring: f64) {
    for &(x, cx) in terms {
        for &(y, cy) in terms {
            k[(x, y)] += spring * cx * cy;
        }
    }
}
