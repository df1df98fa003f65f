//! A planetary stage's characteristic frequencies at a motor speed, and the level of a
//! window's averaged signal at each: the fault frequencies a condition-monitoring
//! engineer reads a planetary gearbox's spectrum for. With f_s, f_c, f_r the sun's,
//! carrier's and ring's speeds and f_p a planet's (Hz): the mesh frequency z_s|f_s − f_c|,
//! the planet-pass frequency N|f_r − f_c|, and a tooth fault's line, where the faulted
//! tooth meets its mates: a sun tooth meets the N planets in turn, N|f_s − f_c|; a planet
//! tooth meets the sun and the ring once per planet turn against the carrier, |f_p − f_c|
//! ((z_r/z_p) f_c with the ring held); a ring tooth is passed by the N planets,
//! N|f_r − f_c|.

use std::f64::consts::PI;

use rig::RigTopology;
use serde_json::{Value, json};

/// A stage's characteristic frequencies (Hz).
#[derive(Clone, Debug, PartialEq)]
pub struct StageLines {
    /// The stage's name.
    pub stage: String,
    /// The carrier's speed (Hz).
    pub carrier_hz: f64,
    /// Each named line's frequency (Hz): mesh, planet pass, sun, planet and ring fault.
    pub lines: Vec<(&'static str, f64)>,
}

/// Every stage's lines in `rig` with its motor at `motor_rpm`.
pub fn stage_lines(rig: &RigTopology, motor_rpm: f64) -> Vec<StageLines> {
    let speeds = rig.relative_speeds();
    let reference = rig.motor.unwrap_or(0);
    let base = speeds[reference].unwrap_or(1.0);
    let hz = |body: usize| motor_rpm / 60.0 * speeds[body].unwrap_or(0.0) / base;
    rig.planetary
        .iter()
        .map(|s| {
            let (sun, ring, carrier) = (hz(s.sun), hz(s.ring), hz(s.carrier));
            let planet = s.planet_speed(sun * 2.0 * PI, carrier * 2.0 * PI) / (2.0 * PI);
            let n = s.planets() as f64;
            StageLines {
                stage: s.name.clone(),
                carrier_hz: carrier.abs(),
                lines: vec![
                    ("mesh", f64::from(s.teeth.sun) * (sun - carrier).abs()),
                    ("planet_pass", n * (ring - carrier).abs()),
                    ("sun_fault", n * (sun - carrier).abs()),
                    ("planet_fault", (planet - carrier).abs()),
                    ("ring_fault", n * (ring - carrier).abs()),
                ],
            }
        })
        .collect()
}

impl StageLines {
    /// As JSON, each line's frequency and the level `level(hz)` gives at it.
    pub fn to_json(&self, level: impl Fn(f64) -> f64) -> Value {
        let lines: serde_json::Map<String, Value> = self
            .lines
            .iter()
            .map(|&(name, hz)| {
                (
                    name.to_string(),
                    json!({ "hz": hz, "amplitude": level(hz) }),
                )
            })
            .collect();
        json!({ "stage": self.stage, "carrier_hz": self.carrier_hz, "lines": lines })
    }
}
