//! Natural frequencies against thesis App. C and Fig. 2.5.

mod support;

use rig::RigChains;

fn freqs(chain: &rig::Chain) -> Vec<f64> {
    chain.modes().iter().map(|m| m.frequency_hz).collect()
}

fn assert_close(got: &[f64], want: &[f64], tol_hz: f64) {
    assert_eq!(got.len(), want.len(), "{got:?} vs {want:?}");
    for (g, w) in got.iter().zip(want) {
        assert!((g - w).abs() < tol_hz, "{got:?} vs {want:?}");
    }
}

#[test]
fn whole_rig_matches_appendix_c() {
    let chains = RigChains::of(&support::thesis());
    assert_close(&freqs(&chains.whole_rig), &[17.84, 86.95, 91.95], 0.01);
}

#[test]
fn motor_and_brake_sides_match_appendix_c() {
    let chains = RigChains::of(&support::thesis());
    assert_close(&freqs(&chains.motor_side), &[91.90], 0.01);
    // The thesis rounds the brake side to 86.28 and 88.67 Hz.
    assert_close(&freqs(&chains.brake_side), &[86.28, 88.67], 0.05);
}

#[test]
fn locked_mesh_adds_the_mesh_mode() {
    let chains = RigChains::of(&support::thesis());
    let f = freqs(&chains.locked_mesh);
    // Two inertias on the mesh spring: f = √(K23 (1/J2 + 1/J3)) / 2π, nearly.
    let p = support::thesis();
    let mesh = (p.k23_mesh_nm_per_rad
        * (1.0 / p.j2_input_flywheel_kgm2 + 1.0 / p.j3_driven_gear_kgm2))
        .sqrt()
        / (2.0 * std::f64::consts::PI);
    assert_eq!(f.len(), 4);
    assert!((f[3] - mesh).abs() / mesh < 0.01, "{} vs {mesh}", f[3]);
    // With the driven gear added to the gear pair the fundamental drops below App. C's 17.84 Hz.
    assert!(f[0] < 17.84 && f[0] > 17.6, "{}", f[0]);
}

#[test]
fn mode_shapes_are_normalised_and_orthogonal_in_mass() {
    let chains = RigChains::of(&support::thesis());
    let chain = &chains.locked_mesh;
    let modes = chain.modes();
    for m in &modes {
        let peak = m.shape.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        assert!((peak - 1.0).abs() < 1e-12);
    }
    for a in 0..modes.len() {
        for b in a + 1..modes.len() {
            let dot: f64 = (0..5)
                .map(|i| chain.inertia_kgm2[i] * modes[a].shape[i] * modes[b].shape[i])
                .sum();
            assert!(dot.abs() < 1e-9, "modes {a} and {b}: {dot}");
        }
    }
}
