//! The analyser: conventions, averaging, overlap, and the aliasing study with ground truth.

use instruments::{
    Adc, AdcSettings, AliasTruth, Analyser, AnalyserSettings, AntiAliasFilter, Averaging, Block,
    FilterKind, LowPassSpec, Sampling, Window,
};
use std::f64::consts::PI;

/// The analogue stream rate of these tests: 16 × the thesis's 4 kHz ADC rate.
const ANALOGUE_HZ: f64 = 64_000.0;
const DECIMATION: usize = 16;
const N: usize = 1024;

fn sine(freq_hz: f64, amplitude: f64, samples: usize) -> Vec<f64> {
    (0..samples)
        .map(|k| amplitude * (2.0 * PI * freq_hz * k as f64 / ANALOGUE_HZ).sin())
        .collect()
}

fn adc() -> Adc {
    Adc::new(AdcSettings {
        ratio: DECIMATION as f64,
        bits: 16,
        range_v: 2.0,
        dither_seed: None,
    })
    .expect("valid")
}

/// Analogue signal → optional filter → ADC → analyser (thesis convention, Fmax 2 kHz, 1 average).
fn analyse(analogue: &[f64], filter: Option<LowPassSpec>) -> Vec<instruments::Line> {
    let mut f = AntiAliasFilter::new(filter, ANALOGUE_HZ).expect("valid");
    let mut filtered = vec![0.0; analogue.len()];
    f.process(analogue, &mut filtered);
    let mut samples = Vec::new();
    adc().convert(&filtered, &mut samples);
    let mut settings = AnalyserSettings::thesis(N, 2_000.0);
    settings.averages = 1;
    let mut analyser = Analyser::new(settings).expect("valid");
    analyser.push(&samples);
    assert!(analyser.is_complete());
    analyser.display()
}

fn peak(lines: &[instruments::Line]) -> (usize, f64) {
    lines.iter().enumerate().fold(
        (0, 0.0),
        |best, (k, l)| if l.value > best.1 { (k, l.value) } else { best },
    )
}

#[test]
fn conventions_give_the_rate_and_lines_the_thesis_and_modern_analysers_use() {
    let thesis = AnalyserSettings::thesis(1024, 2_000.0);
    assert_eq!(thesis.sample_rate_hz(), 4_000.0);
    assert_eq!(thesis.displayed_lines(), 512);
    let modern = AnalyserSettings {
        sampling: Sampling::Modern,
        ..thesis
    };
    assert_eq!(modern.sample_rate_hz(), 5_120.0);
    assert_eq!(modern.displayed_lines(), 401);
    let analyser = Analyser::new(modern).expect("valid");
    let lines = analyser.display();
    assert!(
        (lines.last().expect("lines").frequency_hz - 2_000.0).abs() < 1e-9,
        "400 lines reach Fmax"
    );
}

#[test]
fn a_2_2_khz_sine_sampled_at_4_khz_shows_at_1_8_khz_flagged_as_its_alias() {
    let analogue = sine(2_200.0, 1.0, N * DECIMATION);
    let lines = analyse(&analogue, None);
    let (k, _) = peak(&lines);
    let df = 4_000.0 / N as f64;
    assert!(
        (lines[k].frequency_hz - 1_800.0).abs() <= df,
        "peak at {} Hz",
        lines[k].frequency_hz
    );
    let mut truth =
        AliasTruth::new(N, DECIMATION as f64, ANALOGUE_HZ, Window::Hanning).expect("valid");
    let flags = truth.classify(&analogue, lines.len(), 0.0);
    let source = flags[k].expect("the 1.8 kHz line is an alias");
    assert!((source - 2_200.0).abs() <= 16.0, "alias of {source} Hz");
    // A real line stays unflagged: 1 kHz below Fmax.
    let real = sine(1_000.0, 1.0, N * DECIMATION);
    let real_lines = analyse(&real, None);
    let (kr, _) = peak(&real_lines);
    assert_eq!(truth.classify(&real, real_lines.len(), 0.0)[kr], None);
}

#[test]
fn the_anti_alias_filter_attenuates_the_alias_as_designed() {
    let spec = LowPassSpec {
        kind: FilterKind::Butterworth,
        order: 8,
        cutoff_hz: 2_000.0,
    };
    // Let the filter's transient pass: analyse the second block's worth of signal.
    let n = N * DECIMATION;
    let analogue = sine(2_200.0, 1.0, 2 * n);
    let open = analyse(&analogue[n..], None);
    let mut filtered_input = analogue.clone();
    let mut f = AntiAliasFilter::new(Some(spec), ANALOGUE_HZ).expect("valid");
    let copy = filtered_input.clone();
    f.process(&copy, &mut filtered_input);
    let filtered = analyse(&filtered_input[n..], None);
    let attenuation_db = 10.0 * (peak(&filtered).1 / peak(&open).1).log10();
    let designed_db = 20.0 * f.response(2_200.0).expect("linear").norm().log10();
    assert!(
        (attenuation_db - designed_db).abs() < 0.1,
        "{attenuation_db} dB vs designed {designed_db} dB"
    );
    assert!(designed_db < -6.0);
}

#[test]
fn linear_averaging_is_the_mean_and_peak_hold_the_maximum() {
    let settings = |averaging| AnalyserSettings {
        averaging,
        averages: 4,
        ..AnalyserSettings::thesis(64, 32.0)
    };
    // Four blocks of a sine whose amplitude steps 1, 2, 3, 4 (bin-centred at 8 Hz, Δf = 1 Hz).
    let blocks: Vec<f64> = (0..4)
        .flat_map(|b| {
            (0..64).map(move |k| f64::from(b + 1) * (2.0 * PI * 8.0 * k as f64 / 64.0).sin())
        })
        .collect();
    let mut linear = Analyser::new(settings(Averaging::Linear)).expect("valid");
    let mut peak_hold = Analyser::new(settings(Averaging::PeakHold)).expect("valid");
    linear.push(&blocks);
    peak_hold.push(&blocks);
    // Power of a sine of amplitude a is a²/2: mean of 1,4,9,16 over 2 = 3.75; peak 8.
    assert!(
        (linear.display()[8].value - 3.75).abs() < 1e-9,
        "{}",
        linear.display()[8].value
    );
    assert!((peak_hold.display()[8].value - 8.0).abs() < 1e-9);
    assert_eq!(linear.average_count(), 4);
    assert!(linear.is_complete());
}

#[test]
fn overlap_takes_blocks_at_the_hop() {
    let settings = AnalyserSettings {
        averages: 100,
        overlap: 0.5,
        ..AnalyserSettings::thesis(64, 32.0)
    };
    let mut analyser = Analyser::new(settings).expect("valid");
    analyser.push(&vec![0.1; 64 * 5]);
    // 320 samples at hop 32 give blocks starting at 0, 32, ..., 256: 9 blocks.
    assert_eq!(analyser.average_count(), 9);
    let bad = AnalyserSettings {
        overlap: 1.0,
        ..settings
    };
    assert!(Analyser::new(bad).is_err());
}

#[test]
fn the_quantisation_floor_per_line_matches_the_noise_an_adc_adds() {
    // Three incommensurate tones over most of the range make the quantisation error white
    // (variance q²/12); lines away from the tones then hold 2·(q²/12)·ENBW/fs each.
    let samples = N * DECIMATION * 8;
    let analogue: Vec<f64> = (0..samples)
        .map(|k| {
            let t = k as f64 / ANALOGUE_HZ;
            0.6 * (2.0 * PI * 211.7 * t).sin()
                + 0.5 * (2.0 * PI * 737.3 * t).sin()
                + 0.4 * (2.0 * PI * 1_313.9 * t).sin()
        })
        .collect();
    let mut converter = Adc::new(AdcSettings {
        ratio: DECIMATION as f64,
        bits: 8,
        range_v: 2.0,
        dither_seed: None,
    })
    .expect("valid");
    let mut digital = Vec::new();
    converter.convert(&analogue, &mut digital);
    let mut settings = AnalyserSettings::thesis(N, 2_000.0);
    settings.averages = 8;
    let mut analyser = Analyser::new(settings).expect("valid");
    analyser.push(&digital);
    let lines = analyser.display();
    let df = 4_000.0 / N as f64;
    let mut away: Vec<f64> = lines
        .iter()
        .filter(|l| {
            [211.7, 737.3, 1_313.9]
                .iter()
                .all(|&f| ((l.frequency_hz - f) / df).abs() > 40.0)
        })
        .map(|l| l.value)
        .collect();
    away.sort_by(f64::total_cmp);
    let median = away[away.len() / 2];
    let floor = converter.quantisation_line_power(analyser.enbw_hz(), 4_000.0);
    let ratio = median / floor;
    // The median of a chi-square with 16 degrees of freedom (8 averages) is 0.96 of its mean.
    assert!((0.7..1.4).contains(&ratio), "median/floor = {ratio}");
}

#[test]
fn an_alias_below_the_quantisation_floor_is_not_flagged() {
    // A 2.2 kHz tone of 1 nV folds to 1.8 kHz far below a 16-bit ADC's noise: invisible.
    let analogue = sine(2_200.0, 1e-9, N * DECIMATION);
    let mut truth =
        AliasTruth::new(N, DECIMATION as f64, ANALOGUE_HZ, Window::Hanning).expect("valid");
    let k = (1_800.0_f64 / (4_000.0 / N as f64)).round() as usize;
    let lines = N / 2 + 1;
    let unfloored = truth.classify(&analogue, lines, 0.0);
    assert!(unfloored[k].is_some(), "without a floor the alias is named");
    let floor = adc().quantisation_line_power(1.5 * 4_000.0 / N as f64, 4_000.0);
    let floored = truth.classify(&analogue, lines, floor);
    assert!(
        floored.iter().all(Option::is_none),
        "nothing below the floor is flagged"
    );
    // The same tone at 0.1 V stands far above the floor and is still flagged.
    let loud = sine(2_200.0, 0.1, N * DECIMATION);
    assert!(truth.classify(&loud, lines, floor)[k].is_some());
}
