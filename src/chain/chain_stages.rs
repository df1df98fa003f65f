//! The chain as a list of described stages: each names its output and the signals it
//! reads. The list is put in an order where every input is produced before it is read,
//! and built into running stages; the scenario check, `testrig run` and the sweeps'
//! inline chain all build it here.

use instruments::{InstrumentError, ShaftStrain};

use super::instrument::Instrument;
use super::stage_plan::{NamedStage, StagePlan};
use crate::vocabulary::frame::SignalNames;
use crate::vocabulary::signal_names::{plant_full_scale, plant_unit};

/// Why a chain cannot be wired or built; each names the stage by its output.
#[derive(Debug, thiserror::Error)]
pub enum WiringError {
    /// An input no plant signal or stage provides (or only a stage that depends on this).
    #[error("`{output}` reads `{input}`, which is not a signal before it; known: {known}")]
    UnknownInput {
        /// The stage's output.
        output: String,
        /// The input not found.
        input: String,
        /// The signals there are.
        known: String,
    },
    /// Two stages, or a stage and a plant signal, with one name.
    #[error("`{output}` is already a signal of the run; give the stage another name")]
    DuplicateOutput {
        /// The name.
        output: String,
    },
    /// The instrument refuses its settings on this stream.
    #[error("{source}")]
    Instrument {
        /// The stage's output.
        output: String,
        /// What it said.
        source: InstrumentError,
    },
}

impl WiringError {
    /// The output of the stage at fault.
    pub fn output(&self) -> &str {
        match self {
            Self::UnknownInput { output, .. }
            | Self::DuplicateOutput { output }
            | Self::Instrument { output, .. } => output,
        }
    }
}

/// The stages in running order (every input before it is read).
#[derive(Clone, Debug, Default)]
pub struct ChainStages(Vec<StagePlan>);

impl ChainStages {
    /// Puts `stages` in running order: stages keep their given order except where one
    /// reads a later one's output. Every input must be a plant signal or another stage's
    /// output, and every output a new name.
    pub fn ordered(stages: Vec<StagePlan>) -> Result<Self, WiringError> {
        Self::ordered_on(stages, &SignalNames::plant())
    }

    /// As [`Self::ordered`], on the signals `sources` instead of the plant's (a chain
    /// on a recording's channels).
    pub fn ordered_on(stages: Vec<StagePlan>, sources: &SignalNames) -> Result<Self, WiringError> {
        let mut known = sources.clone();
        for s in &stages {
            if known.index(&s.output).is_some() {
                return Err(WiringError::DuplicateOutput {
                    output: s.output.clone(),
                });
            }
            known.push(&s.output);
        }
        let mut available = sources.clone();
        let mut pending = stages;
        let mut ordered = Vec::with_capacity(pending.len());
        while !pending.is_empty() {
            let ready = pending
                .iter()
                .position(|s| s.inputs.iter().all(|i| available.index(i).is_some()));
            let Some(ready) = ready else {
                return Err(unresolved(&pending, &available));
            };
            let stage = pending.remove(ready);
            available.push(&stage.output);
            ordered.push(stage);
        }
        Ok(Self(ordered))
    }

    /// The stages in running order.
    pub fn stages(&self) -> &[StagePlan] {
        &self.0
    }

    /// The stage writing `name`.
    pub fn producing(&self, name: &str) -> Option<&StagePlan> {
        self.0.iter().find(|s| s.output == name)
    }

    /// Unit of signal `name`, a plant signal or a stage's output (a filter's, its
    /// input's).
    pub fn unit_of(&self, name: &str) -> Option<&'static str> {
        match self.unit_setter(name) {
            (_, Some(s)) => Some(s.instrument.unit()),
            (plant, None) => plant_unit(plant),
        }
    }

    /// Full scale of signal `name` for integer recordings (in its unit; a filter's, its
    /// input's).
    pub fn full_scale_of(&self, name: &str) -> Option<f64> {
        match self.unit_setter(name) {
            (_, Some(s)) => Some(s.instrument.full_scale()),
            (plant, None) => plant_unit(plant).map(plant_full_scale),
        }
    }

    /// What sets the unit of signal `name`: back through the stages that keep their
    /// input's ([`Instrument::keeps_unit`]) to the first that writes its own (the signal
    /// it writes and the stage), or to a plant signal (its name and `None`).
    fn unit_setter<'a>(&'a self, name: &'a str) -> (&'a str, Option<&'a StagePlan>) {
        match self.producing(name) {
            Some(s) if s.instrument.keeps_unit() => self.unit_setter(&s.inputs[0]),
            stage => (name, stage),
        }
    }

    /// Every signal of a run on the plant signals `plant`, then the stages' outputs.
    pub fn signal_names_on(&self, plant: &SignalNames) -> SignalNames {
        let mut names = plant.clone();
        for output in self.outputs() {
            names.push(output);
        }
        names
    }

    /// The stages' outputs, in running order.
    pub fn outputs(&self) -> impl Iterator<Item = &str> {
        self.0.iter().map(|s| s.output.as_str())
    }

    /// These stages with every strain stage on `shaft` (a rig file's gauged shaft).
    pub fn with_gauged_shaft(&self, shaft: ShaftStrain) -> Self {
        let mut stages = self.clone();
        for s in &mut stages.0 {
            if let Instrument::Strain(gauged) = &mut s.instrument {
                *gauged = shaft;
            }
        }
        stages
    }

    /// Gives every seeded instrument `seed`.
    pub fn reseed(&mut self, seed: u64) {
        for s in &mut self.0 {
            s.instrument.reseed(seed);
        }
    }

    /// Builds the stages on a stream at `rate_hz`; `names` holds the plant's channels on
    /// entry and every stage's output on return.
    pub fn build(
        &self,
        rate_hz: f64,
        names: &mut SignalNames,
    ) -> Result<Vec<NamedStage>, WiringError> {
        let mut built = Vec::with_capacity(self.0.len());
        for s in &self.0 {
            let inputs: Vec<usize> = s.inputs.iter().filter_map(|n| names.index(n)).collect();
            if inputs.len() != s.instrument.input_count() {
                return Err(unresolved(std::slice::from_ref(s), names));
            }
            let stage =
                s.instrument
                    .build(rate_hz, &inputs)
                    .map_err(|source| WiringError::Instrument {
                        output: s.output.clone(),
                        source,
                    })?;
            names.push(&s.output);
            built.push(NamedStage {
                output: s.output.clone(),
                stage,
                plan: s.clone(),
                inputs,
                rate_hz,
            });
        }
        Ok(built)
    }
}

fn unresolved(pending: &[StagePlan], available: &SignalNames) -> WiringError {
    let s = &pending[0];
    let input = s
        .inputs
        .iter()
        .find(|i| available.index(i).is_none())
        .cloned()
        .unwrap_or_else(|| format!("{} inputs", s.instrument.input_count()));
    WiringError::UnknownInput {
        output: s.output.clone(),
        input,
        known: available.names().join(", "),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chain::Instrument;

    /// A force sensor's signal through an AC coupling and a low-pass stays in newtons, at
    /// the plant's full scale for forces; an instrument of its own unit writes volts.
    #[test]
    fn filters_keep_their_inputs_unit_and_full_scale() {
        let stage = |output: &str, input: &str, instrument| StagePlan {
            output: output.into(),
            inputs: vec![input.into()],
            instrument,
        };
        let sources = SignalNames::of(&["time_s", "sensor_epi_n"]);
        let chain = ChainStages::ordered_on(
            vec![
                stage("ring_ac_n", "sensor_epi_n", Instrument::AcCoupling(1.0)),
                stage("ring_n", "ring_ac_n", Instrument::LowPass(None)),
                stage("ring_tacho_v", "ring_n", Instrument::Tacho),
            ],
            &sources,
        )
        .expect("wired");
        assert_eq!(chain.unit_of("ring_n"), Some("N"));
        assert_eq!(chain.full_scale_of("ring_n"), Some(plant_full_scale("N")));
        assert_eq!(chain.unit_of("ring_tacho_v"), Some("V"));
    }
}
