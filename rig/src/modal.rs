//! Undamped natural frequencies and mode shapes of the rig's torsional chains.

use nalgebra::{DMatrix, DVector, SymmetricEigen};
use serde::Serialize;

use crate::params::RigParams;

/// One natural mode of a chain.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct NaturalMode {
    /// Natural frequency (Hz).
    pub frequency_hz: f64,
    /// Angular amplitudes of the inertias, largest magnitude scaled to 1.
    pub shape: Vec<f64>,
}

/// A chain of inertias joined in a line by springs.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Chain {
    /// Names of the inertias, for reports.
    pub bodies: Vec<&'static str>,
    /// Inertias (kg m²).
    pub inertia_kgm2: Vec<f64>,
    /// Stiffnesses between neighbours (N m/rad), one fewer than inertias.
    pub stiffness_nm_per_rad: Vec<f64>,
}

impl Chain {
    /// Flexible modes in ascending frequency; the rigid-body mode (free chain) is left out.
    pub fn modes(&self) -> Vec<NaturalMode> {
        let n = self.inertia_kgm2.len();
        let mut k: DMatrix<f64> = DMatrix::zeros(n, n);
        for (i, &spring) in self.stiffness_nm_per_rad.iter().enumerate() {
            k[(i, i)] += spring;
            k[(i + 1, i + 1)] += spring;
            k[(i, i + 1)] -= spring;
            k[(i + 1, i)] -= spring;
        }
        free_modes(&k, &self.inertia_kgm2, 1)
    }
}

/// The flexible modes of coordinates of inertias `inertia_kgm2` (kg m² for a rotation,
/// kg for a translation) joined by the stiffness matrix `k` (N m/rad, N/m), in ascending
/// frequency: the eigen-solution of K − ω² M, its `rigid` lowest modes (the motions no
/// spring resists) left out.
pub(crate) fn free_modes(k: &DMatrix<f64>, inertia_kgm2: &[f64], rigid: usize) -> Vec<NaturalMode> {
    let n = inertia_kgm2.len();
    let inv_sqrt = DVector::from_iterator(n, inertia_kgm2.iter().map(|j| 1.0 / j.sqrt()));
    let scaled: DMatrix<f64> = DMatrix::from_fn(n, n, |r, c| inv_sqrt[r] * k[(r, c)] * inv_sqrt[c]);
    let eigen = SymmetricEigen::new(scaled);
    let mut modes: Vec<NaturalMode> = (0..n)
        .map(|m| {
            let omega_sq = eigen.eigenvalues[m].max(0.0);
            let raw: Vec<f64> = (0..n)
                .map(|r| eigen.eigenvectors[(r, m)] * inv_sqrt[r])
                .collect();
            NaturalMode {
                frequency_hz: omega_sq.sqrt() / (2.0 * std::f64::consts::PI),
                shape: normalised(&raw),
            }
        })
        .collect();
    modes.sort_by(|a, b| a.frequency_hz.total_cmp(&b.frequency_hz));
    modes.drain(..rigid.min(modes.len()));
    modes
}

fn normalised(shape: &[f64]) -> Vec<f64> {
    let peak = shape
        .iter()
        .copied()
        .fold(0.0_f64, |m, v| if v.abs() > m.abs() { v } else { m });
    shape.iter().map(|v| v / peak).collect()
}

/// The chains of thesis App. C and the five-inertia rig.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RigChains {
    /// App. C four-inertia form: the gear pair rigid, the driven gear's inertia left out as there.
    pub whole_rig: Chain,
    /// Five inertias with the mesh spring K23 (teeth locked in contact).
    pub locked_mesh: Chain,
    /// Motor side alone (teeth apart): motor and input flywheel.
    pub motor_side: Chain,
    /// Brake side alone: driven gear, output flywheel, brake.
    pub brake_side: Chain,
}

impl RigChains {
    /// The four chains of `p`.
    pub fn of(p: &RigParams) -> Self {
        let [j1, j2, j3, j4, j5] = p.inertias_kgm2();
        let (k12, k23, k34, k45) = (
            p.k12_input_shaft_nm_per_rad,
            p.k23_mesh_nm_per_rad,
            p.k34_intermediate_shaft_nm_per_rad,
            p.k45_final_shaft_nm_per_rad,
        );
        Self {
            whole_rig: Chain {
                bodies: vec![
                    "motor",
                    "input flywheel + gears",
                    "output flywheel",
                    "brake",
                ],
                inertia_kgm2: vec![j1, j2, j4, j5],
                stiffness_nm_per_rad: vec![k12, k34, k45],
            },
            locked_mesh: Chain {
                bodies: vec![
                    "motor",
                    "input flywheel + driving gear",
                    "driven gear",
                    "output flywheel",
                    "brake",
                ],
                inertia_kgm2: vec![j1, j2, j3, j4, j5],
                stiffness_nm_per_rad: vec![k12, k23, k34, k45],
            },
            motor_side: Chain {
                bodies: vec!["motor", "input flywheel + driving gear"],
                inertia_kgm2: vec![j1, j2],
                stiffness_nm_per_rad: vec![k12],
            },
            brake_side: Chain {
                bodies: vec!["driven gear", "output flywheel", "brake"],
                inertia_kgm2: vec![j3, j4, j5],
                stiffness_nm_per_rad: vec![k34, k45],
            },
        }
    }
}
