//! One FMU instance in safe Rust: FMI 3.0's co-simulation states (instantiated,
//! initialization, step, terminated), the variables' values, and the plant of its rig
//! (`rig::NetworkPlant`) started at rest and advanced exactly over each communication
//! step with the inputs held. The C functions (`ffi.rs`) only translate to and from it.

use rig::{
    LiveCeiling, NetworkBlock, NetworkPlant, NetworkStart, RigTopology, Schedule, SetPoints, Track,
};

use crate::error::FmuError;
use crate::variables::{Causality, Kind, Role, SAMPLE_RATE_HZ, SetPoint, Variable, variables};

/// Most samples run into one scratch block.
const CHUNK: usize = 4096;

/// How far (in samples) a communication point may sit from the plant's sample grid.
const GRID_TOLERANCE: f64 = 1e-6;

/// Where the instance is in FMI 3.0's state machine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase {
    /// After instantiation or reset: parameters and inputs may be set.
    Instantiated,
    /// Between `fmi3EnterInitializationMode` and `fmi3ExitInitializationMode`.
    Initialization,
    /// Communication steps.
    Step,
    /// After `fmi3Terminate`: values may be read.
    Terminated,
    /// A step failed: only reset or free.
    Failed,
}

/// An FMU instance of one rig.
#[derive(Clone, Debug)]
pub struct Instance {
    rig: RigTopology,
    variables: Vec<Variable>,
    /// Each variable's value (parameters, inputs; outputs as last computed).
    values: Vec<f64>,
    phase: Phase,
    start_time_s: f64,
    plant: Option<NetworkPlant>,
    inputs_changed: bool,
    block: NetworkBlock,
}

impl Instance {
    /// A fresh instance of `rig` (checked), every variable at its start value.
    pub fn new(rig: RigTopology) -> Result<Self, FmuError> {
        rig.check()?;
        let variables = variables(&rig);
        let values = variables.iter().map(|v| v.start.unwrap_or(0.0)).collect();
        let block = NetworkBlock::new(&rig);
        Ok(Self {
            rig,
            variables,
            values,
            phase: Phase::Instantiated,
            start_time_s: 0.0,
            plant: None,
            inputs_changed: false,
            block,
        })
    }

    /// The variables, indexed by value reference.
    pub fn variables(&self) -> &[Variable] {
        &self.variables
    }

    /// Where it is in the state machine.
    pub fn phase(&self) -> Phase {
        self.phase
    }

    /// Back to the state after instantiation: start values, no plant.
    pub fn reset(&mut self) {
        if let Ok(fresh) = Self::new(self.rig.clone()) {
            *self = fresh;
        }
    }

    /// After an internal fault: nothing but reset or free.
    pub fn fail(&mut self) {
        self.phase = Phase::Failed;
    }

    /// Impacts of every mesh since the start.
    pub fn impact_total(&self) -> f64 {
        self.variables
            .iter()
            .zip(&self.values)
            .filter(|(v, _)| matches!(v.role, Role::Impacts(_)))
            .map(|(_, x)| x)
            .sum()
    }

    /// `fmi3EnterInitializationMode` at `start_time_s`.
    pub fn enter_initialization(&mut self, start_time_s: f64) -> Result<(), FmuError> {
        self.expect(&[Phase::Instantiated], "fmi3EnterInitializationMode")?;
        if !start_time_s.is_finite() {
            return Err(FmuError(format!("start time {start_time_s} is not finite")));
        }
        self.start_time_s = start_time_s;
        self.phase = Phase::Initialization;
        Ok(())
    }

    /// `fmi3ExitInitializationMode`: the plant built at rest with the parameters set.
    pub fn exit_initialization(&mut self) -> Result<(), FmuError> {
        self.expect(&[Phase::Initialization], "fmi3ExitInitializationMode")?;
        self.ensure_plant()?;
        self.phase = Phase::Step;
        Ok(())
    }

    /// `fmi3Terminate`.
    pub fn terminate(&mut self) -> Result<(), FmuError> {
        self.expect(&[Phase::Initialization, Phase::Step], "fmi3Terminate")?;
        self.phase = Phase::Terminated;
        Ok(())
    }

    /// The current time (s).
    pub fn time_s(&self) -> f64 {
        let plant = self.plant.as_ref().map_or(0.0, |p| p.time_s());
        self.start_time_s + plant
    }

    /// Sets a Float64 parameter (before the end of initialization) or input.
    pub fn set_float64(&mut self, vr: u32, value: f64) -> Result<(), FmuError> {
        let v = self.variable(vr, Kind::Float64)?.clone();
        match v.causality {
            Causality::Parameter => {
                self.expect(
                    &[Phase::Instantiated, Phase::Initialization],
                    &format!("setting parameter {}", v.name),
                )?;
                self.check_range(&v, value)?;
                if let Role::Field(path) = &v.role {
                    let mut rig = self.rig.clone();
                    rig.set_field(path, value)?;
                }
                self.plant = None;
            }
            Causality::Input => {
                self.expect(
                    &[Phase::Instantiated, Phase::Initialization, Phase::Step],
                    &format!("setting input {}", v.name),
                )?;
                self.check_range(&v, value)?;
                self.check_input(&v, value)?;
                if self.phase == Phase::Step {
                    self.inputs_changed = true;
                } else {
                    self.plant = None;
                }
            }
            _ => {
                return Err(FmuError(format!(
                    "{} is an output: it cannot be set",
                    v.name
                )));
            }
        }
        self.values[vr as usize] = value;
        Ok(())
    }

    /// A Float64 variable's value.
    pub fn get_float64(&mut self, vr: u32) -> Result<f64, FmuError> {
        self.variable(vr, Kind::Float64)?;
        self.value(vr)
    }

    /// An Int32 variable's value (a contact state).
    pub fn get_int32(&mut self, vr: u32) -> Result<i32, FmuError> {
        self.variable(vr, Kind::Int32)?;
        Ok(self.value(vr)? as i32)
    }

    /// An Int64 variable's value (a count).
    pub fn get_int64(&mut self, vr: u32) -> Result<i64, FmuError> {
        self.variable(vr, Kind::Int64)?;
        Ok(self.value(vr)? as i64)
    }

    /// `fmi3DoStep`: advances from `current_s` by `step_s`, the inputs held; the step must
    /// start at the instance's time and span a whole number of its samples.
    pub fn do_step(&mut self, current_s: f64, step_s: f64) -> Result<(), FmuError> {
        self.expect(&[Phase::Step], "fmi3DoStep")?;
        let samples = self.samples_of(current_s, step_s)?;
        if self.inputs_changed {
            let set = self.set_points();
            self.plant_mut()?.hold_set_points(set)?;
            self.inputs_changed = false;
        }
        if let Err(e) = self.run(samples) {
            self.phase = Phase::Failed;
            return Err(e);
        }
        self.refresh_outputs()
    }

    /// Samples in a step from `current_s` by `step_s`, checked against the grid.
    fn samples_of(&self, current_s: f64, step_s: f64) -> Result<usize, FmuError> {
        let now = self.time_s();
        let offset = (current_s - now) * SAMPLE_RATE_HZ;
        if offset.is_nan() || offset.abs() > GRID_TOLERANCE {
            return Err(FmuError(format!(
                "fmi3DoStep at {current_s} s: the FMU is at {now} s (a step starts where the last ended)"
            )));
        }
        let samples = step_s * SAMPLE_RATE_HZ;
        let whole = samples.round();
        let on_grid = (samples - whole).abs() <= GRID_TOLERANCE * whole.max(1.0);
        if !on_grid || step_s.is_nan() || step_s <= 0.0 || whole < 1.0 {
            return Err(FmuError(format!(
                "communication step {step_s} s: it must be a positive whole number of the FMU's {} s samples",
                1.0 / SAMPLE_RATE_HZ
            )));
        }
        if whole > 1e9 {
            return Err(FmuError(format!(
                "communication step {step_s} s: at most 1e5 s a step"
            )));
        }
        Ok(whole as usize)
    }

    /// Runs `samples` samples, counting each mesh's impacts.
    fn run(&mut self, samples: usize) -> Result<(), FmuError> {
        let mut left = samples;
        while left > 0 {
            let n = left.min(CHUNK);
            self.block.clear();
            let plant = self.plant.as_mut().ok_or_else(no_plant)?;
            plant.run(n, &mut self.block)?;
            let impacts = plant.take_impacts();
            plant.take_revolutions();
            for impact in impacts {
                let vr = self.impacts_vr(impact.mesh);
                self.values[vr] += 1.0;
            }
            left -= n;
        }
        Ok(())
    }

    fn impacts_vr(&self, mesh: usize) -> usize {
        self.variables
            .iter()
            .position(|v| v.role == Role::Impacts(mesh))
            .expect("every mesh has an impact count")
    }

    /// A variable's value, outputs computed (the plant built in initialization).
    fn value(&mut self, vr: u32) -> Result<f64, FmuError> {
        let v = &self.variables[vr as usize];
        match v.role {
            Role::Time => Ok(self.time_s()),
            Role::Column(_) | Role::Impacts(_) => {
                if self.phase == Phase::Instantiated {
                    return Err(FmuError(format!(
                        "output {} is known from fmi3EnterInitializationMode on",
                        v.name
                    )));
                }
                if self.plant.is_none() {
                    self.ensure_plant()?;
                }
                Ok(self.values[vr as usize])
            }
            _ => Ok(self.values[vr as usize]),
        }
    }

    /// Builds the plant at rest from the parameters and inputs set, if not built.
    fn ensure_plant(&mut self) -> Result<(), FmuError> {
        if self.plant.is_some() {
            return Ok(());
        }
        let rig = self.rig_with_parameters()?;
        let set = self.set_points();
        if let Some(limit) = rig.drive.limit_nm() {
            check_load_within(set.load_nm, limit)?;
        }
        let schedule = Schedule {
            speed_rpm: Track::hold(set.speed_rpm),
            load_nm: Track::hold(set.load_nm),
            oscillating_load_nm: Track::hold(set.oscillating_load_nm),
            oscillating_load_hz: Track::hold(set.oscillating_load_hz),
        };
        // The oscillating load's frequency is held to its variable's range.
        let ceiling = LiveCeiling {
            speed_rpm: self.role_value(&Role::SpeedCeiling),
            oscillating_load_hz: f64::INFINITY,
        };
        let plant =
            NetworkPlant::live(&rig, schedule, SAMPLE_RATE_HZ, NetworkStart::Rest, ceiling)?;
        self.plant = Some(plant);
        self.inputs_changed = false;
        for (index, v) in self.variables.iter().enumerate() {
            if matches!(v.role, Role::Impacts(_)) {
                self.values[index] = 0.0;
            }
        }
        self.refresh_outputs()
    }

    /// The rig with every parameter's value, checked.
    fn rig_with_parameters(&self) -> Result<RigTopology, FmuError> {
        let mut rig = self.rig.clone();
        for (v, value) in self.variables.iter().zip(&self.values) {
            if let Role::Field(path) = &v.role {
                rig.set_field(path, *value)?;
            }
        }
        rig.check()?;
        Ok(rig)
    }

    /// Sets the column outputs from the plant's current sample.
    fn refresh_outputs(&mut self) -> Result<(), FmuError> {
        self.block.clear();
        let plant = self.plant.as_mut().ok_or_else(no_plant)?;
        plant.sample_now(&mut self.block);
        let columns = rig::columns(&self.rig, &self.block);
        for (index, v) in self.variables.iter().enumerate() {
            if let Role::Column(c) = v.role {
                self.values[index] = columns[c][0];
            }
        }
        Ok(())
    }

    fn set_points(&self) -> SetPoints {
        SetPoints {
            speed_rpm: self.role_value(&Role::Input(SetPoint::SpeedRpm)),
            load_nm: self.role_value(&Role::Input(SetPoint::LoadNm)),
            oscillating_load_nm: self.role_value(&Role::Input(SetPoint::OscillatingLoadNm)),
            oscillating_load_hz: self.role_value(&Role::Input(SetPoint::OscillatingLoadHz)),
        }
    }

    fn role_value(&self, role: &Role) -> f64 {
        self.variables
            .iter()
            .position(|v| &v.role == role)
            .map_or(0.0, |i| self.values[i])
    }

    fn plant_mut(&mut self) -> Result<&mut NetworkPlant, FmuError> {
        self.plant.as_mut().ok_or_else(no_plant)
    }

    /// The variable `vr`, which must be of `kind`.
    fn variable(&self, vr: u32, kind: Kind) -> Result<&Variable, FmuError> {
        let v = self.variables.get(vr as usize).ok_or_else(|| {
            FmuError(format!(
                "no variable has value reference {vr} (there are {})",
                self.variables.len()
            ))
        })?;
        if v.kind != kind {
            return Err(FmuError(format!(
                "{} (value reference {vr}) is {:?}, not {kind:?}",
                v.name, v.kind
            )));
        }
        Ok(v)
    }

    fn check_range(&self, v: &Variable, value: f64) -> Result<(), FmuError> {
        let (min, max) = v.range;
        let low = min.is_some_and(|m| value < m);
        let high = max.is_some_and(|m| value > m);
        if !value.is_finite() || low || high {
            let bound = |b: Option<f64>| b.map_or("none".to_string(), |x| x.to_string());
            return Err(FmuError(format!(
                "{} = {value}: out of range (min {}, max {}{})",
                v.name,
                bound(min),
                bound(max),
                if v.unit.is_empty() {
                    String::new()
                } else {
                    format!(" {}", v.unit)
                }
            )));
        }
        Ok(())
    }

    /// The checks of a set point beyond its fixed range: the speed ceiling the step was
    /// sized for, a load the motor's torque limit can carry.
    fn check_input(&self, v: &Variable, value: f64) -> Result<(), FmuError> {
        match v.role {
            Role::Input(SetPoint::SpeedRpm) => {
                let ceiling = self.role_value(&Role::SpeedCeiling);
                if value > ceiling {
                    return Err(FmuError(format!(
                        "set_speed_rpm = {value}: above speed_ceiling_rpm = {ceiling} (set that parameter higher before initialization)"
                    )));
                }
                Ok(())
            }
            Role::Input(SetPoint::LoadNm) => match self.rig_with_parameters()?.drive.limit_nm() {
                Some(limit) => check_load_within(value, limit),
                None => Ok(()),
            },
            _ => Ok(()),
        }
    }

    fn expect(&self, phases: &[Phase], what: &str) -> Result<(), FmuError> {
        if phases.contains(&self.phase) {
            return Ok(());
        }
        Err(FmuError(format!(
            "{what} is not allowed in the {:?} state (allowed in: {phases:?})",
            self.phase
        )))
    }
}

fn check_load_within(load_nm: f64, limit_nm: f64) -> Result<(), FmuError> {
    if load_nm > limit_nm {
        return Err(FmuError(format!(
            "load_nm = {load_nm}: above the motor's torque limit {limit_nm} N m, which could not hold any speed against it"
        )));
    }
    Ok(())
}

fn no_plant() -> FmuError {
    FmuError("the plant is not built: call fmi3EnterInitializationMode first".into())
}
