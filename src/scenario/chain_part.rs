//! The measuring chain, the analyser and the recordings of a scenario.

use instruments::{
    AcCoupling, Adc, AdcSettings, Analyser, AnalyserSettings, AntiAliasFilter, Averaging,
    BridgeArrangement, CarrierDemodulator, CarrierSettings, LowPassSpec, Sampling, Scope,
    ScopeSettings, ShaftStrain, SlipRingSettings, Slope, Spectrum, StrainBridge, SweepMode,
};
use toml::Spanned;

use super::chain_file::DEFAULT_CUTOFF_HZ;
use super::file::{AnalyserFile, ChainFile, RecordFile};
use super::plan::{AnalyserPlan, ChainPlan, DvmSettings, MeterSettings, RecordPlan, WavFormat};
use super::source::ScenarioSource;
use crate::signal_catalog;

/// Carrier frequency when the scenario gives none and the stream allows it (Hz).
pub const DEFAULT_CARRIER_HZ: f64 = 10_000.0;

/// The chain's settings, each checked by building the instrument once. `band_hz` is the
/// analyser's Fmax, the anti-alias filter's cut-off when the file gives none.
pub fn chain_plan(
    src: &ScenarioSource,
    chain: &ChainFile,
    rate_hz: f64,
    seed: u64,
    band_hz: Option<f64>,
) -> anyhow::Result<ChainPlan> {
    let g = &chain.gauges;
    let arrangement = BridgeArrangement::from(g.arrangement);
    let mut bridge = StrainBridge::new(arrangement, g.gauge_factor.0, g.excitation_v.0)
        .map_err(|e| src.error(0..0, "chain.gauges", e))?;
    bridge.gauge_factor_error = g.gauge_factor_error.0;
    let carrier = carrier_settings(src, chain, &bridge, rate_hz)?;
    let slip_rings = chain.slip_rings.as_ref().map(|s| SlipRingSettings {
        broadband_rms: s.broadband_rms.0,
        per_rev_amplitude: s.per_rev_amplitude.0,
        contact_noise_v_rms: s.contact_noise_v_rms.0,
        seed: seed.wrapping_add(1),
    });
    Ok(ChainPlan {
        shaft: ShaftStrain::intermediate_shaft(),
        bridge,
        carrier,
        slip_rings,
        filter: filter_spec(src, chain, rate_hz, band_hz)?,
        meter: meter_settings(src, chain, rate_hz)?,
        dvm: dvm_settings(src, chain, rate_hz)?,
        scope: scope_settings(src, chain, rate_hz)?,
    })
}

fn carrier_settings(
    src: &ScenarioSource,
    chain: &ChainFile,
    bridge: &StrainBridge,
    rate_hz: f64,
) -> anyhow::Result<CarrierSettings> {
    let a = &chain.amplifier;
    let carrier_hz = a
        .carrier_hz
        .as_ref()
        .map_or(DEFAULT_CARRIER_HZ.min(rate_hz / 5.0), |c| c.get_ref().0);
    let settings = CarrierSettings {
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
    };
    let span = [&a.carrier_hz, &a.output_lowpass_hz]
        .into_iter()
        .flatten()
        .next()
        .map_or(0..0, Spanned::span);
    CarrierDemodulator::new(settings, rate_hz)
        .map_err(|e| src.error(span, "chain.amplifier", e))?;
    Ok(settings)
}

fn filter_spec(
    src: &ScenarioSource,
    chain: &ChainFile,
    rate_hz: f64,
    band_hz: Option<f64>,
) -> anyhow::Result<Option<LowPassSpec>> {
    let f = &chain.filter;
    let kind = f.kind.kind();
    let Some(kind) = kind else {
        return Ok(None);
    };
    let (cutoff, span, origin) = match &f.cutoff_hz {
        Some(c) => (c.get_ref().0, c.span(), ""),
        None => match band_hz {
            Some(band) => (band, 0..0, " (left out: the analyser's fmax_hz)"),
            None => (DEFAULT_CUTOFF_HZ, 0..0, " (left out: the default)"),
        },
    };
    if cutoff >= rate_hz / 2.0 {
        return Err(src.error(
            span,
            "chain.filter.cutoff_hz",
            format!(
                "{cutoff} Hz{origin} is at or above the analogue Nyquist rate {} Hz (half of rate_hz); a cut-off below it is allowed",
                rate_hz / 2.0
            ),
        ));
    }
    let spec = LowPassSpec {
        kind,
        order: *f.order.get_ref(),
        cutoff_hz: cutoff,
    };
    AntiAliasFilter::new(Some(spec), rate_hz)
        .map_err(|e| src.error(f.order.span(), "chain.filter", e))?;
    Ok(Some(spec))
}

fn meter_settings(
    src: &ScenarioSource,
    chain: &ChainFile,
    rate_hz: f64,
) -> anyhow::Result<MeterSettings> {
    let settings = MeterSettings {
        detector: chain.meter.detector.into(),
        tau_s: chain.meter.tau_s.0,
        ac_coupling_hz: chain.meter.ac_coupling_hz.get_ref().0,
    };
    settings
        .build(rate_hz)
        .map_err(|e| src.error(chain.meter.ac_coupling_hz.span(), "chain.meter", e))?;
    Ok(settings)
}

/// The tacho's DVM, checked by building it (a gate shorter than one sample fails here,
/// at its line, not at run time).
fn dvm_settings(
    src: &ScenarioSource,
    chain: &ChainFile,
    rate_hz: f64,
) -> anyhow::Result<DvmSettings> {
    let t = &chain.tacho;
    let settings = DvmSettings {
        gate_s: t.gate_s.get_ref().0,
        tau_s: t.tau_s.0,
        resolution_v: t.resolution_v.0,
    };
    settings
        .build(rate_hz)
        .map_err(|e| src.error(t.gate_s.span(), "chain.tacho", e))?;
    Ok(settings)
}

fn scope_settings(
    src: &ScenarioSource,
    chain: &ChainFile,
    rate_hz: f64,
) -> anyhow::Result<Option<(ScopeSettings, f64)>> {
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
    Ok(Some((settings, coupling)))
}

/// The analyser's and ADC's settings.
pub fn analyser_plan(
    src: &ScenarioSource,
    file: &AnalyserFile,
    rate_hz: f64,
    seed: u64,
) -> anyhow::Result<AnalyserPlan> {
    let window = file.window.0;
    let sampling = Sampling::from(file.sampling);
    let overlap = file.overlap_pct.as_ref().map_or(0.0, |o| o.get_ref().0);
    if overlap >= 100.0 {
        let span = file.overlap_pct.as_ref().map_or(0..0, Spanned::span);
        return Err(src.error(span, "analyser.overlap_pct", "must lie in [0, 100)"));
    }
    let settings = AnalyserSettings {
        block: *file.block.get_ref(),
        fmax_hz: file.fmax_hz.get_ref().0,
        sampling,
        window,
        spectrum: Spectrum::Power,
        averaging: Averaging::Linear,
        averages: *file.averages.get_ref(),
        overlap: overlap / 100.0,
    };
    Analyser::new(settings).map_err(|e| src.error(file.block.span(), "analyser", e))?;
    let ratio = rate_hz / settings.sample_rate_hz();
    if ratio < 1.0 {
        return Err(src.error(
            file.fmax_hz.span(),
            "analyser.fmax_hz",
            format!(
                "needs an ADC rate of {} Hz, above the stream rate {rate_hz} Hz",
                settings.sample_rate_hz()
            ),
        ));
    }
    let adc = AdcSettings {
        ratio,
        bits: *file.bits.get_ref(),
        range_v: file.range_v.0,
        dither_seed: file.dither.then_some(seed.wrapping_add(2)),
    };
    Adc::new(adc).map_err(|e| src.error(file.bits.span(), "analyser.bits", e))?;
    Ok(AnalyserPlan { settings, adc })
}

/// What to record, with each name checked.
pub fn record_plan(
    src: &ScenarioSource,
    file: &RecordFile,
    slip_rings: bool,
) -> anyhow::Result<RecordPlan> {
    let mut signals = Vec::new();
    for name in &file.signals {
        let n = name.get_ref();
        let wired = signal_catalog::is_known(n) && (slip_rings || n != "slip_ring_v");
        if !wired {
            return Err(src.error(
                name.span(),
                "record.signals",
                format!(
                    "`{n}` is not a signal of this run; known: {}",
                    signal_catalog::all_names()
                ),
            ));
        }
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
                file.full_scale
                    .get(s)
                    .map_or(signal_catalog::default_full_scale(s), |v| v.get_ref().0)
            })
            .collect(),
        signals,
        wav: None,
        csv: false,
        uff58: false,
        decimate: (*file.decimate.get_ref()).max(1),
    };
    if *file.decimate.get_ref() == 0 {
        return Err(src.error(file.decimate.span(), "record.decimate", "must be ≥ 1"));
    }
    let wav_format = WavFormat::from(file.wav_format);
    for format in &file.formats {
        match format.get_ref().as_str() {
            "wav" => plan.wav = Some(wav_format),
            "csv" => plan.csv = true,
            "uff58" => plan.uff58 = true,
            other => {
                return Err(src.error(
                    format.span(),
                    "record.formats",
                    format!("`{other}` is not one of wav, csv, uff58"),
                ));
            }
        }
    }
    Ok(plan)
}
