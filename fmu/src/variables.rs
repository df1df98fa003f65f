//! The FMU's variables, numbered from its rig: time; every number of the rig by its path
//! (`testrig params --rig`) and the set-speed ceiling as parameters; the motor's set
//! speed, the brake's load and the oscillating load as inputs; every signal column of
//! `testrig simulate --rig` (`rig::column_specs`, time aside) and each mesh's impact
//! count as outputs. The model description and the instance both build this list from
//! the same rig, so value references agree.

use rig::RigTopology;

/// Rate of the plant's samples inside the FMU (Hz): a communication step is a whole
/// number of them.
pub const SAMPLE_RATE_HZ: f64 = 10_000.0;

/// Highest set speed the internal step is sized for unless the importer sets
/// `speed_ceiling_rpm` (rev/min).
pub const DEFAULT_SPEED_CEILING_RPM: f64 = 3_000.0;

/// Highest set speed any rig accepts (rev/min).
pub const MAX_SPEED_RPM: f64 = rig::MAX_SPEED_RPM;

/// Highest oscillating-load frequency accepted (Hz), as the live panel's.
pub const MAX_OSCILLATING_HZ: f64 = 200.0;

/// A variable's FMI type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// fmi3Float64.
    Float64,
    /// fmi3Int32 (a contact state).
    Int32,
    /// fmi3Int64 (a count).
    Int64,
}

/// A variable's causality.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Causality {
    /// The independent variable, time.
    Independent,
    /// Set before initialization, fixed after.
    Parameter,
    /// Set by the importer, held over each communication step.
    Input,
    /// Computed by the FMU.
    Output,
}

/// One of the four set points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SetPoint {
    /// The motor's set speed (rev/min).
    SpeedRpm,
    /// The brake's load (N m).
    LoadNm,
    /// The oscillating load's amplitude (N m).
    OscillatingLoadNm,
    /// The oscillating load's frequency (Hz).
    OscillatingLoadHz,
}

/// What a variable stands for in the instance.
#[derive(Clone, Debug, PartialEq)]
pub enum Role {
    /// Time (s).
    Time,
    /// A number of the rig by its path.
    Field(String),
    /// The set-speed ceiling the internal step is sized for (rev/min).
    SpeedCeiling,
    /// A set point.
    Input(SetPoint),
    /// Column `index` of `rig::columns`.
    Column(usize),
    /// Impacts of mesh `index` since the start.
    Impacts(usize),
}

/// One variable of the model description.
#[derive(Clone, Debug, PartialEq)]
pub struct Variable {
    /// Its name.
    pub name: String,
    /// Its value reference.
    pub value_reference: u32,
    /// Its type.
    pub kind: Kind,
    /// Its causality.
    pub causality: Causality,
    /// What it stands for.
    pub role: Role,
    /// Its unit (empty: none).
    pub unit: &'static str,
    /// Its start value (parameters and inputs).
    pub start: Option<f64>,
    /// Its least and greatest values where bounded.
    pub range: (Option<f64>, Option<f64>),
    /// What it is.
    pub description: String,
}

impl Variable {
    fn new(name: impl Into<String>, kind: Kind, causality: Causality, role: Role) -> Self {
        Self {
            name: name.into(),
            value_reference: 0,
            kind,
            causality,
            role,
            unit: "",
            start: None,
            range: (None, None),
            description: String::new(),
        }
    }

    fn unit(mut self, unit: &'static str) -> Self {
        self.unit = unit;
        self
    }

    fn start(mut self, value: f64) -> Self {
        self.start = Some(value);
        self
    }

    fn range(mut self, min: Option<f64>, max: Option<f64>) -> Self {
        self.range = (min, max);
        self
    }

    fn describe(mut self, text: impl Into<String>) -> Self {
        self.description = text.into();
        self
    }
}

/// The FMU's variables for `rig`, value references 0, 1, 2 … in order.
pub fn variables(rig: &RigTopology) -> Vec<Variable> {
    let mut list = vec![
        Variable::new("time", Kind::Float64, Causality::Independent, Role::Time)
            .unit("s")
            .describe("simulation time"),
    ];
    list.extend(parameters(rig));
    list.extend(inputs(rig));
    list.extend(outputs(rig));
    for (index, v) in list.iter_mut().enumerate() {
        v.value_reference = index as u32;
    }
    list
}

fn parameters(rig: &RigTopology) -> Vec<Variable> {
    let mut list: Vec<Variable> = rig
        .fields()
        .into_iter()
        .map(|f| {
            let unit = if f.unit == "1" { "" } else { f.unit };
            Variable::new(
                f.path.clone(),
                Kind::Float64,
                Causality::Parameter,
                Role::Field(f.path),
            )
            .unit(unit)
            .start(f.value)
            .describe(f.meaning)
        })
        .collect();
    list.push(
        Variable::new(
            "speed_ceiling_rpm",
            Kind::Float64,
            Causality::Parameter,
            Role::SpeedCeiling,
        )
        .unit("rev/min")
        .start(DEFAULT_SPEED_CEILING_RPM)
        .range(Some(0.0), Some(MAX_SPEED_RPM))
        .describe(
            "highest set speed the internal step is sized for; a higher set_speed_rpm is refused",
        ),
    );
    list
}

fn inputs(rig: &RigTopology) -> Vec<Variable> {
    let input = |name: &str, set: SetPoint, unit| {
        Variable::new(name, Kind::Float64, Causality::Input, Role::Input(set))
            .unit(unit)
            .start(0.0)
    };
    let load_max = rig.drive.limit_nm();
    vec![
        input("set_speed_rpm", SetPoint::SpeedRpm, "rev/min")
            .range(Some(0.0), Some(MAX_SPEED_RPM))
            .describe("the motor's set speed, held over each communication step (at most speed_ceiling_rpm)"),
        input("load_nm", SetPoint::LoadNm, "N m")
            .range(Some(0.0), load_max)
            .describe("the brake's load, held over each communication step (at most the motor's torque limit)"),
        input("oscillating_load_nm", SetPoint::OscillatingLoadNm, "N m")
            .range(Some(0.0), None)
            .describe("amplitude of the brake's oscillating load"),
        input("oscillating_load_hz", SetPoint::OscillatingLoadHz, "Hz")
            .range(Some(0.0), Some(MAX_OSCILLATING_HZ))
            .describe("frequency of the brake's oscillating load"),
    ]
}

fn outputs(rig: &RigTopology) -> Vec<Variable> {
    let mut list: Vec<Variable> = rig::column_specs(rig)
        .into_iter()
        .enumerate()
        .skip(1)
        .map(|(index, c)| {
            let kind = if c.discrete {
                Kind::Int32
            } else {
                Kind::Float64
            };
            Variable::new(c.name, kind, Causality::Output, Role::Column(index))
                .unit(c.unit)
                .describe(c.meaning)
        })
        .collect();
    for (index, m) in rig.meshes.iter().enumerate() {
        list.push(
            Variable::new(
                format!("impacts_{}", m.name),
                Kind::Int64,
                Causality::Output,
                Role::Impacts(index),
            )
            .describe(format!("mesh {}: impacts since the start", m.name)),
        );
    }
    list
}
