//! Tooth-pair spacing errors (`mesh_spacing_m`): with a 1:1 pair, as the thesis's, tooth i
//! of the driving gear always meets tooth i of the driven gear, so each pair has one
//! combined error, the displacement of the mesh while that pair is in mesh; a mesh of
//! other teeth gives each gear's teeth errors of their own.

use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;

use crate::topology::Mesh;

/// The spacing errors of a rig file's mesh along the line of action (m), per tooth of the
/// driving and of the driven gear (the pair in mesh displaces the mesh by the sum of its
/// two teeth's): with equal teeth, as the thesis's 1:1 pair, one combined error per pair
/// on the driver's teeth (the thesis's draw); otherwise each gear's teeth drawn with
/// 1/√2 of the RMS (the driven gear's from the seed + 1), so a pair's errors have the RMS
/// asked for. Empty when off.
pub fn mesh_spacing_m(mesh: &Mesh) -> [Vec<f64>; 2] {
    let rms_m = mesh.tooth_spacing_error_um * 1e-6;
    if rms_m == 0.0 {
        return [Vec::new(), Vec::new()];
    }
    let [z1, z2] = mesh.teeth;
    let seed = mesh.tooth_spacing_seed;
    if z1 == z2 {
        return [spacing_draws(z1, seed, rms_m), vec![0.0; z2 as usize]];
    }
    let each = rms_m / std::f64::consts::SQRT_2;
    [
        spacing_draws(z1, seed, each),
        spacing_draws(z2, seed.wrapping_add(1), each),
    ]
}

/// `count` normal draws from `seed` (PCG 64, Box–Muller), made zero-mean and scaled to an
/// RMS of `rms`.
fn spacing_draws(count: u32, seed: u32, rms: f64) -> Vec<f64> {
    let mut rng = Pcg64Mcg::seed_from_u64(u64::from(seed));
    let mut draws: Vec<f64> = (0..count)
        .map(|_| {
            let u1 = 1.0 - rng.random::<f64>();
            let u2 = rng.random::<f64>();
            (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
        })
        .collect();
    let mean = draws.iter().sum::<f64>() / draws.len() as f64;
    let spread =
        (draws.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / draws.len() as f64).sqrt();
    let scale = rms / spread.max(f64::MIN_POSITIVE);
    for d in &mut draws {
        *d = (*d - mean) * scale;
    }
    draws
}

#[cfg(test)]
mod tests {
    use super::mesh_spacing_m;
    use crate::params::RigParams;
    use crate::preset_rig::preset_rig;
    use crate::presets::basmaji_1983;
    use crate::topology::Mesh;

    #[test]
    fn the_errors_have_the_rms_asked_for_a_zero_mean_and_follow_the_seed() {
        let mut params = basmaji_1983();
        let mesh = |params: &RigParams| -> Mesh { preset_rig("t", "", params).meshes[0].clone() };
        assert!(mesh_spacing_m(&mesh(&params))[0].is_empty());
        params.tooth_spacing_error_um = 10.0;
        let [errors, driven] = mesh_spacing_m(&mesh(&params));
        assert_eq!(errors.len(), 30);
        assert!(driven.iter().all(|&e| e == 0.0), "1:1: one error a pair");
        let mean = errors.iter().sum::<f64>() / 30.0;
        let rms = (errors.iter().map(|e| e * e).sum::<f64>() / 30.0).sqrt();
        assert!(mean.abs() < 1e-20, "{mean}");
        // 10 µm of arc at the pitch circle, 10 cos 20° µm along the line of action.
        let along_m = 10e-6 * 20.0_f64.to_radians().cos();
        assert!((rms - along_m).abs() < 1e-15, "{rms}");
        assert_eq!(
            mesh_spacing_m(&mesh(&params))[0],
            errors,
            "the same seed, the same errors"
        );
        params.tooth_spacing_seed += 1;
        assert_ne!(
            mesh_spacing_m(&mesh(&params))[0],
            errors,
            "another seed, other errors"
        );
    }
}
