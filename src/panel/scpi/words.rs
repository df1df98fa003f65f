//! SCPI's numbers and words read against what the rig takes: a parameter count, a number
//! in its range (MIN/MAX allowed), a word among those taken, a boolean, a register byte;
//! and the analyser's and chain's names in SCPI's spelling (lines ↔ block, window and
//! filter words).

use super::error::ScpiError;
use super::message::Parameter;
use crate::vocabulary::LiveSpectrum;

/// Lines in the band: the span over the line spacing.
pub(crate) fn lines(sp: &LiveSpectrum) -> usize {
    let df = match sp.frequency_hz.as_slice() {
        [a, b, ..] => b - a,
        _ => return 0,
    };
    (sp.fmax_hz / df).round() as usize
}

/// The block giving `wanted` lines in the current band (a power of two, 64 … 16384).
pub(crate) fn block_for_lines(sp: &LiveSpectrum, wanted: f64) -> Result<usize, ScpiError> {
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

pub(crate) fn filter_word(kind: &str) -> &'static str {
    match kind {
        "butterworth" => "BUTT",
        "bessel" => "BESS",
        _ => "NONE",
    }
}

pub(crate) fn window_word(name: &str) -> &'static str {
    match name {
        "hanning" => "HANN",
        "flattop" => "FLAT",
        _ => "UNIF",
    }
}

pub(crate) fn expect(params: &[Parameter], n: usize) -> Result<(), ScpiError> {
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
pub(crate) fn number(
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
                "{what}: `{}` is not a number",
                other.shown()
            )));
        }
    };
    if !(range.0..=range.1).contains(&value) {
        return Err(ScpiError::out_of_range(&format!(
            "{what} {value}: {} to {} {unit}",
            range.0, range.1
        )));
    }
    Ok(value)
}

/// One word among `allowed` (as written, upper case).
pub(crate) fn word<'a>(params: &[Parameter], allowed: &[&'a str]) -> Result<&'a str, ScpiError> {
    expect(params, 1)?;
    match &params[0] {
        Parameter::Word(w) => allowed.iter().find(|a| *a == w).copied().ok_or_else(|| {
            ScpiError::illegal_value(&format!("{w}: one of {}", allowed.join(", ")))
        }),
        other => Err(ScpiError::data_type(&format!(
            "`{}`: one of {}",
            other.shown(),
            allowed.join(", ")
        ))),
    }
}

/// ON, OFF, 1 or 0.
pub(crate) fn boolean(params: &[Parameter]) -> Result<bool, ScpiError> {
    expect(params, 1)?;
    match &params[0] {
        Parameter::Word(w) if w == "ON" => Ok(true),
        Parameter::Word(w) if w == "OFF" => Ok(false),
        Parameter::Number(x) if *x == 1.0 => Ok(true),
        Parameter::Number(x) if *x == 0.0 => Ok(false),
        other => Err(ScpiError::illegal_value(&format!(
            "`{}`: ON, OFF, 1 or 0",
            other.shown()
        ))),
    }
}

/// A register value 0 … 255.
pub(crate) fn byte(params: &[Parameter]) -> Result<u8, ScpiError> {
    let x = number(params, "register", (0.0, 255.0), "")?;
    Ok(x.round() as u8)
}
