//! A sampled signal through the anti-alias filter, the ADC and the Fourier analyser, with
//! the ground truth of which displayed lines are aliases: the one path of `testrig
//! analyse` and of the Python package's `testrig.analyse`.

use anyhow::Context;
use instruments::LowPassSpec;

use super::analyser_setup::AnalyserSetup;
use super::chain_stages::ChainStages;
use super::inline::InlineChain;
use super::instrument::Instrument;
use super::measurement::{AnalysedSpectrum, Measurement, Truth};
use super::stage_plan::StagePlan;
use crate::vocabulary::FILTER_V;
use crate::vocabulary::{Frame, SignalNames};

/// Name of the input channel as the filter stage reads it.
const INPUT: &str = "input";

/// `samples` (at `rate_hz`) through the low-pass `spec` (`None`: as they are): a chain
/// of one stage on the signal.
pub fn anti_aliased(
    samples: &[f64],
    rate_hz: f64,
    spec: Option<LowPassSpec>,
) -> anyhow::Result<Vec<f64>> {
    let stage = StagePlan {
        output: FILTER_V.to_string(),
        inputs: vec![INPUT.to_string()],
        instrument: Instrument::LowPass(spec),
    };
    let mut names = SignalNames::of(&[INPUT]);
    let stages = ChainStages::ordered_on(vec![stage], &names)?
        .build(rate_hz, &mut names)
        .context("the anti-alias filter")?;
    let frame = InlineChain::new(stages).process(Frame::of_channels(vec![samples.into()]));
    Ok(frame.channels[1].to_vec())
}

/// The analogue signal `analogue` measured on `setup` (sampled by its ADC, averaged by
/// its analyser, the alias truth kept); `None` when it holds less than one block.
pub fn analyse_analogue(setup: AnalyserSetup, analogue: &[f64]) -> Option<AnalysedSpectrum> {
    let mut measurement = Measurement::new(setup, Truth::Kept);
    measurement.push(analogue);
    measurement.spectrum()
}
