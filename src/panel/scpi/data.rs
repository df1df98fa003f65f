//! How answers carry numbers: ASCII (NR3, shortest round-trip, comma-separated) or an
//! IEEE 488.2 definite-length block `#<digits><length><bytes>` of big-endian IEEE floats
//! (`FORMat:DATA REAL,32|REAL,64`), as pyvisa's `query_binary_values` reads them.

use super::error::ScpiError;
use super::message::Parameter;

/// The data format of one client's answers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Text numbers.
    Ascii,
    /// 32-bit big-endian floats in a block.
    Real32,
    /// 64-bit big-endian floats in a block.
    Real64,
}

impl Format {
    /// The format `FORMat:DATA`'s parameters name: `ASCii`, `REAL` (64), `REAL,32`,
    /// `REAL,64`.
    pub fn of(params: &[Parameter]) -> Result<Self, ScpiError> {
        let word = |p: &Parameter| match p {
            Parameter::Word(w) => Some(w.clone()),
            _ => None,
        };
        match params {
            [first] | [first, _]
                if word(first)
                    .as_deref()
                    .is_some_and(|w| w == "ASC" || w == "ASCII") =>
            {
                Ok(Self::Ascii)
            }
            [first] if word(first).as_deref() == Some("REAL") => Ok(Self::Real64),
            [first, Parameter::Number(bits)] if word(first).as_deref() == Some("REAL") => {
                match *bits as i64 {
                    32 if *bits == 32.0 => Ok(Self::Real32),
                    64 if *bits == 64.0 => Ok(Self::Real64),
                    _ => Err(ScpiError::illegal_value(&format!(
                        "REAL,{bits}: REAL,32 or REAL,64"
                    ))),
                }
            }
            [] => Err(ScpiError::missing_parameter("ASCii, REAL,32 or REAL,64")),
            _ => Err(ScpiError::illegal_value("ASCii, REAL,32 or REAL,64")),
        }
    }

    /// As `FORMat?` answers.
    pub fn word(self) -> &'static str {
        match self {
            Self::Ascii => "ASC,8",
            Self::Real32 => "REAL,32",
            Self::Real64 => "REAL,64",
        }
    }
}

/// `values` as text: each the shortest decimal that reads back to it, comma-separated.
pub fn ascii(values: &[f64]) -> String {
    values
        .iter()
        .map(|v| format!("{v:E}"))
        .collect::<Vec<_>>()
        .join(",")
}

/// `values` as a definite-length block of big-endian floats of `format`'s width.
pub fn block(values: &[f64], format: Format) -> Vec<u8> {
    let bytes: Vec<u8> = match format {
        Format::Real32 => values
            .iter()
            .flat_map(|v| (*v as f32).to_be_bytes())
            .collect(),
        _ => values.iter().flat_map(|v| v.to_be_bytes()).collect(),
    };
    let length = bytes.len().to_string();
    let mut out = format!("#{}{length}", length.len()).into_bytes();
    out.extend(bytes);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_block_says_its_length_and_holds_big_endian_floats() {
        let b = block(&[1.0, -2.5], Format::Real32);
        assert_eq!(&b[..3], b"#18");
        assert_eq!(&b[3..7], &1.0f32.to_be_bytes());
        assert_eq!(&b[7..], &(-2.5f32).to_be_bytes());
        let b = block(&[0.1; 2], Format::Real64);
        assert_eq!(&b[..4], b"#216");
        assert_eq!(f64::from_be_bytes(b[4..12].try_into().unwrap()), 0.1);
    }

    #[test]
    fn ascii_numbers_read_back_exactly() {
        let values = [0.1, 1e-20, 123456.789, -0.0];
        let text = ascii(&values);
        let back: Vec<f64> = text.split(',').map(|t| t.parse().unwrap()).collect();
        assert_eq!(back, values);
    }
}
