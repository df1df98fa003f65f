//! The measuring chain, the analyser and the recordings of a scenario.

use instruments::{
    AcCoupling, BridgeArrangement, CarrierSettings, Sampling, Scope, ScopeSettings, ShaftStrain,
    SlipRingSettings, Slope, StrainBridge, SweepMode,
};
use toml::Spanned;

use super::chain_toml::AmplifierFile;
use super::read_instrument::{filter_spec, meter_settings};
use super::read_stages::{read_signal_among, wired_stages};
use super::run_plan::{AnalyserPlan, ChainPlan, RecordPlan, ScopePlan};
use super::scenario_toml::{AnalyserFile, ChainFile, RecordFile};
use super::source::ScenarioSource;
use crate::chain::analyser_setup::{AdcChoice, AnalyserSetting, AnalyserWords};
use crate::chain::{DvmSettings, StandardChain};
use crate::vocabulary::choices::RecordFormatChoice;
use crate::vocabulary::choices::WavFormat;
use crate::vocabulary::frame::SignalNames;
use crate::vocabulary::seeds::NoiseSource;
use crate::vocabulary::signal_names::{AMPLIFIER_V, FILTER_V};

/// Carrier frequency when the scenario gives none and the stream allows it (Hz).
pub const DEFAULT_CARRIER_HZ: f64 = 10_000.0;

/// The plant's signals the chain reads, the stream's rate, the seed and the analyser's
/// band: what a chain is planned on.
#[derive(Clone, Copy, Debug)]
pub struct ChainSetting<'a> {
    /// The plant's signals (`crate::rig_roles::plant_signals`).
    pub plant: &'a SignalNames,
    /// The stream's rate (Hz).
    pub rate_hz: f64,
    /// The run's base seed.
    pub seed: u64,
    /// The analyser's Fmax, the anti-alias filter's cut-off when the file gives none (Hz).
    pub band_hz: Option<f64>,
}

/// The chain's stages and scope on the plant's signals, each instrument checked by
/// building it once, as the run builds it; every input must be a plant signal or a
/// stage's output.
pub fn chain_plan(
    src: &ScenarioSource,
    chain: &ChainFile,
    setting: ChainSetting,
) -> anyhow::Result<ChainPlan> {
    let ChainSetting {
        plant,
        rate_hz,
        seed,
        band_hz,
    } = setting;
    let standard = standard_chain(src, chain, rate_hz, seed, band_hz)?;
    let stages = wired_stages(src, chain, &standard, plant, (rate_hz, band_hz))?;
    let scope = scope_plan(src, chain, rate_hz, &stages.signal_names_on(plant))?;
    Ok(ChainPlan {
        stages,
        strain_per_nm: standard.shaft.strain_per_nm(),
        volts_per_nm: standard.volts_per_nm(),
        scope,
    })
}

fn standard_chain(
    src: &ScenarioSource,
    chain: &ChainFile,
    rate_hz: f64,
    seed: u64,
    band_hz: Option<f64>,
) -> anyhow::Result<StandardChain> {
    let g = &chain.gauges;
    let arrangement = BridgeArrangement::from(g.arrangement);
    let mut bridge = StrainBridge::new(arrangement, g.gauge_factor.0, g.excitation_v.0)
        .map_err(|e| src.error(0..0, "chain.gauges", e))?;
    bridge.gauge_factor_error = g.gauge_factor_error.0;
    let slip_rings = chain.slip_rings.as_ref().map(|s| SlipRingSettings {
        broadband_rms: s.broadband_rms.0,
        per_rev_amplitude: s.per_rev_amplitude.0,
        contact_noise_v_rms: s.contact_noise_v_rms.0,
        seed: NoiseSource::SlipRings.seed(seed),
    });
    let input = |i: &Option<Spanned<String>>| i.as_ref().map(|i| i.get_ref().clone());
    let t = &chain.tacho;
    Ok(StandardChain {
        shaft: ShaftStrain::intermediate_shaft(),
        carrier: carrier_settings(&chain.amplifier, &bridge, rate_hz),
        bridge,
        slip_rings,
        filter: filter_spec(src, &chain.filter, "chain.filter", rate_hz, band_hz)?,
        filter_input: input(&chain.filter.input),
        meter: meter_settings(&chain.meter),
        meter_input: input(&chain.meter.input),
        dvm: DvmSettings {
            gate_s: t.gate_s.get_ref().0,
            tau_s: t.tau_s.0,
            resolution_v: t.resolution_v.0,
        },
    })
}

fn carrier_settings(a: &AmplifierFile, bridge: &StrainBridge, rate_hz: f64) -> CarrierSettings {
    let carrier_hz = a
        .carrier_hz
        .as_ref()
        .map_or(DEFAULT_CARRIER_HZ.min(rate_hz / 5.0), |c| c.get_ref().0);
    CarrierSettings {
        carrier_hz,
        output_lowpass_hz: a
            .output_lowpass_hz
            .as_ref()
            .map_or(carrier_hz / 2.0, |l| l.get_ref().0),
        gain: CarrierSettings::calibrated_gain(
            a.calibration_microstrain.0,
            a.calibration_v.0,
            bridge.output_v(1.0),
        ),
    }
}

fn scope_plan(
    src: &ScenarioSource,
    chain: &ChainFile,
    rate_hz: f64,
    names: &SignalNames,
) -> anyhow::Result<Option<ScopePlan>> {
    let Some(s) = &chain.scope else {
        return Ok(None);
    };
    let slope = Slope::from(s.slope);
    let settings = ScopeSettings {
        volts_per_div: s.volts_per_div.0,
        seconds_per_div: s.seconds_per_div.get_ref().0,
        trigger_v: s.trigger_v.0,
        slope,
        mode: SweepMode::Single,
    };
    Scope::new(settings, rate_hz)
        .map_err(|e| src.error(s.seconds_per_div.span(), "chain.scope", e))?;
    let coupling = s.ac_coupling_hz.get_ref().0;
    if coupling > 0.0 {
        AcCoupling::new(coupling, rate_hz)
            .map_err(|e| src.error(s.ac_coupling_hz.span(), "chain.scope.ac_coupling_hz", e))?;
    }
    Ok(Some(ScopePlan {
        settings,
        ac_coupling_hz: coupling,
        input: read_signal_among(
            src,
            names,
            s.input.as_ref(),
            "chain.scope.input",
            AMPLIFIER_V,
        )?,
    }))
}

/// The analyser's and ADC's settings.
pub fn analyser_plan(
    src: &ScenarioSource,
    file: &AnalyserFile,
    rate_hz: f64,
    seed: u64,
) -> anyhow::Result<AnalyserPlan> {
    let overlap_pct = file.overlap_pct.as_ref().map_or(0.0, |o| o.get_ref().0);
    let words = AnalyserWords {
        fmax_hz: file.fmax_hz.get_ref().0,
        block: *file.block.get_ref(),
        window: file.window.0,
        averages: *file.averages.get_ref(),
        overlap: overlap_pct / 100.0,
        sampling: Sampling::from(file.sampling),
        adc: AdcChoice {
            bits: *file.bits.get_ref(),
            range_v: file.range_v.0,
            dither_seed: file.dither.then_some(NoiseSource::AdcDither.seed(seed)),
        },
    };
    let setup = words.set_up(rate_hz).map_err(|e| {
        let (span, field) = match e.setting() {
            AnalyserSetting::Block => (file.block.span(), "analyser"),
            AnalyserSetting::FmaxHz => (file.fmax_hz.span(), "analyser.fmax_hz"),
            AnalyserSetting::Averages => (file.averages.span(), "analyser.averages"),
            AnalyserSetting::OverlapPct => (
                file.overlap_pct.as_ref().map_or(0..0, Spanned::span),
                "analyser.overlap_pct",
            ),
            AnalyserSetting::Adc => (file.bits.span(), "analyser.bits"),
        };
        src.error(span, field, e)
    })?;
    Ok(AnalyserPlan {
        input: file
            .input
            .as_ref()
            .map_or(FILTER_V.to_string(), |i| i.get_ref().clone()),
        settings: setup.settings,
        adc: setup.adc_settings,
    })
}

/// What to record, with each name checked against the run's signals.
/// The recording `file` asks for, each signal one of `names` (the run's signals).
pub fn record_plan(
    src: &ScenarioSource,
    file: &RecordFile,
    chain: &ChainPlan,
    names: &SignalNames,
) -> anyhow::Result<RecordPlan> {
    let mut signals = Vec::new();
    for name in &file.signals {
        let n = name.get_ref();
        read_signal_among(src, names, Some(name), "record.signals", n)?;
        signals.push(n.clone());
    }
    if signals.is_empty() {
        return Err(src.error(0..0, "record.signals", "name at least one signal"));
    }
    if let Some((name, value)) = file.full_scale.iter().find(|(n, _)| !signals.contains(n)) {
        return Err(src.error(
            value.span(),
            &format!("record.full_scale.{name}"),
            "is not one of the recorded signals",
        ));
    }
    let mut plan = RecordPlan {
        full_scale: signals
            .iter()
            .map(|s| {
                file.full_scale.get(s).map_or_else(
                    || chain.stages.full_scale_of(s).unwrap_or(1.0),
                    |v| v.get_ref().0,
                )
            })
            .collect(),
        signals,
        wav: None,
        csv: false,
        uff58: false,
        decimate: (*file.decimate.get_ref()).max(1),
        from_start: file.from_start,
    };
    if *file.decimate.get_ref() == 0 {
        return Err(src.error(file.decimate.span(), "record.decimate", "must be ≥ 1"));
    }
    let wav_format = WavFormat::from(file.wav_format);
    for format in &file.formats {
        match format {
            RecordFormatChoice::Wav => plan.wav = Some(wav_format),
            RecordFormatChoice::Csv => plan.csv = true,
            RecordFormatChoice::Uff58 => plan.uff58 = true,
        }
    }
    Ok(plan)
}
