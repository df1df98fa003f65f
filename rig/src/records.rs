//! What the plant logs beside the sampled signals: impacts and once-per-revolution samples.

/// Which flank took an impact.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Flank {
    /// d ≤ −B: the flank that carries a positive load (thesis "left").
    Drive,
    /// d ≥ B: the back flank (thesis "right").
    Back,
}

impl Flank {
    /// +1 for the drive flank, −1 for the back flank: the sign of the torque it transmits.
    pub fn sign(self) -> f64 {
        match self {
            Flank::Drive => 1.0,
            Flank::Back => -1.0,
        }
    }
}

/// One contact start.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Impact {
    /// Exact time of the contact start (s).
    pub time_s: f64,
    /// Flank that closed.
    pub flank: Flank,
    /// Tooth of the driving gear in mesh, 0..teeth.
    pub tooth: u32,
    /// Rate at which the gap closed (rad/s of relative rotation).
    pub closing_speed_rad_s: f64,
}

/// The state sampled as the driving gear passes a whole revolution (a Poincaré section).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RevolutionSample {
    /// Exact time of the crossing (s).
    pub time_s: f64,
    /// X1..X5 (rad) and V1..V5 (rad/s) relative to the set rotation.
    pub state: [f64; 10],
    /// Intermediate-shaft torque (N m).
    pub shaft_torque_nm: f64,
}
