//! One SCPI client's instrument: its registers, data format and protection, and the
//! execution of each line's units against the live rig. Settings become the panel's own
//! commands (`RigCommand`, sent through the control channel and journalled into
//! `session.toml` as the panel's are); queries read the panel's state. A refused unit
//! goes onto the error queue and changes nothing; the units after it still run, unless
//! the line itself does not parse.

use std::sync::Arc;
use std::sync::atomic::Ordering;
use std::time::Duration;

use instruments::Window;

use super::data::{Format, ascii, block};
use super::error::ScpiError;
use super::message::{Parameter, Unit, units};
use super::rack::Rack;
use super::registers::{OPC_BIT, Registers};
use super::tree::{Command, Form, find};
use crate::panel::state::PanelState;
use crate::vocabulary::LiveSpectrum;
use crate::vocabulary::choices::{FilterChoice, WindowChoice};
use crate::vocabulary::command::{Reply, RigCommand, ScopeMode};

/// SCPI's "not a number" (SCPI 1999 §7.2.1.5): an alias line with no aliased component.
const SCPI_NAN: f64 = 9.91e37;

/// How often `*OPC?` and `*WAI` look whether the measurement is done.
const POLL: Duration = Duration::from_millis(10);

/// Longest wait for a display to appear while the run starts (wall time).
const STARTING: Duration = Duration::from_secs(10);

/// One client's instrument.
pub struct Instrument {
    rack: Rack,
    registers: Registers,
    format: Format,
    unlocked: bool,
    opc_armed: bool,
}

impl Instrument {
    /// A fresh instrument on `rack`.
    pub fn new(rack: Rack) -> Self {
        let unlocked = rack.token.is_none();
        Self {
            rack,
            registers: Registers::default(),
            format: Format::Ascii,
            unlocked,
            opc_armed: false,
        }
    }

    /// Queues an error found outside a line's units (a line too long).
    pub fn push_error(&mut self, error: ScpiError) {
        self.registers.push(error);
    }

    /// Executes one line; the answer to send (its queries' answers joined by `;` and
    /// ended by a newline), empty where it asked nothing.
    pub fn execute(&mut self, line: &str) -> Vec<u8> {
        let (units, error) = units(line);
        let mut answers: Vec<Vec<u8>> = Vec::new();
        for unit in &units {
            match self.unit(unit) {
                Ok(Some(answer)) => answers.push(answer),
                Ok(None) => {}
                Err(e) => self.registers.push(e),
            }
        }
        if let Some(e) = error {
            self.registers.push(e);
        }
        if answers.is_empty() {
            return Vec::new();
        }
        let mut out = answers.join(&b';');
        out.push(b'\n');
        out
    }

    fn unit(&mut self, unit: &Unit) -> Result<Option<Vec<u8>>, ScpiError> {
        let (command, form) =
            find(&unit.path).ok_or_else(|| ScpiError::undefined_header(&unit.header))?;
        if !self.unlocked
            && !matches!(
                command,
                Command::Identify | Command::Unlock | Command::NextError
            )
        {
            return Err(ScpiError::protected(
                "send SYSTem:PASSword \"<token>\" first (the token the panel printed; docs/security.md)",
            ));
        }
        let takes = |n: usize| expect_count(unit, n);
        match (form, unit.query) {
            (Form::Query, false) => Err(ScpiError::undefined_header(&format!(
                "{} is a query only: add ?",
                unit.header
            ))),
            (Form::Set | Form::Event, true) => Err(ScpiError::undefined_header(&format!(
                "{} has no query form",
                unit.header
            ))),
            (_, true) => {
                takes(0)?;
                self.query(command).map(Some)
            }
            (Form::Event, false) => {
                takes(0)?;
                self.event(command).map(|()| None)
            }
            (_, false) => self.set(command, &unit.parameters).map(|()| None),
        }
    }

    fn state(&self) -> PanelState {
        PanelState::of(&self.rack.status.snapshot(), self.rack.rate_hz)
    }

    fn measuring(&self) -> bool {
        self.state().spectrum.is_some_and(|s| !s.complete)
    }

    /// Blocks until the measurement under way is done (or the server stops).
    fn wait_for_measurement(&self) {
        while self.measuring() && !self.rack.stop.load(Ordering::Relaxed) {
            std::thread::sleep(POLL);
        }
    }

    fn send(&self, command: RigCommand, out_of_range: bool) -> Result<(), ScpiError> {
        let Reply { ok, error, .. } = self.rack.control.send(command);
        if ok {
            return Ok(());
        }
        let why = error.unwrap_or_default();
        Err(if out_of_range {
            ScpiError::out_of_range(&why)
        } else {
            ScpiError::execution(&why)
        })
    }

    fn spectrum(&self) -> Result<Arc<LiveSpectrum>, ScpiError> {
        if !self.rack.has_analyser {
            return Err(ScpiError::execution("this rig's scenario has no analyser"));
        }
        self.displayed(|s| s.spectrum.clone(), "the analyser")
    }

    /// A display of the state, waited for while the run starts (at most
    /// [`STARTING`]).
    fn displayed<T>(
        &self,
        display: impl Fn(&PanelState) -> Option<T>,
        what: &str,
    ) -> Result<T, ScpiError> {
        let since = std::time::Instant::now();
        loop {
            if let Some(shown) = display(&self.state()) {
                return Ok(shown);
            }
            if since.elapsed() > STARTING || self.rack.stop.load(Ordering::Relaxed) {
                return Err(ScpiError::execution(&format!("{what} shows nothing yet")));
            }
            std::thread::sleep(POLL);
        }
    }

    fn query(&mut self, command: Command) -> Result<Vec<u8>, ScpiError> {
        let s = self.state();
        let number = |x: f64| Ok(ascii(&[x]).into_bytes());
        let text = |t: &str| Ok(format!("\"{t}\"").into_bytes());
        match command {
            Command::Identify => Ok(self.rack.identity.clone().into_bytes()),
            Command::OperationComplete => {
                self.wait_for_measurement();
                Ok(b"1".to_vec())
            }
            Command::EventStatus => {
                self.settle_opc();
                Ok(self.registers.take_esr().to_string().into_bytes())
            }
            Command::EventEnable => Ok(self.registers.ese.to_string().into_bytes()),
            Command::ServiceEnable => Ok(self.registers.sre.to_string().into_bytes()),
            Command::StatusByte => {
                self.settle_opc();
                let measuring = self.measuring();
                Ok(self
                    .registers
                    .status_byte(measuring)
                    .to_string()
                    .into_bytes())
            }
            Command::SelfTest => Ok(b"0".to_vec()),
            Command::NextError => Ok(self.registers.next_error().into_bytes()),
            Command::ErrorCount => Ok(self.registers.error_count().to_string().into_bytes()),
            Command::Version => Ok(b"1999.0".to_vec()),
            Command::Speed => number(s.speed_set_rpm),
            Command::Load => number(s.load_set_nm),
            Command::OscillationAmplitude => number(s.oscillating_load_nm),
            Command::OscillationFrequency => number(s.oscillating_load_hz),
            Command::Motion => text(s.motion.as_deref().unwrap_or("settling")),
            Command::Time => number(s.simulated_s),
            Command::Impacts => Ok(s.impacts.to_string().into_bytes()),
            Command::AmplifierGain => {
                number(self.displayed(|s| s.chain.amplifier_gain, "the carrier amplifier")?)
            }
            Command::FilterType | Command::FilterOrder | Command::FilterFrequency => {
                let f = self.displayed(|s| s.chain.filter.clone(), "the anti-alias filter")?;
                match command {
                    Command::FilterType => Ok(filter_word(&f.kind).as_bytes().to_vec()),
                    Command::FilterOrder => Ok(f.order.to_string().into_bytes()),
                    _ => number(f.cutoff_hz),
                }
            }
            Command::TachoSpeed => number(s.dvm_rpm),
            Command::DvmVolts => number(s.dvm_v),
            Command::RmsVolts => number(s.meter_v),
            Command::OperationCondition => Ok(if self.measuring() {
                b"16".to_vec()
            } else {
                b"0".to_vec()
            }),
            Command::Format => Ok(self.format.word().as_bytes().to_vec()),
            Command::Span
            | Command::Resolution
            | Command::AverageState
            | Command::AverageCount
            | Command::AverageType
            | Command::Window
            | Command::InputRange
            | Command::SpectrumData
            | Command::FrequencyData
            | Command::AliasData => self.analyser_query(command),
            Command::ScopeVolts
            | Command::ScopeTime
            | Command::ScopeTrigger
            | Command::ScopeMode
            | Command::ScopeData
            | Command::ScopeTimeData => self.scope_query(command),
            _ => Err(ScpiError::undefined_header("no query form")),
        }
    }

    fn analyser_query(&self, command: Command) -> Result<Vec<u8>, ScpiError> {
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

    fn scope_query(&self, command: Command) -> Result<Vec<u8>, ScpiError> {
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

    /// Values in the format set: ASCII numbers or a definite-length block.
    fn data(&self, values: &[f64]) -> Vec<u8> {
        match self.format {
            Format::Ascii => ascii(values).into_bytes(),
            binary => block(values, binary),
        }
    }

    fn event(&mut self, command: Command) -> Result<(), ScpiError> {
        match command {
            Command::Reset => self.reset(),
            Command::ClearStatus => {
                self.registers.clear();
                self.opc_armed = false;
                Ok(())
            }
            Command::Wait => {
                self.wait_for_measurement();
                Ok(())
            }
            Command::Initiate => self.send(RigCommand::StartAverage, false),
            Command::Abort => self.send(RigCommand::HoldAverage, false),
            Command::ScopeArm => self.send(RigCommand::ArmScope, false),
            _ => Err(ScpiError::undefined_header("not an event")),
        }
    }

    /// `*RST`: the analyser back to its settings at the start, the average held, ASCII
    /// data. The motor and brake keep their set points: a lab's analyser reset does not
    /// stop the machine under test.
    fn reset(&mut self) -> Result<(), ScpiError> {
        self.format = Format::Ascii;
        self.opc_armed = false;
        if self.rack.reset.is_empty() {
            return Ok(());
        }
        self.send(RigCommand::HoldAverage, false)?;
        for command in self.rack.reset.clone() {
            self.send(command, false)?;
        }
        Ok(())
    }

    /// Sets `OPC` in the event register once the measurement `*OPC` waited for is done.
    fn settle_opc(&mut self) {
        if self.opc_armed && !self.measuring() {
            self.registers.esr |= OPC_BIT;
            self.opc_armed = false;
        }
    }

    fn set(&mut self, command: Command, params: &[Parameter]) -> Result<(), ScpiError> {
        let s = self.state();
        match command {
            Command::OperationComplete => {
                expect(params, 0)?;
                self.opc_armed = true;
                self.settle_opc();
                Ok(())
            }
            Command::EventEnable => {
                self.registers.ese = byte(params)?;
                Ok(())
            }
            Command::ServiceEnable => {
                self.registers.sre = byte(params)?;
                Ok(())
            }
            Command::Unlock => {
                let given = match params {
                    [Parameter::Text(t)] | [Parameter::Word(t)] => t.clone(),
                    _ => return Err(ScpiError::missing_parameter("the token, quoted")),
                };
                if self.rack.token.as_deref().is_none_or(|t| t == given) {
                    self.unlocked = true;
                    Ok(())
                } else {
                    Err(ScpiError::protected("wrong token"))
                }
            }
            Command::Speed => {
                let rpm = number(
                    params,
                    "RIG:SPEed",
                    (0.0, self.rack.max_speed_rpm),
                    "rev/min",
                )?;
                self.send(RigCommand::SetSpeed { rpm }, true)
            }
            Command::Load => {
                let nm = number(params, "RIG:LOAD", (0.0, self.rack.max_load_nm), "N m")?;
                self.send(RigCommand::SetLoad { nm }, true)
            }
            Command::OscillationAmplitude => {
                let nm = number(
                    params,
                    "RIG:OSCillation:AMPLitude",
                    (0.0, self.rack.max_load_nm),
                    "N m",
                )?;
                let hz = s.oscillating_load_hz;
                self.send(RigCommand::SetOscillatingLoad { nm, hz }, true)
            }
            Command::OscillationFrequency => {
                let hz = number(
                    params,
                    "RIG:OSCillation:FREQuency",
                    (0.0, self.rack.max_oscillating_hz),
                    "Hz",
                )?;
                let nm = s.oscillating_load_nm;
                self.send(RigCommand::SetOscillatingLoad { nm, hz }, true)
            }
            Command::AmplifierGain => {
                let gain = number(params, "RIG:AMPLifier:GAIN", (1e-6, 1e6), "V/V")?;
                self.send(RigCommand::SetAmplifierGain { gain }, true)
            }
            Command::FilterType | Command::FilterOrder | Command::FilterFrequency => {
                self.set_filter(command, params)
            }
            Command::Format => {
                self.format = Format::of(params)?;
                Ok(())
            }
            Command::ScopeVolts
            | Command::ScopeTime
            | Command::ScopeTrigger
            | Command::ScopeMode => self.set_scope(command, params),
            _ => self.set_analyser(command, params),
        }
    }

    fn set_filter(&mut self, command: Command, params: &[Parameter]) -> Result<(), ScpiError> {
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

    fn set_scope(&mut self, command: Command, params: &[Parameter]) -> Result<(), ScpiError> {
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

    fn set_analyser(&mut self, command: Command, params: &[Parameter]) -> Result<(), ScpiError> {
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

/// Lines in the band: the span over the line spacing.
fn lines(sp: &LiveSpectrum) -> usize {
    let df = match sp.frequency_hz.as_slice() {
        [a, b, ..] => b - a,
        _ => return 0,
    };
    (sp.fmax_hz / df).round() as usize
}

/// The block giving `wanted` lines in the current band (a power of two, 64 … 16384).
fn block_for_lines(sp: &LiveSpectrum, wanted: f64) -> Result<usize, ScpiError> {
    let now = lines(sp).max(1) as f64;
    let per_line = sp.block as f64 / now;
    let allowed: Vec<String> = (6..=14)
        .map(|p| ((1usize << p) as f64 / per_line).round().to_string())
        .collect();
    let block = wanted * per_line;
    let power = block.log2().round();
    if (block - 2f64.powf(power)).abs() < 1e-6 && (6.0..=14.0).contains(&power) {
        Ok(block.round() as usize)
    } else {
        Err(ScpiError::illegal_value(&format!(
            "{wanted} lines: one of {} at this span",
            allowed.join(", ")
        )))
    }
}

fn filter_word(kind: &str) -> &'static str {
    match kind {
        "butterworth" => "BUTT",
        "bessel" => "BESS",
        _ => "NONE",
    }
}

fn window_word(name: &str) -> &'static str {
    match name {
        "hanning" => "HANN",
        "flattop" => "FLAT",
        _ => "UNIF",
    }
}

fn expect_count(unit: &Unit, n: usize) -> Result<(), ScpiError> {
    expect(&unit.parameters, n)
}

fn expect(params: &[Parameter], n: usize) -> Result<(), ScpiError> {
    match params.len().cmp(&n) {
        std::cmp::Ordering::Equal => Ok(()),
        std::cmp::Ordering::Greater => Err(ScpiError::parameter_not_allowed(&format!(
            "{} parameters where {n} are taken",
            params.len()
        ))),
        std::cmp::Ordering::Less => Err(ScpiError::missing_parameter(&format!("{n} taken"))),
    }
}

/// One number in `range` (MINimum and MAXimum allowed), named `what` in messages.
fn number(
    params: &[Parameter],
    what: &str,
    range: (f64, f64),
    unit: &str,
) -> Result<f64, ScpiError> {
    expect(params, 1)?;
    let value = match &params[0] {
        Parameter::Number(x) => *x,
        Parameter::Word(w) if w == "MIN" || w == "MINIMUM" => range.0,
        Parameter::Word(w) if w == "MAX" || w == "MAXIMUM" => range.1,
        other => {
            return Err(ScpiError::data_type(&format!(
                "{what}: {other:?} is not a number"
            )));
        }
    };
    if !(range.0..=range.1).contains(&value) {
        return Err(ScpiError::out_of_range(&format!(
            "{what} {value}: {} … {} {unit}",
            range.0, range.1
        )));
    }
    Ok(value)
}

/// One word among `allowed` (as written, upper case).
fn word<'a>(params: &[Parameter], allowed: &[&'a str]) -> Result<&'a str, ScpiError> {
    expect(params, 1)?;
    match &params[0] {
        Parameter::Word(w) => allowed.iter().find(|a| *a == w).copied().ok_or_else(|| {
            ScpiError::illegal_value(&format!("{w}: one of {}", allowed.join(", ")))
        }),
        other => Err(ScpiError::data_type(&format!(
            "{other:?}: one of {}",
            allowed.join(", ")
        ))),
    }
}

/// ON, OFF, 1 or 0.
fn boolean(params: &[Parameter]) -> Result<bool, ScpiError> {
    expect(params, 1)?;
    match &params[0] {
        Parameter::Word(w) if w == "ON" => Ok(true),
        Parameter::Word(w) if w == "OFF" => Ok(false),
        Parameter::Number(x) if *x == 1.0 => Ok(true),
        Parameter::Number(x) if *x == 0.0 => Ok(false),
        other => Err(ScpiError::illegal_value(&format!(
            "{other:?}: ON, OFF, 1 or 0"
        ))),
    }
}

/// A register value 0 … 255.
fn byte(params: &[Parameter]) -> Result<u8, ScpiError> {
    let x = number(params, "register", (0.0, 255.0), "")?;
    Ok(x.round() as u8)
}
