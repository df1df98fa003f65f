//! A sampled signal through the anti-alias filter, the ADC and the Fourier analyser, with
//! the ground truth of which displayed lines are aliases: the one path of `testrig
//! analyse` and of the Python package's `testrig.analyse`.

use anyhow::Context;
use instruments::{Line, LowPassSpec};

use super::analyser_setup::AnalyserSetup;
use super::chain_stages::ChainStages;
use super::inline::InlineChain;
use super::instrument::Instrument;
use super::stage_plan::StagePlan;
use crate::vocabulary::FILTER_V;
use crate::vocabulary::{Frame, SignalNames};

/// Name of the input channel as the filter stage reads it.
const INPUT: &str = "input";

/// An averaged spectrum with its alias truth.
#[derive(Clone, Debug)]
pub struct AnalysedSpectrum {
    /// The displayed lines (Hz; the input's unit squared).
    pub lines: Vec<Line>,
    /// For each line, the true frequency (Hz) it is an alias of, where it is one.
    pub alias_of: Vec<Option<f64>>,
    /// Spectra averaged.
    pub averages: usize,
    /// ADC samples clipped at its range.
    pub adc_overloads: u64,
    /// The ADC's quantisation noise in one line (the input's unit squared).
    pub floor: f64,
}

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
    let frame = InlineChain::new(stages).process(Frame::of_channels(vec![samples.to_vec()]));
    Ok(frame.channels[1].to_vec())
}

/// The analogue signal `analogue` sampled by the set-up ADC and averaged by its analyser;
/// `None` when it holds less than one block.
pub fn analyse_analogue(setup: &mut AnalyserSetup, analogue: &[f64]) -> Option<AnalysedSpectrum> {
    let ratio = setup.adc_settings.ratio;
    let mut samples = Vec::with_capacity((analogue.len() as f64 / ratio) as usize + 1);
    setup.adc.convert(analogue, &mut samples);
    analyse_samples(setup, analogue, &samples)
}

/// As [`analyse_analogue`], the ADC's `samples` of `analogue` already taken.
pub fn analyse_samples(
    setup: &mut AnalyserSetup,
    analogue: &[f64],
    samples: &[f64],
) -> Option<AnalysedSpectrum> {
    let settings = setup.settings;
    setup.analyser.push(samples);
    let averages = setup.analyser.average_count();
    if averages == 0 {
        return None;
    }
    setup.truth.add_blocks(analogue, averages, settings.hop());
    let lines = setup.analyser.display();
    let floor = setup
        .adc
        .quantisation_line_power(setup.analyser.enbw_hz(), settings.sample_rate_hz());
    let alias_of = setup.truth.flags(lines.len(), floor);
    Some(AnalysedSpectrum {
        lines,
        alias_of,
        averages,
        adc_overloads: setup.adc.overloads(),
        floor,
    })
}
