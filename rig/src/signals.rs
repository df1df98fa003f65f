//! The true signals the instruments measure, a block of samples at the output rate.

/// Columns of true signals, one entry per output sample (struct of arrays).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SignalBlock {
    /// Simulated time (s), t = n / output rate.
    pub time_s: Vec<f64>,
    /// Absolute angles of M1..M5 (rad), mean rotation included.
    pub angle_rad: [Vec<f64>; 5],
    /// Absolute speeds of M1..M5 (rad/s).
    pub speed_rad_s: [Vec<f64>; 5],
    /// Elastic torques of the input, intermediate and final shafts, K·(θi − θj) (N m).
    pub shaft_torque_nm: [Vec<f64>; 3],
    /// Mesh torque on the driven gear F_XT (N m), positive driving it forward.
    pub mesh_torque_nm: Vec<f64>,
    /// Motor torque on M1 (N m).
    pub motor_torque_nm: Vec<f64>,
    /// Contact: +1 drive flank, −1 back flank, 0 no mesh torque.
    pub contact: Vec<i8>,
    /// Tooth of the driving gear in mesh, 0..teeth.
    pub tooth: Vec<u32>,
}

/// The output shaft (intermediate, strain-gauged) in [`SignalBlock::shaft_torque_nm`].
pub const INTERMEDIATE_SHAFT: usize = 1;

/// The driven gear (M3) in [`SignalBlock::angle_rad`] and [`SignalBlock::speed_rad_s`].
pub const DRIVEN_GEAR: usize = 2;

/// Names with units of the columns, in the order [`SignalBlock::row`] gives them.
pub const COLUMN_NAMES: [&str; 18] = [
    "time_s",
    "angle1_rad",
    "angle2_rad",
    "angle3_rad",
    "angle4_rad",
    "angle5_rad",
    "speed1_rad_s",
    "speed2_rad_s",
    "speed3_rad_s",
    "speed4_rad_s",
    "speed5_rad_s",
    "torque_input_shaft_nm",
    "torque_intermediate_shaft_nm",
    "torque_final_shaft_nm",
    "mesh_torque_nm",
    "motor_torque_nm",
    "contact",
    "tooth",
];

/// Units of the columns, in the order of [`COLUMN_NAMES`] ("1": a number without unit).
pub const COLUMN_UNITS: [&str; 18] = [
    "s", "rad", "rad", "rad", "rad", "rad", "rad/s", "rad/s", "rad/s", "rad/s", "rad/s", "N m",
    "N m", "N m", "N m", "N m", "1", "1",
];

impl SignalBlock {
    /// Number of samples held.
    pub fn len(&self) -> usize {
        self.time_s.len()
    }

    /// Whether no sample is held.
    pub fn is_empty(&self) -> bool {
        self.time_s.is_empty()
    }

    /// Empties every column, keeping the allocations.
    pub fn clear(&mut self) {
        self.time_s.clear();
        self.columns_mut().for_each(Vec::clear);
        self.mesh_torque_nm.clear();
        self.motor_torque_nm.clear();
        self.contact.clear();
        self.tooth.clear();
    }

    fn columns_mut(&mut self) -> impl Iterator<Item = &mut Vec<f64>> {
        self.angle_rad
            .iter_mut()
            .chain(self.speed_rad_s.iter_mut())
            .chain(self.shaft_torque_nm.iter_mut())
    }
}
