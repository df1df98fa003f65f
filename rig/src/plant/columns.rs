//! A run's samples as named columns, after the rig: what `testrig simulate --rig` writes
//! to `signals.csv`, Python's `simulate(rig=…)` returns and an FMU outputs.

use std::f64::consts::PI;

use crate::topology::{RigCoordinates, RigTopology};

use super::block::NetworkBlock;
use super::ring_sensor::ring_sensor_n;

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

/// The column of the torque in the shaft named `shaft` (N m), between two bodies or to
/// the frame.
pub fn shaft_torque_column(shaft: &str) -> String {
    format!("torque_{shaft}_nm")
}

/// The signals' columns, after the rig: `time_s`, `speed_<body>_rpm`, `angle_<body>_rad`,
/// `torque_<shaft>_nm` (shafts, then shafts to the frame), `contact_<mesh>` (+1 drive flank, −1 back flank, 0 apart),
/// `force_<mesh>_n`, `x_<body>_m` and `y_<body>_m` for each body and planet that moves in the plane,
/// `sensor_<stage>_n` for each planetary stage with a ring sensor, `motor_torque_nm`, and `strain_<shaft>_ue` where the rig has gauges.
pub fn column_specs(rig: &RigTopology) -> Vec<Column> {
    let column = |name: String, unit, meaning: String| Column {
        name,
        unit,
        meaning,
        discrete: false,
    };
    let mut out = vec![column("time_s".into(), "s", "time".into())];
    let turning = rig.turning_names();
    for b in &turning {
        let meaning = format!("speed of {b} in its sense of rotation");
        out.push(column(format!("speed_{b}_rpm"), "rev/min", meaning));
    }
    for b in &turning {
        let meaning = format!("angle turned by {b} in its sense of rotation");
        out.push(column(format!("angle_{b}_rad"), "rad", meaning));
    }
    for s in &rig.shafts {
        let meaning = format!("torque in shaft {}", s.name);
        out.push(column(shaft_torque_column(&s.name), "N m", meaning));
    }
    for s in &rig.frame_shafts {
        let body = &rig.bodies[s.body].name;
        let meaning = format!("torque in shaft {} holding {body} to the frame", s.name);
        out.push(column(shaft_torque_column(&s.name), "N m", meaning));
    }
    let meshes = rig.mesh_names();
    for m in &meshes {
        out.push(Column {
            name: format!("contact_{m}"),
            unit: "",
            meaning: format!("mesh {m}: +1 drive flank, -1 back flank, 0 apart"),
            discrete: true,
        });
    }
    for m in &meshes {
        let meaning = format!("mesh {m}: force along the line of action");
        out.push(column(format!("force_{m}_n"), "N", meaning));
    }
    for (name, what) in translating(rig) {
        for axis in ["x", "y"] {
            out.push(column(
                format!("{axis}_{name}_m"),
                "m",
                format!("{axis} of {what}"),
            ));
        }
    }
    for s in rig.planetary.iter().filter(|s| s.ring_sensor.is_some()) {
        let meaning = format!(
            "stage {}: the ring-planet mesh forces as a sensor on the ring sees them",
            s.name
        );
        out.push(column(format!("sensor_{}_n", s.name), "N", meaning));
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

/// What moves in the plane, each with what its x and y measure: the bodies on bearings
/// (a stage's sun, ring or carrier in the carrier's frame), then the planets on their
/// pins' bearings (centre less pin, in the carrier's frame).
fn translating(rig: &RigTopology) -> Vec<(String, String)> {
    let member = |i: usize| {
        rig.planetary
            .iter()
            .any(|s| [s.sun, s.ring, s.carrier].contains(&i))
    };
    let bodies = rig
        .bodies
        .iter()
        .enumerate()
        .filter(|(_, b)| b.planar.is_some());
    let mut out: Vec<(String, String)> = bodies
        .map(|(i, b)| {
            let frame = if member(i) {
                ", in the carrier's frame"
            } else {
                ""
            };
            (
                b.name.clone(),
                format!("body {}'s centre on its bearing{frame}", b.name),
            )
        })
        .collect();
    for s in rig.planetary.iter().filter(|s| s.planet_bearing.is_some()) {
        for k in 0..s.planets() {
            let name = s.planet_name(k);
            let what = format!("{name}'s centre less its pin's, in the carrier's frame");
            out.push((name, what));
        }
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
    (0..).map_while(|k| column(rig, block, k)).collect()
}

/// Column `k` of `block` in the order of [`column_specs`] (speeds in rev/min, strain in
/// µε), alone: a run computes only the columns it reads. `None` past the last.
pub fn column(rig: &RigTopology, block: &NetworkBlock, k: usize) -> Option<Vec<f64>> {
    let (bodies, shafts, meshes) = (
        rig.turning_names().len(),
        rig.shafts.len() + rig.frame_shafts.len(),
        rig.mesh_names().len(),
    );
    let mut k = k;
    if k == 0 {
        return Some(block.time_s.clone());
    }
    k -= 1;
    if k < bodies {
        return Some(block.speed_rad_s[k].iter().map(|w| w * 30.0 / PI).collect());
    }
    k -= bodies;
    if k < bodies {
        return Some(block.angle_rad[k].clone());
    }
    k -= bodies;
    if k < shafts {
        return Some(block.shaft_torque_nm[k].clone());
    }
    k -= shafts;
    if k < meshes {
        return Some(block.contact[k].iter().map(|&x| f64::from(x)).collect());
    }
    k -= meshes;
    if k < meshes {
        return Some(block.mesh_force_n[k].clone());
    }
    k -= meshes;
    let translations = RigCoordinates::translation_count(rig);
    if k < translations {
        return Some(block.translation_m[k].clone());
    }
    k -= translations;
    let sensed: Vec<usize> = (0..rig.planetary.len())
        .filter(|&i| rig.planetary[i].ring_sensor.is_some())
        .collect();
    if let Some(&stage) = sensed.get(k) {
        return Some(sensor_column(rig, block, stage));
    }
    k -= sensed.len();
    match (k, &rig.gauge) {
        (0, _) => Some(block.motor_torque_nm.clone()),
        (1, Some(g)) => {
            let per_nm = g.microstrain_per_nm();
            Some(
                block.shaft_torque_nm[g.shaft]
                    .iter()
                    .map(|t| t * per_nm)
                    .collect(),
            )
        }
        _ => None,
    }
}

/// Stage `stage`'s ring sensor's signal over `block` (N): its ring meshes' forces, each
/// through the window over its planet's passage (`ring_sensor.rs`).
fn sensor_column(rig: &RigTopology, block: &NetworkBlock, stage: usize) -> Vec<f64> {
    let s = &rig.planetary[stage];
    let Some(sensor) = &s.ring_sensor else {
        return Vec::new();
    };
    // The carrier's angle as the coordinates count it (the block's is in its sense: the
    // sign of its speed per unit speed of the motor's body).
    let speeds = rig.relative_speeds();
    let base = speeds[rig.motor.unwrap_or(0)].unwrap_or(1.0);
    let share = speeds[s.carrier].unwrap_or(0.0) / base;
    let sense = if share < 0.0 { -1.0 } else { 1.0 };
    let carrier: Vec<f64> = block.angle_rad[s.carrier]
        .iter()
        .map(|a| sense * a)
        .collect();
    // The stage's ring meshes follow every earlier mesh and its own sun meshes.
    let first = rig.meshes.len()
        + rig.planetary[..stage]
            .iter()
            .map(|p| 2 * p.planets())
            .sum::<usize>()
        + s.planets();
    let forces: Vec<&[f64]> = block.mesh_force_n[first..first + s.planets()]
        .iter()
        .map(Vec::as_slice)
        .collect();
    ring_sensor_n(s, sensor, &carrier, &forces)
}
