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
pub enum Command {
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
    commands: Vec<Command>,
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
    pub fn commands(&self) -> &[Command] {
        &self.commands
    }

    /// Runs the program on ADC `samples` with the analyser's block size, rate and window;
    /// returns every display in order (the displayed lines of the block shown).
    pub fn run(
        &self,
        settings: &AnalyserSettings,
        samples: &[f64],
    ) -> Result<Vec<Vec<Line>>, InstrumentError> {
        let mut estimator =
            SpectrumEstimator::new(settings.block, settings.sample_rate_hz(), settings.window)?;
        let labels: HashMap<u32, usize> = self
            .commands
            .iter()
            .enumerate()
            .filter_map(|(i, c)| {
                if let Command::Label(n) = c {
                    Some((*n, i))
                } else {
                    None
                }
            })
            .collect();
        let lines = estimator.lines();
        let mut blocks: HashMap<u32, Vec<f64>> = HashMap::new();
        let mut passes: HashMap<usize, u32> = HashMap::new();
        let (mut record, mut spectrum) = (Vec::new(), vec![0.0; lines]);
        let (mut target, mut cursor, mut transformed) = (1, 0, false);
        let mut displays = Vec::new();
        let mut pc = 0;
        for _ in 0..STEP_LIMIT {
            let Some(&command) = self.commands.get(pc) else {
                return Ok(displays);
            };
            let line = self.source_lines[pc];
            pc += 1;
            match command {
                Command::Label(_) => {}
                Command::Clear(b) => {
                    blocks.insert(b, vec![0.0; lines]);
                }
                Command::AnalogIn { block, .. } => {
                    let end = cursor + settings.block;
                    let Some(taken) = samples.get(cursor..end) else {
                        return Err(program_error(line, "ANALOG IN ran out of samples"));
                    };
                    record = taken.to_vec();
                    cursor = end;
                    target = block;
                    transformed = false;
                }
                Command::Fourier => transformed = !record.is_empty(),
                Command::PowerSpectrum => {
                    if !transformed {
                        return Err(program_error(
                            line,
                            "POWER SPECTRUM needs FOURIER TRANSFORM of an ANALOG IN record",
                        ));
                    }
                    estimator.spectrum(&record, Spectrum::Power, &mut spectrum);
                    let block = blocks.entry(target).or_insert_with(|| vec![0.0; lines]);
                    block.iter_mut().zip(&spectrum).for_each(|(b, s)| *b += s);
                }
                Command::CountLoop { label, times } => {
                    let count = passes.entry(pc).or_insert(0);
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
                Command::Divide { block, by } => {
                    blocks
                        .entry(block)
                        .or_insert_with(|| vec![0.0; lines])
                        .iter_mut()
                        .for_each(|v| *v /= by);
                    target = block;
                }
                Command::Log => {
                    blocks
                        .entry(target)
                        .or_insert_with(|| vec![0.0; lines])
                        .iter_mut()
                        .for_each(|v| *v = 10.0 * v.log10());
                }
                Command::Display => {
                    let block = blocks
                        .get(&target)
                        .cloned()
                        .unwrap_or_else(|| vec![0.0; lines]);
                    let df = estimator.resolution_hz();
                    displays.push(
                        (0..settings.displayed_lines().min(lines))
                            .map(|k| Line {
                                frequency_hz: k as f64 * df,
                                value: block[k],
                            })
                            .collect(),
                    );
                }
                Command::End => return Ok(displays),
            }
        }
        Err(program_error(
            self.source_lines.last().copied().unwrap_or(0),
            "the program did not reach END within a million steps",
        ))
    }
}

fn program_error(line: usize, text: &str) -> InstrumentError {
    InstrumentError::Program {
        line,
        text: text.to_string(),
    }
}

fn parse_words(words: &[&str]) -> Option<Command> {
    let number = |w: &str| w.parse::<u32>().ok();
    Some(match words {
        ["LABEL", n] => Command::Label(number(n)?),
        ["CLEAR", "BLOCK", b] => Command::Clear(number(b)?),
        ["ANALOG", "IN", "CHANNEL", c, "BLOCK", b] => Command::AnalogIn {
            channel: number(c)?,
            block: number(b)?,
        },
        ["FOURIER", "TRANSFORM"] => Command::Fourier,
        ["POWER", "SPECTRUM"] => Command::PowerSpectrum,
        ["COUNT", "LOOP", "LABEL", n, "TIMES", k] => Command::CountLoop {
            label: number(n)?,
            times: number(k)?,
        },
        ["DIVIDE", "BLOCK", b, "BY", k] => Command::Divide {
            block: number(b)?,
            by: k
                .parse::<f64>()
                .ok()
                .filter(|v| *v != 0.0 && v.is_finite())?,
        },
        ["LOG"] => Command::Log,
        ["DISPLAY"] => Command::Display,
        ["END"] => Command::End,
        _ => return None,
    })
}
