//! One SCPI client's instrument: its registers, data format and protection, and the
//! execution of each line's units against the live rig. Settings become the panel's own
//! commands (`RigCommand`, sent through the control channel and journalled into
//! `session.toml` as the panel's are); queries read the panel's state. A refused unit
//! goes onto the error queue and changes nothing; the units after it still run, unless
//! the line itself does not parse.

use std::sync::Arc;
use std::sync::atomic::Ordering;
use std::time::Duration;

use super::ascii::ascii as ascii_text;
use super::data::{Format, ascii, block};
use super::error::ScpiError;
use super::message::{Parameter, Unit, units};
use super::rack::Rack;
use super::registers::{OPC_BIT, Registers};
use super::tree::{Command, Form, find};
use super::words::{byte, expect, filter_word, number};
use crate::panel::state::PanelState;
use crate::vocabulary::LiveSpectrum;
use crate::vocabulary::command::{Reply, RigCommand};

/// SCPI's "not a number" (SCPI 1999 §7.2.1.5): an alias line with no aliased component.
pub(super) const SCPI_NAN: f64 = 9.91e37;

/// How often `*OPC?` and `*WAI` look whether the measurement is done.
const POLL: Duration = Duration::from_millis(10);

/// Longest wait for a display to appear while the run starts (wall time).
const STARTING: Duration = Duration::from_secs(10);

/// One client's instrument.
pub struct Instrument {
    pub(super) rack: Rack,
    registers: Registers,
    pub(super) format: Format,
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
        let takes = |n: usize| expect(&unit.parameters, n);
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

    pub(super) fn state(&self) -> PanelState {
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

    pub(super) fn send(&self, command: RigCommand, out_of_range: bool) -> Result<(), ScpiError> {
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

    pub(super) fn spectrum(&self) -> Result<Arc<LiveSpectrum>, ScpiError> {
        if !self.rack.has_analyser {
            return Err(ScpiError::execution("this rig's scenario has no analyser"));
        }
        self.displayed(|s| s.spectrum.clone(), "the analyser")
    }

    /// A display of the state, waited for while the run starts (at most
    /// [`STARTING`]).
    pub(super) fn displayed<T>(
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
        let text = |t: &str| Ok(format!("\"{}\"", ascii_text(t).replace('"', "'")).into_bytes());
        match command {
            Command::Identify => Ok(ascii_text(&self.rack.identity).into_bytes()),
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

    /// Values in the format set: ASCII numbers or a definite-length block.
    pub(super) fn data(&self, values: &[f64]) -> Vec<u8> {
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
}
