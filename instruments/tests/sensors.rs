//! Strain, bridge, meters and tacho against their physics.

use instruments::{
    AcCoupling, AntiAliasFilter, Block, BrakeDrive, BrakeDriveSettings, BridgeArrangement,
    CarrierDemodulator, CarrierModulator, CarrierSettings, Detector, DigitalVoltmeter, FilterKind,
    LowPassSpec, Scope, ScopeSettings, ShaftStrain, SlipRing, SlipRingSettings, Slope,
    StrainBridge, SweepMode, Tacho, Voltmeter,
};
use std::f64::consts::PI;

const RATE: f64 = 51_200.0;

#[test]
fn shaft_strain_is_half_the_surface_shear() {
    let shaft = ShaftStrain::intermediate_shaft();
    let torque = 2.712;
    // γ = 16 T / (π d³ G), ε(45°) = γ/2.
    let gamma = 16.0 * torque / (PI * 0.02_f64.powi(3) * 82.7e9);
    let mut out = [0.0];
    let mut block = shaft;
    block.process(&[torque], &mut out);
    assert!(
        (out[0] - gamma / 2.0).abs() < 1e-18,
        "{} vs {}",
        out[0],
        gamma / 2.0
    );
    // On the Ø20 mm shaft: 3.85 µε per N m (10.4 µε at 2.712 N m).
    assert!(
        (shaft.strain_per_nm() * 1e6 - 3.849).abs() < 0.001,
        "{}",
        shaft.strain_per_nm() * 1e6
    );
    assert!(ShaftStrain::new(0.0, 82.7e9).is_err());
}

#[test]
fn full_and_half_bridges_are_linear_and_the_quarter_bridge_is_not() {
    let epsilon = 1e-3;
    let (gf, e) = (2.1, 10.0);
    let full = StrainBridge::new(BridgeArrangement::Full, gf, e).expect("valid");
    let half = StrainBridge::new(BridgeArrangement::Half, gf, e).expect("valid");
    let quarter = StrainBridge::new(BridgeArrangement::Quarter, gf, e).expect("valid");
    assert!((full.output_v(epsilon) - gf * e * epsilon).abs() < 1e-15);
    assert!((half.output_v(epsilon) - gf * e * epsilon / 2.0).abs() < 1e-15);
    // Quarter bridge: E_out = E GF ε / (4 + 2 GF ε): below the linear GF E ε / 4 for
    // tension, above it for compression, by the factor 1/(1 + GF ε/2).
    let q = quarter.output_v(epsilon);
    assert!((q - e * gf * epsilon / (4.0 + 2.0 * gf * epsilon)).abs() < 1e-15);
    let nonlinearity = q / (gf * e * epsilon / 4.0) - 1.0;
    assert!(
        (nonlinearity + gf * epsilon / 2.0 / (1.0 + gf * epsilon / 2.0)).abs() < 1e-12,
        "{nonlinearity}"
    );
    assert!(quarter.output_v(-epsilon).abs() > q);
    // A gauge factor 1 % high reads 1 % high.
    let mut off = full;
    off.gauge_factor_error = 0.01;
    assert!((off.output_v(epsilon) / full.output_v(epsilon) - 1.01).abs() < 1e-12);
}

fn settle(meter: &mut Voltmeter, signal: impl Fn(f64) -> f64, seconds: f64) -> f64 {
    let n = (seconds * RATE) as usize;
    let input: Vec<f64> = (0..n).map(|k| signal(k as f64 / RATE)).collect();
    let mut output = vec![0.0; n];
    meter.process(&input, &mut output);
    meter.reading()
}

#[test]
fn the_400e_reads_a_sine_right_and_a_square_wave_high_by_its_form_factor() {
    let sine = |t: f64| 3.0 * (2.0 * PI * 50.0 * t).sin();
    let square = |t: f64| {
        if (2.0 * PI * 50.0 * t).sin() >= 0.0 {
            3.0
        } else {
            -3.0
        }
    };
    let mut hp = Voltmeter::new(Detector::AverageRmsCalibrated, RATE, 0.2).expect("valid");
    let mut true_rms = Voltmeter::new(Detector::TrueRms, RATE, 0.2).expect("valid");
    let sine_rms = 3.0 / 2f64.sqrt();
    assert!((settle(&mut hp, sine, 3.0) / sine_rms - 1.0).abs() < 2e-3);
    assert!((settle(&mut true_rms, sine, 3.0) / sine_rms - 1.0).abs() < 2e-3);
    hp.reset();
    true_rms.reset();
    let hp_square = settle(&mut hp, square, 3.0);
    let true_square = settle(&mut true_rms, square, 3.0);
    assert!((true_square / 3.0 - 1.0).abs() < 1e-3);
    assert!(
        (hp_square / true_square - 1.1107).abs() < 1e-3,
        "{}",
        hp_square / true_square
    );
}

#[test]
fn the_ac_coupled_400e_ignores_the_static_strain_and_passes_10_hz() {
    // 2 V static + a 1 V-amplitude sine: the AC meter reads the sine alone.
    let corner_hz = 1.0;
    let mut ac = Voltmeter::new(Detector::AverageRmsCalibrated, RATE, 0.2)
        .expect("valid")
        .ac_coupled(corner_hz, RATE)
        .expect("valid");
    let offset_sine = |t: f64| 2.0 + (2.0 * PI * 50.0 * t).sin();
    let reading = settle(&mut ac, offset_sine, 6.0);
    assert!((reading / 0.5f64.sqrt() - 1.0).abs() < 3e-3, "{reading}");
    // At 10 Hz a first-order high-pass at 1 Hz passes 1/√(1 + 0.01) of the amplitude
    // (read with a slow detector, τ = 2 s, so the 20 Hz ripple of the rectified sine is small).
    let mut ac = Voltmeter::new(Detector::AverageRmsCalibrated, RATE, 2.0)
        .expect("valid")
        .ac_coupled(corner_hz, RATE)
        .expect("valid");
    let at_10_hz = settle(&mut ac, |t| (2.0 * PI * 10.0 * t).sin(), 25.0);
    let expected = 0.5f64.sqrt() / (1.0 + (corner_hz / 10.0f64).powi(2)).sqrt();
    assert!(
        (at_10_hz / expected - 1.0).abs() < 5e-3,
        "{at_10_hz} vs {expected}"
    );
    assert!(
        Voltmeter::new(Detector::TrueRms, RATE, 0.2)
            .expect("valid")
            .ac_coupled(RATE, RATE)
            .is_err()
    );
}

#[test]
fn ac_coupling_passes_a_sine_as_its_response_says() {
    let mut coupling = AcCoupling::new(1.6, RATE).expect("valid");
    for freq_hz in [0.5, 1.6, 3.33, 50.0] {
        coupling.reset();
        let n = (20.0 * RATE) as usize;
        let input: Vec<f64> = (0..n)
            .map(|k| (2.0 * PI * freq_hz * k as f64 / RATE).sin())
            .collect();
        let mut output = vec![0.0; n];
        coupling.process(&input, &mut output);
        let tail = &output[n / 2..];
        let amplitude = tail.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let expected = coupling.response(freq_hz).expect("linear").norm();
        assert!(
            (amplitude / expected - 1.0).abs() < 2e-3,
            "{freq_hz} Hz: {amplitude} vs {expected}"
        );
    }
    assert!((coupling.response(1.6).expect("linear").norm() - 0.5f64.sqrt()).abs() < 1e-3);
}

#[test]
fn the_400e_settles_in_about_a_second() {
    let mut hp = Voltmeter::new(Detector::AverageRmsCalibrated, RATE, 0.2).expect("valid");
    let sine = |t: f64| (2.0 * PI * 100.0 * t).sin();
    let at_half_second = settle(&mut hp, sine, 0.5);
    let at_one_second = settle(&mut hp, sine, 0.5);
    let target = 1.0 / 2f64.sqrt();
    assert!(at_half_second < 0.95 * target, "{at_half_second}");
    assert!(
        (at_one_second / target - 1.0).abs() < 0.01,
        "{at_one_second}"
    );
}

#[test]
fn the_tacho_dvm_reads_40_volts_at_1000_rpm() {
    let mut tacho = Tacho::crompton_parkinson(RATE).expect("valid");
    let mut dvm = DigitalVoltmeter::new(RATE, 1.0, 0.3, 0.1).expect("valid");
    let speed = 1000.0 * PI / 30.0;
    let n = (4.0 * RATE) as usize;
    let mut volts = vec![0.0; n];
    let mut shown = vec![0.0; n];
    tacho.process(&vec![speed; n], &mut volts);
    dvm.process(&volts, &mut shown);
    assert_eq!(dvm.shown_v(), 40.0);
    // The tacho's frequency: 4 poles give two cycles per revolution, 33.3 Hz at 1000 rev/min.
    let crossings = volts
        .windows(2)
        .filter(|w| w[0] < 0.0 && w[1] >= 0.0)
        .count();
    assert!(
        (crossings as f64 / 4.0 - 1000.0 / 60.0 * 2.0).abs() <= 1.0,
        "{crossings}"
    );
}

#[test]
fn blocks_split_into_buffers_give_the_same_output_and_reset_reproduces_it() {
    let input: Vec<f64> = (0..6000)
        .map(|k| ((k * 7919) % 1000) as f64 / 100.0)
        .collect();
    let carrier = CarrierSettings {
        carrier_hz: 5_000.0,
        output_lowpass_hz: 500.0,
        gain: 10.0,
    };
    let blocks: Vec<Box<dyn Block>> = vec![
        Box::new(ShaftStrain::intermediate_shaft()),
        Box::new(StrainBridge::new(BridgeArrangement::Quarter, 2.1, 5.0).expect("valid")),
        Box::new(Voltmeter::new(Detector::AverageRmsCalibrated, RATE, 0.2).expect("valid")),
        Box::new(Voltmeter::new(Detector::TrueRms, RATE, 0.2).expect("valid")),
        Box::new(Tacho::crompton_parkinson(RATE).expect("valid")),
        Box::new(DigitalVoltmeter::new(RATE, 0.01, 0.005, 0.01).expect("valid")),
        Box::new(
            SlipRing::new(
                SlipRingSettings {
                    broadband_rms: 0.01,
                    per_rev_amplitude: 0.02,
                    contact_noise_v_rms: 0.1,
                    seed: 5,
                },
                RATE,
                12.0,
            )
            .expect("valid"),
        ),
        Box::new(CarrierModulator::new(carrier, RATE).expect("valid")),
        Box::new(CarrierDemodulator::new(carrier, RATE).expect("valid")),
        Box::new(
            AntiAliasFilter::new(
                Some(LowPassSpec {
                    kind: FilterKind::Bessel,
                    order: 5,
                    cutoff_hz: 800.0,
                }),
                RATE,
            )
            .expect("valid"),
        ),
        Box::new(
            Scope::new(
                ScopeSettings {
                    volts_per_div: 1.0,
                    seconds_per_div: 1e-3,
                    trigger_v: 5.0,
                    slope: Slope::Rising,
                    mode: SweepMode::Repeat,
                },
                RATE,
            )
            .expect("valid"),
        ),
        Box::new(
            BrakeDrive::new(
                BrakeDriveSettings {
                    ac_amplitude_a: 0.3,
                    ac_frequency_hz: 15.0,
                    coil_time_constant_s: 0.02,
                    torque_per_amp: 2.0,
                },
                RATE,
            )
            .expect("valid"),
        ),
    ];
    for mut block in blocks {
        let mut whole = vec![0.0; input.len()];
        block.process(&input, &mut whole);
        block.reset();
        let mut pieces = vec![0.0; input.len()];
        for (i, chunk) in input.chunks(37).enumerate() {
            block.process(chunk, &mut pieces[i * 37..i * 37 + chunk.len()]);
        }
        assert_eq!(whole, pieces);
    }
}
