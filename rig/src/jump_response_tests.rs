//! The response to a jump of the gear angles (the tooth pass's shift) from its Taylor
//! series equals e^{A s h} Δ from the balanced Padé exponential, in contact and apart.
//! (A unit test: it reaches the plant's internals, which are private to the crate.)

use crate::layout::{Layout, N_MECH};
use crate::matrix_exp::{exp_powers, spectral_radius};
use crate::model::{Frequencies, ModelConstants, system_matrix};
use crate::propagator::ModeSystem;
use crate::{MeshMode, Mode, MotorMode, PairZone, preset};

/// Largest difference between the series and Padé responses over the mechanical states,
/// relative to the largest entry of the response, for a jump of +δ on X2 and −δ on X3.
fn worst_mismatch(mesh: MeshMode) -> f64 {
    let params = preset("basmaji-1983").expect("preset");
    let mc = ModelConstants::of(&params);
    let layout = Layout::new(true, false, false, false);
    let mode = Mode {
        mesh,
        pairs: PairZone::ONE,
        motor: MotorMode::Linear,
    };
    let frequencies = Frequencies {
        rotation_rad_s: 1300.0 * std::f64::consts::PI / 30.0,
        oscillating_load_rad_s: 0.0,
        brake_characteristic_nms_per_rad: 0.0,
    };
    let a = system_matrix(&mc, &layout, mode, frequencies);
    let step_s = 1.0 / 51_200.0;
    let system = ModeSystem::new(&a, step_s, Vec::new());
    let delta_rad = 3e-5;
    let mut worst = 0.0_f64;
    for s in [0.0, 0.07, 0.5, 0.93, 1.0] {
        let mut series = [0.0; Layout::MAX_LEN];
        let order = system.taylor_order(s * step_s);
        system
            .jump_response
            .add_to([delta_rad, -delta_rad], s, order, &mut series);
        let exp = &exp_powers(&a, s * step_s, spectral_radius(&a), 1)[0];
        let pade: Vec<f64> = (0..N_MECH)
            .map(|r| (exp[(r, 1)] - exp[(r, 2)]) * delta_rad)
            .collect();
        let scale = pade.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        for (a, b) in series[..N_MECH].iter().zip(&pade) {
            worst = worst.max((a - b).abs() / scale);
        }
        assert!(
            series[N_MECH..].iter().all(|&v| v == 0.0),
            "forcing states never respond"
        );
    }
    worst
}

#[test]
fn jump_response_in_contact_equals_the_exponential() {
    let worst = worst_mismatch(MeshMode::Drive);
    eprintln!("MEASURED jump response in contact: {worst:e}");
    assert!(worst < 1e-12, "series and Padé differ by {worst:e}");
}

#[test]
fn jump_response_apart_equals_the_exponential() {
    let worst = worst_mismatch(MeshMode::Apart);
    eprintln!("MEASURED jump response apart: {worst:e}");
    assert!(worst < 1e-12, "series and Padé differ by {worst:e}");
}
