//! Speed of the measuring chain: spectra per second of the analyser, and the whole strain
//! chain on one second of a 51.2 kHz stream (the inverse real-time factor).

use divan::Bencher;
use instruments::{
    Adc, AdcSettings, Analyser, AnalyserSettings, AntiAliasFilter, Block, BridgeArrangement,
    CarrierDemodulator, CarrierModulator, CarrierSettings, Detector, FilterKind, LowPassSpec,
    ShaftStrain, SlipRing, SlipRingSettings, Spectrum, SpectrumEstimator, StrainBridge, Voltmeter,
    Window,
};

fn main() {
    divan::main();
}

const RATE: f64 = 51_200.0;

#[divan::bench(args = [1024, 8192])]
fn analyser_spectrum(bencher: Bencher, n: usize) {
    let mut estimator = SpectrumEstimator::new(n, 4_000.0, Window::Hanning).expect("valid");
    let block: Vec<f64> = (0..n).map(|k| (k as f64 * 0.1).sin()).collect();
    let mut out = vec![0.0; estimator.lines()];
    bencher.bench_local(|| estimator.spectrum(divan::black_box(&block), Spectrum::Power, &mut out));
}

/// Torque → strain → full bridge → carrier modulator → slip rings → demodulator →
/// 400E beside, and → 8th-order Butterworth at 2 kHz → ADC (64 kHz/16 = 4 kHz would need
/// 64 kHz; here 51.2 kHz/12, 4.27 kHz) → analyser; one simulated second per iteration.
#[divan::bench(sample_count = 20)]
fn strain_chain_one_second(bencher: Bencher) {
    let n = RATE as usize;
    let torque: Vec<f64> = (0..n)
        .map(|k| 2.712 + 5.0 * (2.0 * std::f64::consts::PI * 21.7 * k as f64 / RATE).sin())
        .collect();
    let carrier = CarrierSettings {
        carrier_hz: 5_000.0,
        output_lowpass_hz: 1_000.0,
        gain: 100.0,
    };
    let mut strain = ShaftStrain::intermediate_shaft();
    let mut bridge = StrainBridge::new(BridgeArrangement::Full, 2.1, 10.0).expect("valid");
    let mut modulator = CarrierModulator::new(carrier, RATE).expect("valid");
    let rings = SlipRingSettings {
        broadband_rms: 0.001,
        per_rev_amplitude: 0.01,
        contact_noise_v_rms: 1e-5,
        seed: 1,
    };
    let mut slip = SlipRing::new(rings, RATE, 21.7).expect("valid");
    let mut demodulator = CarrierDemodulator::new(carrier, RATE).expect("valid");
    let mut meter = Voltmeter::new(Detector::AverageRmsCalibrated, RATE, 0.2).expect("valid");
    let spec = LowPassSpec {
        kind: FilterKind::Butterworth,
        order: 8,
        cutoff_hz: 2_000.0,
    };
    let mut filter = AntiAliasFilter::new(Some(spec), RATE).expect("valid");
    let mut adc = Adc::new(AdcSettings {
        ratio: 12.0,
        bits: 12,
        range_v: 10.0,
        dither_seed: None,
    })
    .expect("valid");
    let settings = AnalyserSettings {
        averages: usize::MAX,
        ..AnalyserSettings::thesis(1024, RATE / 12.0 / 2.0)
    };
    let mut analyser = Analyser::new(settings).expect("valid");
    let (mut a, mut b) = (vec![0.0; 2048], vec![0.0; 2048]);
    let mut samples = Vec::with_capacity(256);
    bencher.bench_local(|| {
        for chunk in torque.chunks(2048) {
            let len = chunk.len();
            strain.process(chunk, &mut a[..len]);
            bridge.process(&a[..len], &mut b[..len]);
            modulator.process(&b[..len], &mut a[..len]);
            slip.process(&a[..len], &mut b[..len]);
            demodulator.process(&b[..len], &mut a[..len]);
            meter.process(&a[..len], &mut b[..len]);
            filter.process(&a[..len], &mut b[..len]);
            samples.clear();
            adc.convert(&b[..len], &mut samples);
            analyser.push(&samples);
        }
        analyser.average_count()
    });
}
