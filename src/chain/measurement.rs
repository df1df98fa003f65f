//! One measurement of the analyser: an analogue stream sampled by the ADC and averaged
//! into a spectrum, with the alias truth from the analogue blocks behind the averages.
//! The one driver of ADC → analyser: the run's analyser sink, the sweeps' cases,
//! `testrig analyse` and Python's `analyse` all measure through it.

use instruments::Line;

use super::analyser_setup::AnalyserSetup;

/// Whether a measurement keeps its analogue blocks to tell which lines are aliases.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Truth {
    /// Kept: every line's alias truth is known (costs the analogue samples' memory).
    Kept,
    /// Not kept: no line is flagged (a sweep's case reads only the heights of lines).
    NotKept,
}

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

/// A measurement under way: the set-up analyser, ADC and truth, and what they were fed.
pub struct Measurement {
    /// The analyser, ADC and alias truth at work.
    pub setup: AnalyserSetup,
    truth: Truth,
    analogue: Vec<f64>,
    adc_out: Vec<f64>,
}

impl Measurement {
    /// A fresh measurement on `setup`, keeping the analogue blocks as `truth` says.
    pub fn new(setup: AnalyserSetup, truth: Truth) -> Self {
        Self {
            setup,
            truth,
            analogue: Vec::new(),
            adc_out: Vec::new(),
        }
    }

    /// Feeds `analogue` (samples at the stream's rate) through the ADC into the analyser.
    pub fn push(&mut self, analogue: &[f64]) {
        if self.truth == Truth::Kept {
            self.analogue.extend_from_slice(analogue);
        }
        self.adc_out.clear();
        self.setup.adc.convert(analogue, &mut self.adc_out);
        self.setup.analyser.push(&self.adc_out);
    }

    /// Starts afresh: a new average, the ADC's state and count of overloads reset.
    pub fn restart(&mut self) {
        self.setup.adc.reset();
        self.setup.analyser.restart();
        self.setup.truth.restart();
        self.analogue.clear();
    }

    /// Spectra averaged so far.
    pub fn average_count(&self) -> usize {
        self.setup.analyser.average_count()
    }

    /// Whether every average asked for is in.
    pub fn is_complete(&self) -> bool {
        self.setup.analyser.is_complete()
    }

    /// ADC samples clipped at its range since the last restart.
    pub fn overloads(&self) -> u64 {
        self.setup.adc.overloads()
    }

    /// The chain's own noise floor per displayed line (the input's unit squared): the
    /// ADC's quantisation noise through the window. No line below it can be told from
    /// the converter.
    pub fn floor(&self) -> f64 {
        self.setup.adc.quantisation_line_power(
            self.setup.analyser.enbw_hz(),
            self.setup.settings.sample_rate_hz(),
        )
    }

    /// The display's lines and, for each, the alias truth from the blocks averaged (none
    /// flagged without [`Truth::Kept`]). The truth takes only the blocks it lacks, so a
    /// live display asked for after every block does not redo it.
    pub fn lines_and_truth(&mut self) -> (Vec<Line>, Vec<Option<f64>>) {
        let lines = self.setup.analyser.display();
        if self.truth == Truth::NotKept {
            return (lines.clone(), vec![None; lines.len()]);
        }
        let count = self.average_count();
        self.setup
            .truth
            .add_blocks(&self.analogue, count, self.setup.settings.hop());
        let alias_of = self.setup.truth.flags(lines.len(), self.floor());
        (lines, alias_of)
    }

    /// The averaged spectrum so far; `None` before the first block is in.
    pub fn spectrum(&mut self) -> Option<AnalysedSpectrum> {
        let averages = self.average_count();
        if averages == 0 {
            return None;
        }
        let (lines, alias_of) = self.lines_and_truth();
        Some(AnalysedSpectrum {
            lines,
            alias_of,
            averages,
            adc_overloads: self.overloads(),
            floor: self.floor(),
        })
    }
}
