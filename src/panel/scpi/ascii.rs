//! IEEE 488.2 response data are 7-bit ASCII (§8.7), and pyvisa decodes answers as ASCII
//! by default: what an answer echoes of the client's own bytes is written as `\xNN`, and
//! this instrument's own words are given in ASCII (the few typographic signs the rig's
//! messages use spelled as ASCII, anything else as `\xNN`).

/// `text` with every byte that is not printable ASCII (a control byte, or any byte of a
/// character beyond ASCII) written as `\xNN`; for what a client sent.
pub(crate) fn escaped(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        push_escaped(&mut out, c);
    }
    out
}

/// `text` in printable ASCII: the rig's typographic signs spelled out (`≥` `>=`, `≤`
/// `<=`, `…` `...`, dashes `-`, `µ` `u`, `×` `x`, `·` `*`, `°` ` deg`, curly quotes
/// straight), anything else as [`escaped`] writes it; for the instrument's own messages.
pub(crate) fn ascii(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match spelled(c) {
            Some(s) => out.push_str(s),
            None => push_escaped(&mut out, c),
        }
    }
    out
}

fn spelled(c: char) -> Option<&'static str> {
    Some(match c {
        '≥' => ">=",
        '≤' => "<=",
        '≠' => "!=",
        '…' => "...",
        '–' | '—' | '−' => "-",
        'µ' | 'μ' => "u",
        '×' => "x",
        '·' => "*",
        '°' => " deg",
        '‘' | '’' => "'",
        '“' | '”' => "\"",
        _ => return None,
    })
}

fn push_escaped(out: &mut String, c: char) {
    if c.is_ascii() && !c.is_ascii_control() {
        out.push(c);
        return;
    }
    let mut bytes = [0u8; 4];
    for b in c.encode_utf8(&mut bytes).bytes() {
        out.push_str(&format!("\\x{b:02X}"));
    }
}

#[cfg(test)]
mod tests {
    use super::{ascii, escaped};

    #[test]
    fn a_clients_bytes_beyond_ascii_are_written_as_hex() {
        assert_eq!(escaped("SPÉ\t1"), "SP\\xC3\\x89\\x091");
        assert_eq!(escaped("plain text"), "plain text");
    }

    #[test]
    fn the_rigs_own_signs_are_spelled_in_ascii_and_the_rest_escaped() {
        assert_eq!(ascii("x ≥ 0 … 5 µε"), "x >= 0 ... 5 u\\xCE\\xB5");
        assert!(ascii("—°×·“”‘’≤≠").is_ascii());
    }
}
