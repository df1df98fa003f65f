//! The chain's stages as a scenario declares them: the standard table with the inputs the
//! file chose, then its `[[chain.stage]]` entries; wired, ordered and built once, each
//! fault reported at the line of the table it comes from.

use std::ops::Range;

use toml::Spanned;

use super::chain_toml::{ChainFile, StageFile};
use super::read_instrument::{filter_spec, meter_settings};
use super::source::ScenarioSource;
use crate::chain::{
    ChainStages, Instrument, StagePlan, StandardChain, WiringError, standard_stages,
};
use crate::vocabulary::frame::SignalNames;
use crate::vocabulary::signal_names::{
    AMPLIFIER_V, BRIDGE_V, CARRIER_V, DVM_V, FILTER_V, METER_V, SLIP_RING_V, STRAIN, TACHO_V,
};

/// Where a stage is written: its table's field and lines (settings, and the input when
/// the file names it).
struct Origin {
    output: String,
    field: String,
    span: Range<usize>,
    input_span: Option<Range<usize>>,
}

/// The standard stages and the file's own on the `plant`'s signals, in running order, each
/// built once on a stream at `rate_hz` to check it (`band_hz`: the analyser's Fmax).
pub fn wired_stages(
    src: &ScenarioSource,
    chain: &ChainFile,
    standard: &StandardChain,
    plant: &SignalNames,
    (rate_hz, band_hz): (f64, Option<f64>),
) -> anyhow::Result<ChainStages> {
    let mut plans = standard_stages(standard);
    let mut origins: Vec<Origin> = plans
        .iter()
        .map(|p| standard_origin(chain, &p.output))
        .collect();
    for (i, file) in chain.stage.iter().enumerate() {
        let field = format!("chain.stage #{}", i + 1);
        plans.push(further_stage(src, file, &field, rate_hz, band_hz)?);
        origins.push(Origin {
            output: file.output.get_ref().clone(),
            field,
            span: file.output.span(),
            input_span: Some(file.input.span()),
        });
    }
    let stages =
        ChainStages::ordered_on(plans, plant).map_err(|e| wiring_error(src, &origins, &e))?;
    stages
        .build(rate_hz, &mut plant.clone())
        .map_err(|e| wiring_error(src, &origins, &e))?;
    Ok(stages)
}

/// The signal a reader (analyser, scope, recording) names at `field`, or `default` when
/// the file names none; it must be one of the run's signals `names`.
pub fn read_signal_among(
    src: &ScenarioSource,
    names: &SignalNames,
    given: Option<&Spanned<String>>,
    field: &str,
    default: &str,
) -> anyhow::Result<String> {
    let (name, span) = given.map_or((default, 0..0), |g| (g.get_ref().as_str(), g.span()));
    if names.index(name).is_none() {
        return Err(src.error(
            span,
            field,
            format!(
                "`{name}` is not a signal of this run; known: {}",
                names.names().join(", ")
            ),
        ));
    }
    Ok(name.to_string())
}

fn further_stage(
    src: &ScenarioSource,
    file: &StageFile,
    field: &str,
    rate_hz: f64,
    band_hz: Option<f64>,
) -> anyhow::Result<StagePlan> {
    let nested_input = [
        file.lowpass.as_ref().and_then(|l| l.input.as_ref()),
        file.meter.as_ref().and_then(|m| m.input.as_ref()),
    ];
    if let Some(input) = nested_input.into_iter().flatten().next() {
        return Err(src.error(
            input.span(),
            &format!("{field}.input"),
            "give the stage's input beside its `output`, not inside its instrument",
        ));
    }
    let lowpass_field = format!("{field}.lowpass");
    let given = [
        file.lowpass.as_ref().map(|l| {
            filter_spec(src, l, &lowpass_field, rate_hz, band_hz).map(Instrument::LowPass)
        }),
        file.meter
            .as_ref()
            .map(|m| Ok(Instrument::Meter(meter_settings(m)))),
        file.ac_coupling
            .as_ref()
            .map(|a| Ok(Instrument::AcCoupling(a.corner_hz.0))),
    ];
    let mut given: Vec<Instrument> = given.into_iter().flatten().collect::<anyhow::Result<_>>()?;
    let (Some(instrument), true) = (given.pop(), given.is_empty()) else {
        return Err(src.error(
            file.output.span(),
            field,
            "give exactly one instrument: `lowpass = { ... }`, `meter = { ... }` or `ac_coupling = { ... }`",
        ));
    };
    Ok(StagePlan {
        output: file.output.get_ref().clone(),
        inputs: vec![file.input.get_ref().clone()],
        instrument,
    })
}

fn standard_origin(chain: &ChainFile, output: &str) -> Origin {
    let first = |spans: &[Option<Range<usize>>]| spans.iter().flatten().next().cloned();
    let a = &chain.amplifier;
    let amplifier = first(&[
        a.carrier_hz.as_ref().map(Spanned::span),
        a.output_lowpass_hz.as_ref().map(Spanned::span),
    ]);
    let input = |i: &Option<Spanned<String>>| i.as_ref().map(Spanned::span);
    let (field, span, input_span) = match output {
        STRAIN | BRIDGE_V => ("chain.gauges", None, None),
        CARRIER_V | AMPLIFIER_V => ("chain.amplifier", amplifier, None),
        SLIP_RING_V => ("chain.slip_rings", None, None),
        FILTER_V => (
            "chain.filter",
            Some(chain.filter.order.span()),
            input(&chain.filter.input),
        ),
        METER_V => (
            "chain.meter",
            Some(chain.meter.ac_coupling_hz.span()),
            input(&chain.meter.input),
        ),
        TACHO_V => ("chain.tacho", None, None),
        DVM_V => ("chain.tacho", Some(chain.tacho.gate_s.span()), None),
        _ => ("chain", None, None),
    };
    Origin {
        output: output.to_string(),
        field: field.to_string(),
        span: span.unwrap_or(0..0),
        input_span,
    }
}

fn wiring_error(src: &ScenarioSource, origins: &[Origin], e: &WiringError) -> anyhow::Error {
    let Some(origin) = origins.iter().rev().find(|o| o.output == e.output()) else {
        return anyhow::anyhow!("{}: chain: {e}", src.path.display());
    };
    match e {
        WiringError::UnknownInput { .. } => src.error(
            origin.input_span.clone().unwrap_or(origin.span.clone()),
            &format!("{}.input", origin.field),
            e,
        ),
        WiringError::DuplicateOutput { .. } => {
            src.error(origin.span.clone(), &format!("{}.output", origin.field), e)
        }
        WiringError::Instrument { .. } => src.error(origin.span.clone(), &origin.field, e),
    }
}
