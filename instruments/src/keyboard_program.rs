//! The HP 5451C keyboard program of the thesis's App. E, read from text and run.
//!
//! One keystroke command per line (case-insensitive, `#` starts a comment):
//!
//! | command | effect |
//! |---|---|
//! | `LABEL n` | a jump target |
//! | `CLEAR BLOCK b` | zeroes data block b |
//! | `ANALOG IN CHANNEL c BLOCK b` | takes the next N ADC samples as the working record, to be transformed into block b (one channel here: c = 0) |
//! | `FOURIER TRANSFORM` | windowed transform of the working record |
//! | `POWER SPECTRUM` | adds its power spectrum (2\|X\|²/S1²) to the block named by `ANALOG IN` |
//! | `COUNT LOOP LABEL n TIMES k` | jumps back to label n until this line has been passed k times |
//! | `DIVIDE BLOCK b BY k` | divides block b by k |
//! | `LOG` | takes 10·log10 of the last block used (dB) |
//! | `DISPLAY` | shows the last block used (a display is recorded) |
//! | `END` | stops |
//!
//! App. E as written: LABEL 0, CLEAR BLOCK 1, LABEL 1, ANALOG IN CHANNEL 0 BLOCK 1,
//! FOURIER TRANSFORM, POWER SPECTRUM, COUNT LOOP LABEL 1 TIMES 10, DIVIDE BLOCK 1 BY 10,
//! DISPLAY, LOG, DISPLAY, END: ten linear power-spectrum averages, shown linear then in dB.

use std::collections::HashMap;

use crate::analyser::{AnalyserSettings, Line};
use crate::error::InstrumentError;
use crate::spectrum::{Spectrum, SpectrumEstimator};

/// One keystroke command.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ProgramStep {
    /// `LABEL n`.
    Label(u32),
    /// `CLEAR BLOCK b`.
    Clear(u32),
    /// `ANALOG IN CHANNEL c BLOCK b`.
    AnalogIn {
        /// Input channel.
        channel: u32,
        /// Target block.
        block: u32,
    },
    /// `FOURIER TRANSFORM`.
    Fourier,
    /// `POWER SPECTRUM`.
    PowerSpectrum,
    /// `COUNT LOOP LABEL n TIMES k`.
    CountLoop {
        /// Label to jump back to.
        label: u32,
        /// Passes before falling through.
        times: u32,
    },
    /// `DIVIDE BLOCK b BY k`.
    Divide {
        /// Block.
        block: u32,
        /// Divisor.
        by: f64,
    },
    /// `LOG`.
    Log,
    /// `DISPLAY`.
    Display,
    /// `END`.
    End,
}

/// A parsed program.
#[derive(Clone, Debug, PartialEq)]
pub struct KeyboardProgram {
    commands: Vec<ProgramStep>,
    /// Source line (1-based) of each command, for errors.
    source_lines: Vec<usize>,
}

/// Most commands executed before a program is declared endless.
const STEP_LIMIT: usize = 1_000_000;

impl KeyboardProgram {
    /// Parses program text; an error names the line and what was expected.
    pub fn parse(text: &str) -> Result<Self, InstrumentError> {
        let mut commands = Vec::new();
        let mut source_lines = Vec::new();
        for (index, raw) in text.lines().enumerate() {
            let line = raw.split('#').next().unwrap_or("").trim().to_uppercase();
            if line.is_empty() {
                continue;
            }
            let words: Vec<&str> = line.split_whitespace().collect();
            let command = parse_words(&words).ok_or_else(|| InstrumentError::Program {
                line: index + 1,
                text: raw.trim().to_string(),
            })?;
            commands.push(command);
            source_lines.push(index + 1);
        }
        Ok(Self {
            commands,
            source_lines,
        })
    }

    /// The commands in order.
    pub fn commands(&self) -> &[ProgramStep] {
        &self.commands
    }

    /// Runs the program on ADC `samples` with the analyser's block size, rate and window;
    /// returns every display in order (the displayed lines of the block shown).
    pub fn run(
        &self,
        settings: &AnalyserSettings,
        samples: &[f64],
    ) -> Result<Vec<Vec<Line>>, InstrumentError> {
        let labels = self.labels();
        let mut machine = Machine::new(settings, samples)?;
        let mut pc = 0;
        for _ in 0..STEP_LIMIT {
            let Some(&command) = self.commands.get(pc) else {
                return Ok(machine.displays);
            };
            let line = self.source_lines[pc];
            pc += 1;
            match command {
                ProgramStep::End => return Ok(machine.displays),
                ProgramStep::CountLoop { label, times } => {
                    let count = machine.passes.entry(pc).or_insert(0);
                    *count += 1;
                    if *count < times {
                        pc = *labels.get(&label).ok_or_else(|| {
                            program_error(
                                line,
                                "COUNT LOOP names a label the program does not have",
                            )
                        })?;
                    }
                }
                other => machine.execute(other, line)?,
            }
        }
        Err(program_error(
            self.source_lines.last().copied().unwrap_or(0),
            "the program did not reach END within a million steps",
        ))
    }

    /// Each label's position in the program.
    fn labels(&self) -> HashMap<u32, usize> {
        self.commands
            .iter()
            .enumerate()
            .filter_map(|(i, c)| match c {
                ProgramStep::Label(n) => Some((*n, i)),
                _ => None,
            })
            .collect()
    }
}

/// The analyser's state while a program runs: the data blocks, the record taken, the
/// block a result goes to, and the displays shown so far.
struct Machine<'a> {
    settings: &'a AnalyserSettings,
    samples: &'a [f64],
    estimator: SpectrumEstimator,
    lines: usize,
    blocks: HashMap<u32, Vec<f64>>,
    passes: HashMap<usize, u32>,
    record: Vec<f64>,
    spectrum: Vec<f64>,
    target: u32,
    cursor: usize,
    transformed: bool,
    displays: Vec<Vec<Line>>,
}

impl<'a> Machine<'a> {
    fn new(settings: &'a AnalyserSettings, samples: &'a [f64]) -> Result<Self, InstrumentError> {
        let estimator =
            SpectrumEstimator::new(settings.block, settings.sample_rate_hz(), settings.window)?;
        let lines = estimator.lines();
        Ok(Self {
            settings,
            samples,
            estimator,
            lines,
            blocks: HashMap::new(),
            passes: HashMap::new(),
            record: Vec::new(),
            spectrum: vec![0.0; lines],
            target: 1,
            cursor: 0,
            transformed: false,
            displays: Vec::new(),
        })
    }

    /// The data block `b`, zeroed when first used.
    fn block(&mut self, b: u32) -> &mut Vec<f64> {
        let lines = self.lines;
        self.blocks.entry(b).or_insert_with(|| vec![0.0; lines])
    }

    /// Carries out one step other than the program's flow (END, COUNT LOOP), written at
    /// program line `line`.
    fn execute(&mut self, command: ProgramStep, line: usize) -> Result<(), InstrumentError> {
        match command {
            ProgramStep::Clear(b) => {
                self.blocks.insert(b, vec![0.0; self.lines]);
            }
            ProgramStep::AnalogIn { block, .. } => {
                let end = self.cursor + self.settings.block;
                let Some(taken) = self.samples.get(self.cursor..end) else {
                    return Err(program_error(line, "ANALOG IN ran out of samples"));
                };
                self.record = taken.to_vec();
                self.cursor = end;
                self.target = block;
                self.transformed = false;
            }
            ProgramStep::Fourier => self.transformed = !self.record.is_empty(),
            ProgramStep::PowerSpectrum => {
                if !self.transformed {
                    return Err(program_error(
                        line,
                        "POWER SPECTRUM needs FOURIER TRANSFORM of an ANALOG IN record",
                    ));
                }
                self.estimator
                    .spectrum(&self.record, Spectrum::Power, &mut self.spectrum);
                let spectrum = std::mem::take(&mut self.spectrum);
                let block = self.block(self.target);
                block.iter_mut().zip(&spectrum).for_each(|(b, s)| *b += s);
                self.spectrum = spectrum;
            }
            ProgramStep::Divide { block, by } => {
                self.block(block).iter_mut().for_each(|v| *v /= by);
                self.target = block;
            }
            ProgramStep::Log => {
                let target = self.target;
                self.block(target)
                    .iter_mut()
                    .for_each(|v| *v = 10.0 * v.log10());
            }
            ProgramStep::Display => self.display(),
            ProgramStep::Label(_) | ProgramStep::CountLoop { .. } | ProgramStep::End => {}
        }
        Ok(())
    }

    /// Shows the target block: its displayed lines.
    fn display(&mut self) {
        let block = self
            .blocks
            .get(&self.target)
            .cloned()
            .unwrap_or_else(|| vec![0.0; self.lines]);
        let df = self.estimator.resolution_hz();
        self.displays.push(
            (0..self.settings.displayed_lines().min(self.lines))
                .map(|k| Line {
                    frequency_hz: k as f64 * df,
                    value: block[k],
                })
                .collect(),
        );
    }
}

fn program_error(line: usize, text: &str) -> InstrumentError {
    InstrumentError::Program {
        line,
        text: text.to_string(),
    }
}

fn parse_words(words: &[&str]) -> Option<ProgramStep> {
    let number = |w: &str| w.parse::<u32>().ok();
    Some(match words {
        ["LABEL", n] => ProgramStep::Label(number(n)?),
        ["CLEAR", "BLOCK", b] => ProgramStep::Clear(number(b)?),
        ["ANALOG", "IN", "CHANNEL", c, "BLOCK", b] => ProgramStep::AnalogIn {
            channel: number(c)?,
            block: number(b)?,
        },
        ["FOURIER", "TRANSFORM"] => ProgramStep::Fourier,
        ["POWER", "SPECTRUM"] => ProgramStep::PowerSpectrum,
        ["COUNT", "LOOP", "LABEL", n, "TIMES", k] => ProgramStep::CountLoop {
            label: number(n)?,
            times: number(k)?,
        },
        ["DIVIDE", "BLOCK", b, "BY", k] => ProgramStep::Divide {
            block: number(b)?,
            by: k
                .parse::<f64>()
                .ok()
                .filter(|v| *v != 0.0 && v.is_finite())?,
        },
        ["LOG"] => ProgramStep::Log,
        ["DISPLAY"] => ProgramStep::Display,
        ["END"] => ProgramStep::End,
        _ => return None,
    })
}
