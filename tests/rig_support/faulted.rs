//! The faulted 1983 rig file the fault tests share: a plain pair (no tooth shifting, no
//! backlash variation) with a fault appended to its mesh, its loaded point, the mesh's
//! deflection.

use rig::RigTopology;
use testrig::scenario::read_rig_file;

use super::body;

/// The 1983 rig file without tooth shifting or backlash variation (a plain pair), with
/// `fault` appended to its mesh.
pub fn rig_with(dir: &std::path::Path, fault: &str) -> RigTopology {
    rig_damped(dir, fault, None)
}

/// [`rig_with`], each shaft's damping `shaft_damping` (N m s/rad) where given.
pub fn rig_damped(dir: &std::path::Path, fault: &str, shaft_damping: Option<f64>) -> RigTopology {
    let path = format!(
        "{}/scenarios/rigs/basmaji-1983.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(path).expect("rig file");
    let plain = text
        .replace("tooth_shifting = true", "tooth_shifting = false")
        .replace("backlash_variation = 0.38", "backlash_variation = 0.0")
        .replace("[motor]", &format!("{fault}\n[motor]"));
    let plain = match shaft_damping {
        Some(c) => plain
            .lines()
            .map(|l| {
                if l.starts_with("damping_nms_per_rad") {
                    format!("damping_nms_per_rad = {c}")
                } else {
                    l.to_string()
                }
            })
            .collect::<Vec<_>>()
            .join("\n"),
        None => plain,
    };
    let file = dir.join("faulted.toml");
    std::fs::write(&file, plain).expect("write");
    read_rig_file(&file).expect("a rig file with a fault")
}

/// `rig` at 600 rev/min and 5.424 N m from steady motion, settled 10 s, measured 10 s at
/// 10.24 kHz, as `simulate --rig` runs it.
pub fn loaded_600_rpm(rig: &RigTopology) -> testrig::steady_point::RigPointRun {
    let spec = testrig::steady_point::RigPointSpec {
        rig,
        rpm: 600.0,
        load_nm: 5.424,
        settle_s: 10.0,
        duration_s: 10.0,
        rate_hz: 10_240.0,
        approach: rig::Approach::Static,
    };
    testrig::steady_point::run_rig_point(
        &spec,
        testrig::vocabulary::FLAG_NAMES,
        || Ok(()),
        |_| Ok(()),
    )
    .expect("run")
}

/// The mesh's deflection along the line of action, r_b (θ_driver − θ_driven) (m; each
/// body's angle in its own sense of rotation).
pub fn deflection_m(rig: &RigTopology, block: &rig::NetworkBlock) -> Vec<f64> {
    let r_b = rig.meshes[0].base_radii_m()[0];
    let (a, b) = (body(rig, "input_flywheel"), body(rig, "driven_gear"));
    (0..block.len())
        .map(|n| r_b * (block.angle_rad[a][n] - block.angle_rad[b][n]))
        .collect()
}
