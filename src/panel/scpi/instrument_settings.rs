//! The analyser's, the chain's and the scope's settings and displays, for one client's
//! [`Instrument`]: each setting read against its range and sent as the panel's command,
//! each query read from the panel's state.

use instruments::Window;

use super::data::ascii;
use super::error::ScpiError;
use super::instrument::{Instrument, SCPI_NAN};
use super::message::Parameter;
use super::tree::Command;
use super::words::{block_for_lines, boolean, lines, number, window_word, word};
use crate::vocabulary::choices::{FilterChoice, WindowChoice};
use crate::vocabulary::command::{RigCommand, ScopeMode};

impl Instrument {
    pub(super) fn analyser_query(&self, command: Command) -> Result<Vec<u8>, ScpiError> {
        let sp = self.spectrum()?;
        let number = |x: f64| Ok(ascii(&[x]).into_bytes());
        match command {
            Command::Span => number(sp.fmax_hz),
            Command::Resolution => number(lines(&sp) as f64),
            Command::AverageState => Ok(if sp.averages_set > 1 {
                b"1".to_vec()
            } else {
                b"0".to_vec()
            }),
            Command::AverageCount => Ok(sp.averages_set.to_string().into_bytes()),
            Command::AverageType => Ok(b"RMS".to_vec()),
            Command::Window => Ok(window_word(&sp.window).as_bytes().to_vec()),
            Command::InputRange => number(sp.adc_range_v),
            Command::SpectrumData => Ok(self.data(&sp.power_v2)),
            Command::FrequencyData => Ok(self.data(&sp.frequency_hz)),
            _ => {
                let alias: Vec<f64> = sp
                    .alias_of_hz
                    .iter()
                    .map(|a| a.unwrap_or(SCPI_NAN))
                    .collect();
                Ok(self.data(&alias))
            }
        }
    }

    pub(super) fn scope_query(&self, command: Command) -> Result<Vec<u8>, ScpiError> {
        if !self.rack.has_scope {
            return Err(ScpiError::execution("this rig's scenario has no scope"));
        }
        let trace = self.displayed(|s| s.trace.clone(), "the scope")?;
        let number = |x: f64| Ok(ascii(&[x]).into_bytes());
        match command {
            Command::ScopeVolts => number(trace.volts_per_div),
            Command::ScopeTime => number(trace.seconds_per_div),
            Command::ScopeTrigger => number(trace.trigger_v),
            Command::ScopeMode => Ok(trace.mode.to_ascii_uppercase().into_bytes()),
            Command::ScopeData => {
                let volts: Vec<f64> = trace
                    .divisions
                    .iter()
                    .map(|d| d * trace.volts_per_div)
                    .collect();
                Ok(self.data(&volts))
            }
            _ => Ok(self.data(&trace.time_s)),
        }
    }

    pub(super) fn set_filter(
        &mut self,
        command: Command,
        params: &[Parameter],
    ) -> Result<(), ScpiError> {
        let applied = self.displayed(|s| s.chain.filter.clone(), "the anti-alias filter")?;
        let mut kind = match applied.kind.as_str() {
            "none" => FilterChoice::None,
            "bessel" => FilterChoice::Bessel,
            _ => FilterChoice::Butterworth,
        };
        let mut order = applied.order.max(1);
        let mut cutoff_hz = applied.cutoff_hz;
        match command {
            Command::FilterType => {
                kind = match word(params, &["NONE", "BUTTERWORTH", "BUTT", "BESSEL", "BESS"])? {
                    "NONE" => FilterChoice::None,
                    "BESSEL" | "BESS" => FilterChoice::Bessel,
                    _ => FilterChoice::Butterworth,
                }
            }
            Command::FilterOrder => {
                order = number(params, "RIG:FILTer:ORDer", (1.0, 12.0), "")? as usize;
            }
            _ => {
                cutoff_hz = number(
                    params,
                    "RIG:FILTer:FREQuency",
                    (1e-3, self.rack.rate_hz / 2.0),
                    "Hz",
                )?;
            }
        }
        self.send(
            RigCommand::SetFilter {
                kind,
                order,
                cutoff_hz,
            },
            true,
        )
    }

    pub(super) fn set_scope(
        &mut self,
        command: Command,
        params: &[Parameter],
    ) -> Result<(), ScpiError> {
        let mut set = (None, None, None, None);
        match command {
            Command::ScopeVolts => {
                set.0 = Some(number(params, "SCOPe:VOLTs", (1e-9, 1e6), "V/div")?)
            }
            Command::ScopeTime => set.1 = Some(number(params, "SCOPe:TIME", (1e-9, 1e3), "s/div")?),
            Command::ScopeTrigger => {
                set.2 = Some(number(params, "SCOPe:TRIGger", (-1e6, 1e6), "V")?)
            }
            _ => {
                set.3 = Some(match word(params, &["AUTO", "SINGLE", "SING"])? {
                    "AUTO" => ScopeMode::Auto,
                    _ => ScopeMode::Single,
                })
            }
        }
        let (volts_per_div, seconds_per_div, trigger_v, mode) = set;
        self.send(
            RigCommand::SetScope {
                volts_per_div,
                seconds_per_div,
                trigger_v,
                mode,
            },
            true,
        )
    }

    pub(super) fn set_analyser(
        &mut self,
        command: Command,
        params: &[Parameter],
    ) -> Result<(), ScpiError> {
        let sp = self.spectrum()?;
        let mut change = AnalyserChange::default();
        match command {
            Command::Span => {
                change.fmax_hz = Some(number(
                    params,
                    "FREQuency:SPAN",
                    (1e-3, self.rack.rate_hz / 2.0),
                    "Hz",
                )?)
            }
            Command::Resolution => {
                change.block = Some(block_for_lines(
                    &sp,
                    number(params, "FREQuency:RESolution", (1.0, 1e6), "lines")?,
                )?)
            }
            Command::AverageState => {
                let on = boolean(params)?;
                change.averages = Some(if on { sp.averages_set.max(2) } else { 1 });
            }
            Command::AverageCount => {
                change.averages =
                    Some(number(params, "AVERage:COUNt", (1.0, 100_000.0), "")?.round() as usize);
            }
            Command::AverageType => {
                word(params, &["RMS", "POWER", "POW"])?;
                return Ok(());
            }
            Command::Window => {
                change.window = Some(
                    match word(
                        params,
                        &[
                            "HANNING",
                            "HANN",
                            "FLATTOP",
                            "FLAT",
                            "UNIFORM",
                            "UNIF",
                            "RECTANGULAR",
                            "RECT",
                        ],
                    )? {
                        "HANNING" | "HANN" => Window::Hanning,
                        "FLATTOP" | "FLAT" => Window::FlatTop,
                        _ => Window::Uniform,
                    },
                )
            }
            Command::InputRange => {
                let range_v = number(params, "INPut:RANGe", (1e-6, 1e3), "V")?;
                return self.send(RigCommand::SetAdcRange { range_v }, true);
            }
            _ => return Err(ScpiError::undefined_header("no set form")),
        }
        self.send(
            RigCommand::SetAnalyser {
                fmax_hz: change.fmax_hz,
                block: change.block,
                window: change.window.map(WindowChoice),
                averages: change.averages,
                overlap_pct: None,
            },
            true,
        )
    }
}

/// An analyser setting changed by one command.
#[derive(Default)]
struct AnalyserChange {
    fmax_hz: Option<f64>,
    block: Option<usize>,
    window: Option<Window>,
    averages: Option<usize>,
}
