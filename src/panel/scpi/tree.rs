//! The command tree: every header the rig answers, in SCPI's notation (upper case the
//! short form, the whole word the long form, `[ ]` an optional node), what it does and
//! whether it sets, queries or both. `docs/scpi.md` lists the same table with ranges.

/// What a header does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Command {
    /// `*IDN?`
    Identify,
    /// `*RST`
    Reset,
    /// `*CLS`
    ClearStatus,
    /// `*OPC` / `*OPC?`
    OperationComplete,
    /// `*WAI`
    Wait,
    /// `*ESR?`
    EventStatus,
    /// `*ESE` / `*ESE?`
    EventEnable,
    /// `*SRE` / `*SRE?`
    ServiceEnable,
    /// `*STB?`
    StatusByte,
    /// `*TST?`
    SelfTest,
    /// `SYSTem:ERRor[:NEXT]?`
    NextError,
    /// `SYSTem:ERRor:COUNt?`
    ErrorCount,
    /// `SYSTem:VERSion?`
    Version,
    /// `SYSTem:PASSword[:CENable]`
    Unlock,
    /// `RIG:SPEed`
    Speed,
    /// `RIG:LOAD`
    Load,
    /// `RIG:OSCillation:AMPLitude`
    OscillationAmplitude,
    /// `RIG:OSCillation:FREQuency`
    OscillationFrequency,
    /// `RIG:MOTion?`
    Motion,
    /// `RIG:TIME?`
    Time,
    /// `RIG:IMPacts?`
    Impacts,
    /// `RIG:AMPLifier:GAIN`
    AmplifierGain,
    /// `RIG:FILTer:TYPE`
    FilterType,
    /// `RIG:FILTer:ORDer`
    FilterOrder,
    /// `RIG:FILTer:FREQuency`
    FilterFrequency,
    /// `MEASure:SPEed?`
    TachoSpeed,
    /// `MEASure:VOLTage:DVM?`
    DvmVolts,
    /// `MEASure:VOLTage:RMS?`
    RmsVolts,
    /// `[SENSe:]FREQuency:SPAN`
    Span,
    /// `[SENSe:]FREQuency:RESolution`
    Resolution,
    /// `[SENSe:]AVERage[:STATe]`
    AverageState,
    /// `[SENSe:]AVERage:COUNt`
    AverageCount,
    /// `[SENSe:]AVERage:TYPE`
    AverageType,
    /// `[SENSe:]WINDow[:TYPE]`
    Window,
    /// `INPut:RANGe`
    InputRange,
    /// `INITiate[:IMMediate]`
    Initiate,
    /// `ABORt`
    Abort,
    /// `STATus:OPERation:CONDition?`
    OperationCondition,
    /// `FORMat[:DATA]`
    Format,
    /// `CALCulate:DATA?`
    SpectrumData,
    /// `CALCulate:X:DATA?`
    FrequencyData,
    /// `CALCulate:ALIas:DATA?`
    AliasData,
    /// `SCOPe:VOLTs`
    ScopeVolts,
    /// `SCOPe:TIME`
    ScopeTime,
    /// `SCOPe:TRIGger[:LEVel]`
    ScopeTrigger,
    /// `SCOPe:MODE`
    ScopeMode,
    /// `SCOPe:ARM`
    ScopeArm,
    /// `SCOPe:DATA?`
    ScopeData,
    /// `SCOPe:X:DATA?`
    ScopeTimeData,
}

/// Whether a header sets, queries, or both; `Event` takes no parameter and no `?`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    /// Set and query.
    Both,
    /// Query only.
    Query,
    /// Set only (with parameters).
    Set,
    /// An action without parameters.
    Event,
}

/// The tree: header pattern, command, form.
pub const TREE: &[(&str, Command, Form)] = &[
    ("*IDN", Command::Identify, Form::Query),
    ("*RST", Command::Reset, Form::Event),
    ("*CLS", Command::ClearStatus, Form::Event),
    ("*OPC", Command::OperationComplete, Form::Both),
    ("*WAI", Command::Wait, Form::Event),
    ("*ESR", Command::EventStatus, Form::Query),
    ("*ESE", Command::EventEnable, Form::Both),
    ("*SRE", Command::ServiceEnable, Form::Both),
    ("*STB", Command::StatusByte, Form::Query),
    ("*TST", Command::SelfTest, Form::Query),
    ("SYSTem:ERRor[:NEXT]", Command::NextError, Form::Query),
    ("SYSTem:ERRor:COUNt", Command::ErrorCount, Form::Query),
    ("SYSTem:VERSion", Command::Version, Form::Query),
    ("SYSTem:PASSword[:CENable]", Command::Unlock, Form::Set),
    ("RIG:SPEed", Command::Speed, Form::Both),
    ("RIG:LOAD", Command::Load, Form::Both),
    (
        "RIG:OSCillation:AMPLitude",
        Command::OscillationAmplitude,
        Form::Both,
    ),
    (
        "RIG:OSCillation:FREQuency",
        Command::OscillationFrequency,
        Form::Both,
    ),
    ("RIG:MOTion", Command::Motion, Form::Query),
    ("RIG:TIME", Command::Time, Form::Query),
    ("RIG:IMPacts", Command::Impacts, Form::Query),
    ("RIG:AMPLifier:GAIN", Command::AmplifierGain, Form::Both),
    ("RIG:FILTer:TYPE", Command::FilterType, Form::Both),
    ("RIG:FILTer:ORDer", Command::FilterOrder, Form::Both),
    ("RIG:FILTer:FREQuency", Command::FilterFrequency, Form::Both),
    ("MEASure:SPEed", Command::TachoSpeed, Form::Query),
    ("MEASure:VOLTage:DVM", Command::DvmVolts, Form::Query),
    ("MEASure:VOLTage:RMS", Command::RmsVolts, Form::Query),
    ("[SENSe:]FREQuency:SPAN", Command::Span, Form::Both),
    (
        "[SENSe:]FREQuency:RESolution",
        Command::Resolution,
        Form::Both,
    ),
    ("[SENSe:]AVERage[:STATe]", Command::AverageState, Form::Both),
    ("[SENSe:]AVERage:COUNt", Command::AverageCount, Form::Both),
    ("[SENSe:]AVERage:TYPE", Command::AverageType, Form::Both),
    ("[SENSe:]WINDow[:TYPE]", Command::Window, Form::Both),
    ("INPut:RANGe", Command::InputRange, Form::Both),
    ("INITiate[:IMMediate]", Command::Initiate, Form::Event),
    ("ABORt", Command::Abort, Form::Event),
    (
        "STATus:OPERation:CONDition",
        Command::OperationCondition,
        Form::Query,
    ),
    ("FORMat[:DATA]", Command::Format, Form::Both),
    ("CALCulate:DATA", Command::SpectrumData, Form::Query),
    ("CALCulate:X:DATA", Command::FrequencyData, Form::Query),
    ("CALCulate:ALIas:DATA", Command::AliasData, Form::Query),
    ("SCOPe:VOLTs", Command::ScopeVolts, Form::Both),
    ("SCOPe:TIME", Command::ScopeTime, Form::Both),
    ("SCOPe:TRIGger[:LEVel]", Command::ScopeTrigger, Form::Both),
    ("SCOPe:MODE", Command::ScopeMode, Form::Both),
    ("SCOPe:ARM", Command::ScopeArm, Form::Event),
    ("SCOPe:DATA", Command::ScopeData, Form::Query),
    ("SCOPe:X:DATA", Command::ScopeTimeData, Form::Query),
];

/// The command and form of a resolved header path, if the tree has it.
pub fn find(path: &[String]) -> Option<(Command, Form)> {
    TREE.iter()
        .find(|(pattern, _, _)| matches(&nodes(pattern), path))
        .map(|&(_, command, form)| (command, form))
}

/// A pattern's nodes: (spelling, optional).
fn nodes(pattern: &str) -> Vec<(&str, bool)> {
    let mut out = Vec::new();
    let mut rest = pattern;
    while !rest.is_empty() {
        if let Some(inner) = rest.strip_prefix('[') {
            let end = inner.find(']').unwrap_or(inner.len());
            let node = inner[..end].trim_matches(':');
            out.push((node, true));
            rest = inner.get(end + 1..).unwrap_or("").trim_start_matches(':');
        } else {
            let end = rest.find([':', '[']).unwrap_or(rest.len());
            out.push((&rest[..end], false));
            rest = rest[end..].trim_start_matches(':');
        }
    }
    out
}

fn matches(nodes: &[(&str, bool)], path: &[String]) -> bool {
    match (nodes.split_first(), path.split_first()) {
        (None, None) => true,
        (None, Some(_)) => false,
        (Some((&(_, true), rest)), None) => matches(rest, path),
        (Some(_), None) => false,
        (Some((&(spelling, optional), rest)), Some((first, tail))) => {
            (mnemonic_matches(spelling, first) && matches(rest, tail))
                || (optional && matches(rest, path))
        }
    }
}

/// Whether `written` (upper-cased) is `spelling`'s short or long form, with an optional
/// numeric suffix 1 (`INPut1`).
fn mnemonic_matches(spelling: &str, written: &str) -> bool {
    let long = spelling.to_ascii_uppercase();
    let short: String = spelling
        .chars()
        .take_while(|c| !c.is_ascii_lowercase())
        .collect();
    let bare = written.strip_suffix('1').unwrap_or(written);
    [written, bare].iter().any(|w| *w == long || *w == short)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn path(text: &str) -> Vec<String> {
        text.split(':').map(str::to_string).collect()
    }

    #[test]
    fn short_and_long_forms_and_optional_nodes_find_the_same_command() {
        for header in [
            "SENS:FREQ:SPAN",
            "SENSE:FREQUENCY:SPAN",
            "FREQ:SPAN",
            "SENSE1:FREQ:SPAN",
        ] {
            assert_eq!(
                find(&path(header)),
                Some((Command::Span, Form::Both)),
                "{header}"
            );
        }
        assert_eq!(find(&path("INIT")).map(|c| c.0), Some(Command::Initiate));
        assert_eq!(
            find(&path("INIT:IMM")).map(|c| c.0),
            Some(Command::Initiate)
        );
        assert_eq!(
            find(&path("AVER")).map(|c| c.0),
            Some(Command::AverageState)
        );
        assert_eq!(
            find(&path("SYST:ERR:NEXT")).map(|c| c.0),
            Some(Command::NextError)
        );
        assert_eq!(
            find(&path("SYST:ERR:COUN")).map(|c| c.0),
            Some(Command::ErrorCount)
        );
        assert_eq!(find(&path("*IDN")).map(|c| c.0), Some(Command::Identify));
    }

    #[test]
    fn forms_between_short_and_long_are_not_commands() {
        for header in [
            "FREQU:SPAN",
            "SENS:FRE:SPAN",
            "SENS",
            "RIG:SPEE",
            "SENS:FREQ:SPAN:X",
        ] {
            assert_eq!(find(&path(header)), None, "{header}");
        }
    }
}
