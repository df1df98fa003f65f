//! A point's measuring window, summed block by block: per body, shaft and mesh, the
//! judged shaft's torque, and the watched gear's synchronous average; judged at its end.

use std::f64::consts::PI;

use rig::{JudgeInput, NetworkBlock, NetworkImpact, RigTopology, judge};

use super::summary::{BodySummary, MeshSummary, RigPointSummary, ShaftSummary, steady_summary};
use crate::chain::{GearCondition, GearConditionReport, sensed_stage, stage_lines, watched_gear};

/// The shaft the judge and the strain column watch: the gauged one, else the last.
pub fn judged_shaft(rig: &RigTopology) -> usize {
    rig.gauge
        .as_ref()
        .map_or(rig.shafts.len().saturating_sub(1), |g| g.shaft)
}

/// What a measuring window keeps: sums per column, the judged shaft's torque and the
/// watched gear's synchronous average.
#[derive(Clone, Debug)]
pub struct RigWindow {
    rate_hz: f64,
    start_s: Option<f64>,
    samples: usize,
    speed_sum: Vec<f64>,
    torque: Vec<(f64, f64)>,
    apart: Vec<usize>,
    motor_sum: f64,
    judged: usize,
    judged_torque: Vec<f64>,
    watched: Option<(usize, u32)>,
    condition: GearCondition,
    /// The rig and the column of its ring sensor, where the average takes that rather
    /// than the judged shaft's torque.
    sensor: Option<(RigTopology, usize)>,
}

impl RigWindow {
    /// An empty window on `rig`'s signals at `rate_hz`.
    pub fn new(rig: &RigTopology, rate_hz: f64) -> Self {
        let watched = watched_gear(rig);
        Self {
            rate_hz,
            start_s: None,
            samples: 0,
            speed_sum: vec![0.0; rig.bodies.len()],
            torque: vec![(0.0, 0.0); rig.shafts.len()],
            apart: vec![0; rig.meshes.len()],
            motor_sum: 0.0,
            judged: judged_shaft(rig),
            judged_torque: Vec::new(),
            watched,
            condition: GearCondition::new(rate_hz),
            sensor: sensed_stage(rig, watched).and_then(|stage| {
                let name = format!("sensor_{}_n", rig.planetary[stage].name);
                let column = rig::column_names(rig).iter().position(|c| *c == name)?;
                Some((rig.clone(), column))
            }),
        }
    }

    /// This window without the watched gear's average (no condition report then).
    pub fn without_condition(mut self) -> Self {
        self.watched = None;
        self
    }

    /// Room for a window of `samples` samples, so that its torques are stored without
    /// growing ([`GearCondition::reserve`]).
    pub fn reserve(&mut self, samples: usize) {
        self.judged_torque.reserve(samples);
        if self.watched.is_some() {
            self.condition.reserve(samples);
        }
    }

    /// Adds a block of the window.
    pub fn add(&mut self, block: &NetworkBlock) {
        if self.start_s.is_none() {
            self.start_s = block.time_s.first().copied();
        }
        self.samples += block.len();
        for (sum, column) in self.speed_sum.iter_mut().zip(&block.speed_rad_s) {
            *sum += column.iter().sum::<f64>();
        }
        for (sums, column) in self.torque.iter_mut().zip(&block.shaft_torque_nm) {
            sums.0 += column.iter().sum::<f64>();
            sums.1 += column.iter().map(|t| t * t).sum::<f64>();
        }
        for (count, column) in self.apart.iter_mut().zip(&block.contact) {
            *count += column.iter().filter(|&&c| c == 0).count();
        }
        self.motor_sum += block.motor_torque_nm.iter().sum::<f64>();
        if let Some(column) = block.shaft_torque_nm.get(self.judged) {
            self.judged_torque.extend_from_slice(column);
            if let Some((gear, _)) = self.watched {
                let sensed = self
                    .sensor
                    .as_ref()
                    .and_then(|(rig, k)| rig::column(rig, block, *k));
                let averaged = sensed.as_deref().unwrap_or(column);
                self.condition
                    .add_samples(&block.time_s, &block.angle_rad[gear], averaged);
            }
        }
    }

    /// The judged shaft's torque at each of `revolutions_s` (the motor body's whole
    /// revolutions in the window, s) (N m).
    pub fn revolution_torque_nm(&self, revolutions_s: &[f64]) -> Vec<f64> {
        let start_s = self.start_s.unwrap_or(0.0);
        revolutions_s
            .iter()
            .filter_map(|t| {
                let i = ((t - start_s) * self.rate_hz).round() as usize;
                self.judged_torque.get(i).copied()
            })
            .collect()
    }

    /// The window summed up and its motion judged, the motor set to `rpm` (rev/min);
    /// `impacts` and `revolutions_s` those of the window.
    pub fn summary(
        &self,
        rig: &RigTopology,
        rpm: f64,
        impacts: &[NetworkImpact],
        revolutions_s: &[f64],
    ) -> RigPointSummary {
        let n = self.sample_count();
        let revolution_torque_nm = self.revolution_torque_nm(revolutions_s);
        let motion = judge(&JudgeInput {
            torque_nm: &self.judged_torque,
            rate_hz: self.rate_hz,
            running_hz: rpm / 60.0,
            revolution_torque_nm: &revolution_torque_nm,
        });
        let (bodies, shafts, meshes) = (
            self.bodies(rig),
            self.shafts(rig),
            self.meshes(rig, impacts),
        );
        let lists = (&bodies[..], &shafts[..], &meshes[..]);
        let measured_s = self.samples as f64 / self.rate_hz;
        let window = (motion, measured_s, revolutions_s.len());
        let steady = steady_summary(rig, lists, window, self.judged, rpm, impacts);
        RigPointSummary {
            steady,
            motor_torque_mean_nm: self.motor_sum / n,
            judged_shaft: rig
                .shafts
                .get(self.judged)
                .map_or(String::new(), |s| s.name.clone()),
            bodies,
            shafts,
            meshes,
            condition: None,
        }
    }

    /// The window's samples, as the divisor of its means (at least 1).
    fn sample_count(&self) -> f64 {
        self.samples.max(1) as f64
    }

    /// Each body's mean speed over the window.
    fn bodies(&self, rig: &RigTopology) -> Vec<BodySummary> {
        let n = self.sample_count();
        let speeds = rig.bodies.iter().zip(&self.speed_sum);
        speeds
            .map(|(b, sum)| BodySummary {
                name: b.name.clone(),
                speed_mean_rpm: sum / n * 30.0 / PI,
            })
            .collect()
    }

    /// Each shaft's mean torque and its RMS about the mean over the window.
    fn shafts(&self, rig: &RigTopology) -> Vec<ShaftSummary> {
        let n = self.sample_count();
        let torques = rig.shafts.iter().zip(&self.torque);
        torques
            .map(|(s, (sum, squares))| {
                let mean = sum / n;
                ShaftSummary {
                    name: s.name.clone(),
                    torque_mean_nm: mean,
                    torque_ac_rms_nm: (squares / n - mean * mean).max(0.0).sqrt(),
                }
            })
            .collect()
    }

    /// Each mesh's impacts (of `impacts`, the window's) and share of the window apart.
    fn meshes(&self, rig: &RigTopology, impacts: &[NetworkImpact]) -> Vec<MeshSummary> {
        let n = self.sample_count();
        let meshes = rig.meshes.iter().enumerate();
        meshes
            .map(|(i, m)| MeshSummary {
                name: m.name.clone(),
                impacts: impacts.iter().filter(|x| x.mesh == i).count(),
                apart_fraction: self.apart[i] as f64 / n,
            })
            .collect()
    }

    /// The watched gear's synchronous average and its indicators, if taken.
    pub fn condition_report(&self) -> Option<GearConditionReport> {
        let (_, teeth) = self.watched?;
        self.condition.report(teeth as usize)
    }
}

/// A condition report as JSON, its gear and averaged signal named; for a rig with
/// planetary stages, each stage's characteristic lines and the averaged signal's level
/// at each (`chain::stage_lines`), the motor at `rpm`.
pub(super) fn condition_json(
    rig: &RigTopology,
    report: &GearConditionReport,
    window: &RigWindow,
    rpm: f64,
) -> serde_json::Value {
    let mut json = report.to_json();
    if let (Some(map), Some((gear, teeth))) = (json.as_object_mut(), window.watched) {
        map.insert("gear".into(), rig.bodies[gear].name.clone().into());
        map.insert("teeth".into(), teeth.into());
        let signal = match &window.sensor {
            Some((_, k)) => rig::column_names(rig)[*k].clone(),
            None => rig
                .shafts
                .get(window.judged)
                .map_or(String::new(), |s| format!("torque_{}_nm", s.name)),
        };
        map.insert("signal".into(), signal.into());
        if !rig.planetary.is_empty() {
            let stages: Vec<serde_json::Value> = stage_lines(rig, rpm)
                .iter()
                .map(|s| s.to_json(|hz| window.condition.line_amplitude(hz)))
                .collect();
            map.insert("planetary".into(), stages.into());
        }
    }
    json
}
