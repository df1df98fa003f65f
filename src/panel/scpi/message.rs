//! IEEE 488.2 program messages: a line split into units at `;` (not inside quotes), each
//! unit's header resolved to a full path (a leading `:` starts from the root; a header
//! after `;` without one continues from the previous header's node, SCPI 1999 §6.2.4;
//! common commands `*XXX` leave the path alone), and its parameters split at commas.

use super::ascii::escaped;
use super::error::ScpiError;

/// Longest line read (bytes); a longer one is refused whole with -363.
pub const MAX_LINE_BYTES: usize = 64 * 1024;

/// Most parameters one unit may carry.
const MAX_PARAMETERS: usize = 16;

/// One parameter as written.
#[derive(Clone, Debug, PartialEq)]
pub enum Parameter {
    /// A decimal number (finite).
    Number(f64),
    /// Character data (`HANNing`, `ON`, `MAX`, `REAL`), upper-cased.
    Word(String),
    /// A quoted string, quotes taken off.
    Text(String),
}

impl Parameter {
    /// The parameter as a message shows it: the number, the word, or the string quoted
    /// (a client's bytes beyond ASCII as `\xNN`).
    pub fn shown(&self) -> String {
        match self {
            Self::Number(x) => x.to_string(),
            Self::Word(w) => w.clone(),
            Self::Text(t) => format!("'{}'", escaped(t)),
        }
    }
}

/// One unit of a message, its header resolved.
#[derive(Clone, Debug, PartialEq)]
pub struct Unit {
    /// The path's mnemonics upper-cased (`["SENSE", "FREQ", "SPAN"]`), or the common
    /// command (`["*IDN"]`).
    pub path: Vec<String>,
    /// Whether it ends in `?`.
    pub query: bool,
    /// Its parameters.
    pub parameters: Vec<Parameter>,
    /// The header as written, for messages.
    pub header: String,
}

/// The units of `line`, each header resolved from the one before; the first unit that
/// does not parse ends the line (its error is returned after the good units before it).
pub fn units(line: &str) -> (Vec<Unit>, Option<ScpiError>) {
    let mut out = Vec::new();
    let mut node: Vec<String> = Vec::new();
    for text in split_outside_quotes(line, ';') {
        let text = text.trim();
        if text.is_empty() {
            continue;
        }
        match unit(text, &node) {
            Ok(u) => {
                if !u.path[0].starts_with('*') {
                    node = u.path[..u.path.len() - 1].to_vec();
                }
                out.push(u);
            }
            Err(e) => return (out, Some(e)),
        }
    }
    (out, None)
}

/// One unit, its header relative to `node` unless it starts with `:`.
fn unit(text: &str, node: &[String]) -> Result<Unit, ScpiError> {
    let (header, rest) = match text.find(char::is_whitespace) {
        Some(at) => (&text[..at], text[at..].trim()),
        None => (text, ""),
    };
    let (header_body, query) = match header.strip_suffix('?') {
        Some(h) => (h, true),
        None => (header, false),
    };
    let shown = escaped(&header.chars().take(40).collect::<String>());
    let path = if let Some(common) = header_body.strip_prefix('*') {
        if common.is_empty() || !common.chars().all(|c| c.is_ascii_alphabetic()) {
            return Err(ScpiError::syntax(&format!("header `{shown}`")));
        }
        vec![format!("*{}", common.to_ascii_uppercase())]
    } else {
        let (absolute, body) = match header_body.strip_prefix(':') {
            Some(b) => (true, b),
            None => (false, header_body),
        };
        let mnemonics: Vec<&str> = body.split(':').collect();
        let good = |m: &&str| {
            !m.is_empty()
                && m.len() <= 24
                && m.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
                && m.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        };
        if !mnemonics.iter().all(good) {
            return Err(ScpiError::syntax(&format!("header `{shown}`")));
        }
        let mut path = if absolute { Vec::new() } else { node.to_vec() };
        path.extend(mnemonics.iter().map(|m| m.to_ascii_uppercase()));
        path
    };
    Ok(Unit {
        path,
        query,
        parameters: parameters(rest)?,
        header: shown,
    })
}

/// The parameters of a unit: comma-separated numbers, words or quoted strings.
fn parameters(text: &str) -> Result<Vec<Parameter>, ScpiError> {
    if text.is_empty() {
        return Ok(Vec::new());
    }
    let items = split_outside_quotes(text, ',');
    if items.len() > MAX_PARAMETERS {
        return Err(ScpiError::parameter_not_allowed(&format!(
            "{} parameters (at most {MAX_PARAMETERS})",
            items.len()
        )));
    }
    items.iter().map(|item| parameter(item.trim())).collect()
}

fn parameter(item: &str) -> Result<Parameter, ScpiError> {
    let shown = escaped(&item.chars().take(40).collect::<String>());
    let Some(first) = item.chars().next() else {
        return Err(ScpiError::missing_parameter(
            "an empty parameter between commas",
        ));
    };
    if first == '"' || first == '\'' {
        let inner = item
            .strip_prefix(first)
            .and_then(|s| s.strip_suffix(first))
            .ok_or_else(|| ScpiError::syntax(&format!("unterminated string {shown}")))?;
        return Ok(Parameter::Text(inner.to_string()));
    }
    if first.is_ascii_digit() || matches!(first, '+' | '-' | '.') {
        let number: f64 = item
            .parse()
            .map_err(|_| ScpiError::data_type(&format!("`{shown}` is not a number")))?;
        if !number.is_finite() {
            return Err(ScpiError::out_of_range(&format!(
                "`{shown}` is beyond any finite number"
            )));
        }
        return Ok(Parameter::Number(number));
    }
    if first.is_ascii_alphabetic() && item.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Ok(Parameter::Word(item.to_ascii_uppercase()));
    }
    Err(ScpiError::syntax(&format!("parameter `{shown}`")))
}

/// `text` split at `separator` wherever it stands outside single or double quotes.
fn split_outside_quotes(text: &str, separator: char) -> Vec<&str> {
    let mut parts = Vec::new();
    let mut quote: Option<char> = None;
    let mut start = 0;
    for (at, c) in text.char_indices() {
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if c == '"' || c == '\'' => quote = Some(c),
            None if c == separator => {
                parts.push(&text[start..at]);
                start = at + c.len_utf8();
            }
            None => {}
        }
    }
    parts.push(&text[start..]);
    parts
}

#[cfg(test)]
mod tests {
    use super::*;

    fn paths(line: &str) -> Vec<String> {
        let (units, error) = units(line);
        assert_eq!(error, None, "{line}");
        units.iter().map(|u| u.path.join(":")).collect()
    }

    #[test]
    fn a_header_after_a_semicolon_continues_from_the_last_node() {
        assert_eq!(
            paths("SENS:FREQ:SPAN 200;RES 400;:AVER:COUN 10;*OPC;STAT 1"),
            [
                "SENS:FREQ:SPAN",
                "SENS:FREQ:RES",
                "AVER:COUN",
                "*OPC",
                "AVER:STAT"
            ]
        );
    }

    #[test]
    fn parameters_are_numbers_words_and_strings_and_case_does_not_matter() {
        let (units, _) =
            units(":sense:window:type hanning;:form:data real,32;:syst:pass:cen 'a;b'");
        assert_eq!(units[0].path, ["SENSE", "WINDOW", "TYPE"]);
        assert_eq!(units[0].parameters, [Parameter::Word("HANNING".into())]);
        assert_eq!(
            units[1].parameters,
            [Parameter::Word("REAL".into()), Parameter::Number(32.0)]
        );
        assert_eq!(units[2].parameters, [Parameter::Text("a;b".into())]);
        assert!(units[2].path.ends_with(&["CEN".to_string()]));
    }

    #[test]
    fn malformed_units_are_refused_with_their_number() {
        for (line, code) in [
            ("RIG:SPE 1e999", -222),
            ("RIG:SPE 12abc", -104),
            ("RIG:SPE 1,,2", -109),
            ("RIG::SPE 1", -102),
            ("*ID%N?", -102),
            ("RIG:SPE \"open", -102),
            ("RIG:SPE $", -102),
        ] {
            let (_, error) = units(line);
            assert_eq!(error.map(|e| e.code), Some(code), "{line}");
        }
    }
}
