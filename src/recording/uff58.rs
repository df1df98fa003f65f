//! Universal File Format dataset 58 (function at nodal DOF), ASCII, as pyuff reads and
//! writes it: records 1–5 ID lines, 6 function identification, 7 data form, 8–11 axis
//! characteristics, 12 data as 4E20.12, between `    -1` delimiters.

use std::io::Write;

use super::fortran_e::FortranE;

/// How the abscissa runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Uff58Abscissa {
    /// Time (s) from `start_s` in steps of `step_s` (specific data type 17).
    Time {
        /// First abscissa value (s).
        start_s: f64,
        /// Step (s).
        step_s: f64,
    },
    /// Frequency (Hz) from `start_hz` in steps of `step_hz` (specific data type 18).
    Frequency {
        /// First abscissa value (Hz).
        start_hz: f64,
        /// Step (Hz).
        step_hz: f64,
    },
}

/// One dataset 58.
#[derive(Clone, Debug, PartialEq)]
pub struct Uff58Record<'a> {
    /// ID line 1: the function's description (80 characters at most).
    pub description: &'a str,
    /// ID line 2 (e.g. the program and scenario).
    pub source: &'a str,
    /// Function type: 1 time response, 2 auto spectrum, 12 spectrum.
    pub function_type: u32,
    /// Response entity name (10 characters at most).
    pub response_name: &'a str,
    /// Response node.
    pub response_node: u32,
    /// Ordinate specific data type: 3 strain, 19 rpm, 0 unknown.
    pub ordinate_type: u32,
    /// Ordinate units label (20 characters at most).
    pub ordinate_unit: &'a str,
    /// Abscissa.
    pub abscissa: Uff58Abscissa,
    /// Values (real, evenly spaced).
    pub values: &'a [f64],
}

/// Fortran E format: `width` characters, `digits` after the point, two-digit exponent.
fn fortran_e(value: f64, width: usize, digits: usize) -> String {
    let mut text = String::new();
    FortranE::default().push(&mut text, value, width, digits);
    text
}

/// A unit label in ASCII, as the universal file format's fixed columns need: µε is
/// written `microstrain`, µ `u`, ² `^2`, any other non-ASCII character `?`.
fn ascii_unit(unit: &str) -> String {
    unit.replace("µε", "microstrain")
        .replace('µ', "u")
        .replace('²', "^2")
        .chars()
        .map(|c| if c.is_ascii() { c } else { '?' })
        .collect()
}

fn padded(text: &str, width: usize) -> String {
    let cut: String = text.chars().take(width).collect();
    format!("{cut:<width$}")
}

/// Appends `record` to `out` as one ASCII dataset 58.
pub fn write_uff58(out: &mut impl Write, record: &Uff58Record) -> std::io::Result<()> {
    write_uff58_header(out, record, record.values.len())?;
    write_uff58_values(out, record.values)?;
    write_uff58_trailer(out)
}

/// Writes records 1–11 of a dataset of `count` values (`record.values` is not used).
pub fn write_uff58_header(
    out: &mut impl Write,
    record: &Uff58Record,
    count: usize,
) -> std::io::Result<()> {
    let (abscissa_type, start, step, abscissa_unit) = match record.abscissa {
        Uff58Abscissa::Time { start_s, step_s } => (17, start_s, step_s, "s"),
        Uff58Abscissa::Frequency { start_hz, step_hz } => (18, start_hz, step_hz, "Hz"),
    };
    writeln!(out, "{:>6}", -1)?;
    writeln!(out, "{:>6}{:74}", 58, "")?;
    for id in [record.description, record.source, "NONE", "NONE", "NONE"] {
        writeln!(out, "{}", padded(id, 80))?;
    }
    let name: String = record.response_name.chars().take(10).collect();
    writeln!(
        out,
        "{:>5}{:>10}{:>5}{:>10} {:>10}{:>10}{:>4} {:>10}{:>10}{:>4}",
        record.function_type, 0, 0, 0, name, record.response_node, 0, "NONE", 0, 0
    )?;
    writeln!(
        out,
        "{:>10}{:>10}{:>10}{}{}{}",
        4,
        count,
        1,
        fortran_e(start, 13, 5),
        fortran_e(step, 13, 5),
        fortran_e(0.0, 13, 5)
    )?;
    let axis = |out: &mut dyn Write, kind: u32, unit: &str| {
        writeln!(
            out,
            "{kind:>10}{:>5}{:>5}{:>5} {} {}",
            0,
            0,
            0,
            padded("NONE", 20),
            padded(&ascii_unit(unit), 20)
        )
    };
    axis(out, abscissa_type, abscissa_unit)?;
    axis(out, record.ordinate_type, record.ordinate_unit)?;
    axis(out, 0, "NONE")?;
    axis(out, 0, "NONE")
}

/// Writes values as record 12 lines (four a line, 4E20.12; the last line may be shorter).
pub fn write_uff58_values(out: &mut impl Write, values: &[f64]) -> std::io::Result<()> {
    FortranE::default().write_values(out, values)
}

/// Closes a dataset.
pub fn write_uff58_trailer(out: &mut impl Write) -> std::io::Result<()> {
    writeln!(out, "{:>6}", -1)
}
