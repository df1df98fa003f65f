//! One stage of the chain as described ([`StagePlan`]: an instrument, what it reads and
//! the signal it writes) and as built and at work ([`NamedStage`]).

use instruments::InstrumentError;

use super::instrument::Instrument;
use super::stage::Stage;

/// One stage: an instrument, what it reads and the signal it writes.
#[derive(Clone, Debug)]
pub struct StagePlan {
    /// Name of the signal it adds.
    pub output: String,
    /// Names of the signals it reads ([`Instrument::input_count`] of them).
    pub inputs: Vec<String>,
    /// The instrument and its settings.
    pub instrument: Instrument,
}

/// A stage with the name of the signal it adds, and what it was built from (so that a
/// command can rebuild it with new settings).
pub struct NamedStage {
    /// Output signal name.
    pub output: String,
    /// The instrument at work.
    pub stage: Box<dyn Stage>,
    /// Its description.
    pub plan: StagePlan,
    /// The channels it reads.
    pub inputs: Vec<usize>,
    /// The stream rate (Hz).
    pub rate_hz: f64,
}

impl NamedStage {
    /// Rebuilds the stage as `instrument` (its state starts afresh); refused, with the
    /// stage unchanged, when the instrument refuses the settings.
    pub fn rebuild(&mut self, instrument: Instrument) -> Result<(), InstrumentError> {
        self.stage = instrument.build(self.rate_hz, &self.inputs)?;
        self.plan.instrument = instrument;
        Ok(())
    }
}
