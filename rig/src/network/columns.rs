//! A run's samples as named columns, after the rig: what `testrig simulate --rig` writes
//! to `signals.csv`, Python's `simulate(rig=…)` returns and an FMU outputs.

use std::f64::consts::PI;

use crate::topology::RigTopology;

use super::block::NetworkBlock;

/// One column: its name, unit and meaning.
#[derive(Clone, Debug, PartialEq)]
pub struct Column {
    /// Its name (`speed_motor_rpm`).
    pub name: String,
    /// Its unit (`rev/min`; empty for a count or state).
    pub unit: &'static str,
    /// What it is.
    pub meaning: String,
    /// Whether it changes only at events (a contact state), not continuously.
    pub discrete: bool,
}

/// The signals' columns, after the rig: `time_s`, `speed_<body>_rpm`, `angle_<body>_rad`,
/// `torque_<shaft>_nm`, `contact_<mesh>` (+1 drive flank, −1 back flank, 0 apart),
/// `force_<mesh>_n`, `motor_torque_nm`, and `strain_<shaft>_ue` where the rig has gauges.
pub fn column_specs(rig: &RigTopology) -> Vec<Column> {
    let column = |name: String, unit, meaning: String| Column {
        name,
        unit,
        meaning,
        discrete: false,
    };
    let mut out = vec![column("time_s".into(), "s", "time".into())];
    for b in &rig.bodies {
        let meaning = format!("speed of body {} in its sense of rotation", b.name);
        out.push(column(format!("speed_{}_rpm", b.name), "rev/min", meaning));
    }
    for b in &rig.bodies {
        let meaning = format!("angle turned by body {} in its sense of rotation", b.name);
        out.push(column(format!("angle_{}_rad", b.name), "rad", meaning));
    }
    for s in &rig.shafts {
        let meaning = format!("torque in shaft {}", s.name);
        out.push(column(format!("torque_{}_nm", s.name), "N m", meaning));
    }
    for m in &rig.meshes {
        out.push(Column {
            name: format!("contact_{}", m.name),
            unit: "",
            meaning: format!("mesh {}: +1 drive flank, -1 back flank, 0 apart", m.name),
            discrete: true,
        });
    }
    for m in &rig.meshes {
        let meaning = format!("mesh {}: force along the line of action", m.name);
        out.push(column(format!("force_{}_n", m.name), "N", meaning));
    }
    out.push(column(
        "motor_torque_nm".into(),
        "N m",
        "the motor's torque".into(),
    ));
    if let Some(g) = &rig.gauge {
        let name = &rig.shafts[g.shaft].name;
        let meaning = format!("strain at +45 deg on shaft {name}, from its torque");
        out.push(column(format!("strain_{name}_ue"), "ue", meaning));
    }
    out
}

/// The column names of [`column_specs`].
pub fn column_names(rig: &RigTopology) -> Vec<String> {
    column_specs(rig).into_iter().map(|c| c.name).collect()
}

/// The columns of `block` in the order of [`column_specs`] (speeds in rev/min, strain
/// in µε).
pub fn columns(rig: &RigTopology, block: &NetworkBlock) -> Vec<Vec<f64>> {
    let rpm = |c: &Vec<f64>| c.iter().map(|w| w * 30.0 / PI).collect::<Vec<f64>>();
    let mut out = vec![block.time_s.clone()];
    out.extend(block.speed_rad_s.iter().map(rpm));
    out.extend(block.angle_rad.iter().cloned());
    out.extend(block.shaft_torque_nm.iter().cloned());
    out.extend(
        block
            .contact
            .iter()
            .map(|c| c.iter().map(|&x| f64::from(x)).collect()),
    );
    out.extend(block.mesh_force_n.iter().cloned());
    out.push(block.motor_torque_nm.clone());
    if let Some(g) = &rig.gauge {
        let k = g.microstrain_per_nm();
        out.push(
            block.shaft_torque_nm[g.shaft]
                .iter()
                .map(|t| t * k)
                .collect(),
        );
    }
    out
}
