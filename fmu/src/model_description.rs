//! `modelDescription.xml` of a rig's FMU (FMI 3.0, co-simulation only), its model
//! identifier and instantiation token. No date in it: the same rig gives the same bytes.

use std::fmt::Write;

use rig::RigTopology;

use crate::error::FmuError;
use crate::units::{UNITS, unit_definition};
use crate::variables::{Causality, Kind, SAMPLE_RATE_HZ, Variable, variables};

/// The name of the rig's file among the FMU's resources.
pub const RIG_RESOURCE: &str = "rig.json";

/// A C identifier for the rig's FMU: `testrig_` and its name, every other character `_`.
pub fn model_identifier(rig: &RigTopology) -> String {
    let name: String = rig
        .name
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    format!("testrig_{name}")
}

/// The instantiation token of the FMU whose rig resource is `rig_json`: an FNV-1a hash
/// of its bytes, so that the binary refuses a model description and a rig that differ.
pub fn instantiation_token(rig_json: &str) -> String {
    let hash = rig_json.bytes().fold(0xcbf2_9ce4_8422_2325_u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    });
    format!("{{testrig-{hash:016x}}}")
}

/// The model description of `rig`'s FMU, whose rig resource is `rig_json`; `tool` names
/// the generating program and its version.
pub fn model_description(
    rig: &RigTopology,
    rig_json: &str,
    tool: &str,
) -> Result<String, FmuError> {
    let vars = variables(rig);
    let mut xml = String::new();
    let description = if rig.description.is_empty() {
        format!("the rig {} of a testrig rig file", rig.name)
    } else {
        rig.description.clone()
    };
    let _ = writeln!(xml, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let _ = writeln!(
        xml,
        r#"<fmiModelDescription fmiVersion="3.0" modelName="{}" instantiationToken="{}" description="{}" generationTool="{}" variableNamingConvention="flat">"#,
        escape(&rig.name),
        instantiation_token(rig_json),
        escape(&description),
        escape(tool)
    );
    let _ = writeln!(
        xml,
        r#"  <CoSimulation modelIdentifier="{}" canHandleVariableCommunicationStepSize="true" fixedInternalStepSize="{:?}" canGetAndSetFMUState="true" canSerializeFMUState="false" providesIntermediateUpdate="false" hasEventMode="false"/>"#,
        model_identifier(rig),
        1.0 / SAMPLE_RATE_HZ
    );
    write_units(&mut xml, &vars)?;
    xml.push_str(concat!(
        "  <LogCategories>\n",
        "    <Category name=\"logStatusError\" description=\"a refused call or value, a plant that failed\"/>\n",
        "    <Category name=\"logStep\" description=\"each communication step: samples advanced, impacts\"/>\n",
        "  </LogCategories>\n",
        "  <DefaultExperiment startTime=\"0\" stopTime=\"5\" stepSize=\"0.001\"/>\n",
        "  <ModelVariables>\n",
    ));
    for v in &vars {
        write_variable(&mut xml, v);
    }
    xml.push_str("  </ModelVariables>\n  <ModelStructure>\n");
    let outputs = vars.iter().filter(|v| v.causality == Causality::Output);
    for v in outputs.clone() {
        let _ = writeln!(
            xml,
            r#"    <Output valueReference="{}"/>"#,
            v.value_reference
        );
    }
    for v in outputs {
        let _ = writeln!(
            xml,
            r#"    <InitialUnknown valueReference="{}"/>"#,
            v.value_reference
        );
    }
    xml.push_str("  </ModelStructure>\n</fmiModelDescription>\n");
    Ok(xml)
}

/// `<UnitDefinitions>`: each unit a variable names, in [`UNITS`]'s order.
fn write_units(xml: &mut String, vars: &[Variable]) -> Result<(), FmuError> {
    for v in vars.iter().filter(|v| !v.unit.is_empty()) {
        if unit_definition(v.unit).is_none() {
            return Err(FmuError(format!(
                "variable {} names the unit `{}`, which the FMU cannot define",
                v.name, v.unit
            )));
        }
    }
    xml.push_str("  <UnitDefinitions>\n");
    for u in UNITS
        .iter()
        .filter(|u| vars.iter().any(|v| v.unit == u.name))
    {
        let mut base = String::new();
        for (symbol, power) in ["kg", "m", "s", "A", "rad"].iter().zip(u.exponents) {
            if power != 0 {
                let _ = write!(base, r#" {symbol}="{power}""#);
            }
        }
        if u.factor != 1.0 {
            let _ = write!(base, r#" factor="{:?}""#, u.factor);
        }
        let _ = writeln!(
            xml,
            r#"    <Unit name="{}"><BaseUnit{base}/></Unit>"#,
            escape(u.name)
        );
    }
    xml.push_str("  </UnitDefinitions>\n");
    Ok(())
}

fn write_variable(xml: &mut String, v: &Variable) {
    let (element, variability, initial) = match (v.kind, v.causality) {
        (Kind::Float64, Causality::Parameter) => ("Float64", "fixed", Some("exact")),
        (Kind::Float64, Causality::Output) => ("Float64", "continuous", Some("calculated")),
        (Kind::Float64, _) => ("Float64", "continuous", None),
        (Kind::Int32, _) => ("Int32", "discrete", Some("calculated")),
        (Kind::Int64, _) => ("Int64", "discrete", Some("calculated")),
    };
    let causality = match v.causality {
        Causality::Independent => "independent",
        Causality::Parameter => "parameter",
        Causality::Input => "input",
        Causality::Output => "output",
    };
    let _ = write!(
        xml,
        r#"    <{element} name="{}" valueReference="{}" description="{}" causality="{causality}" variability="{variability}""#,
        escape(&v.name),
        v.value_reference,
        escape(&v.description)
    );
    if let Some(initial) = initial {
        let _ = write!(xml, r#" initial="{initial}""#);
    }
    if !v.unit.is_empty() {
        let _ = write!(xml, r#" unit="{}""#, escape(v.unit));
    }
    if let Some(min) = v.range.0 {
        let _ = write!(xml, r#" min="{min:?}""#);
    }
    if let Some(max) = v.range.1 {
        let _ = write!(xml, r#" max="{max:?}""#);
    }
    if let Some(start) = v.start {
        let _ = write!(xml, r#" start="{start:?}""#);
    }
    xml.push_str("/>\n");
}

/// `text` with XML's five special characters escaped.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if (c as u32) < 0x20 && c != '\t' => out.push(' '),
            c => out.push(c),
        }
    }
    out
}
