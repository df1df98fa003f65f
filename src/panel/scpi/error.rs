//! SCPI's error numbers (SCPI 1999 vol. 2 §21.8) as the error queue holds them: the
//! standard text, then after a semicolon what this instrument says of the case.

use super::ascii::ascii;

/// One error: its number and message.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ScpiError {
    /// The standard number (negative) or 0.
    pub code: i32,
    /// "Standard text;detail".
    pub message: String,
}

impl ScpiError {
    /// The message is kept to printable ASCII (`ascii.rs`): a detail's typographic signs
    /// spelled out, anything else beyond ASCII as `\xNN`.
    fn new(code: i32, text: &str, detail: &str) -> Self {
        let message = if detail.is_empty() {
            text.to_string()
        } else {
            ascii(&format!("{text};{detail}"))
        };
        Self { code, message }
    }

    /// -102: the line does not parse.
    pub fn syntax(detail: &str) -> Self {
        Self::new(-102, "Syntax error", detail)
    }

    /// -104: a parameter of another kind than the command takes.
    pub fn data_type(detail: &str) -> Self {
        Self::new(-104, "Data type error", detail)
    }

    /// -108: more parameters than the command takes.
    pub fn parameter_not_allowed(detail: &str) -> Self {
        Self::new(-108, "Parameter not allowed", detail)
    }

    /// -109: fewer parameters than the command takes.
    pub fn missing_parameter(detail: &str) -> Self {
        Self::new(-109, "Missing parameter", detail)
    }

    /// -113: no such command.
    pub fn undefined_header(header: &str) -> Self {
        Self::new(-113, "Undefined header", header)
    }

    /// -200: the rig could not carry it out.
    pub fn execution(detail: &str) -> Self {
        Self::new(-200, "Execution error", detail)
    }

    /// -203: protected until the token is given (docs/security.md).
    pub fn protected(detail: &str) -> Self {
        Self::new(-203, "Command protected", detail)
    }

    /// -222: a number outside the command's range (the range in the detail).
    pub fn out_of_range(detail: &str) -> Self {
        Self::new(-222, "Data out of range", detail)
    }

    /// -224: a word the command does not take (the words it takes in the detail).
    pub fn illegal_value(detail: &str) -> Self {
        Self::new(-224, "Illegal parameter value", detail)
    }

    /// -350: more errors than the queue holds.
    pub fn queue_overflow() -> Self {
        Self::new(-350, "Queue overflow", "")
    }

    /// -363: a line longer than the instrument reads.
    pub fn input_overrun(detail: &str) -> Self {
        Self::new(-363, "Input buffer overrun", detail)
    }

    /// The bit of the standard event status register its class sets: command errors
    /// (-1xx) CME, execution (-2xx) EXE, device-specific (-3xx) DDE, query (-4xx) QYE.
    pub fn event_bit(&self) -> u8 {
        match self.code {
            -199..=-100 => 1 << 5,
            -299..=-200 => 1 << 4,
            -399..=-300 => 1 << 3,
            -499..=-400 => 1 << 2,
            _ => 0,
        }
    }

    /// As `SYSTem:ERRor?` answers: `-222,"Data out of range;…"`.
    pub fn answer(&self) -> String {
        format!("{},\"{}\"", self.code, self.message.replace('"', "'"))
    }
}
