//! The App. E keyboard program gives the spectrum of the equivalent analyser settings.

use instruments::{Analyser, AnalyserSettings, KeyboardProgram};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;
use std::f64::consts::PI;

const APPENDIX_E: &str = include_str!("../../scenarios/appendix-e.prg");

fn signal(samples: usize) -> Vec<f64> {
    let mut rng = Pcg64Mcg::seed_from_u64(11);
    (0..samples)
        .map(|k| (2.0 * PI * 250.0 * k as f64 / 4_000.0).sin() + 0.1 * (rng.random::<f64>() - 0.5))
        .collect()
}

#[test]
fn appendix_e_equals_ten_linear_averages_shown_linear_then_in_db() {
    let settings = AnalyserSettings::thesis(1024, 2_000.0);
    let samples = signal(1024 * 10);
    let program = KeyboardProgram::parse(APPENDIX_E).expect("App. E parses");
    let displays = program.run(&settings, &samples).expect("runs");
    assert_eq!(displays.len(), 2);
    let mut analyser = Analyser::new(settings).expect("valid");
    analyser.push(&samples);
    assert_eq!(analyser.average_count(), 10);
    let reference = analyser.display();
    let reference_db = analyser.display_db();
    assert_eq!(displays[0].len(), reference.len());
    for (((linear, db), want), want_db) in displays[0]
        .iter()
        .zip(&displays[1])
        .zip(&reference)
        .zip(&reference_db)
    {
        assert!((db.value - want_db.value).abs() < 1e-9);
        assert_eq!(linear.frequency_hz, want.frequency_hz);
        assert!(
            (linear.value - want.value).abs() <= 1e-12 * want.value.abs().max(1e-30),
            "{} vs {}",
            linear.value,
            want.value
        );
        assert!((db.value - 10.0 * want.value.log10()).abs() < 1e-9);
    }
}

#[test]
fn bad_programs_name_the_line() {
    let err = KeyboardProgram::parse("LABEL 0\nFOURIER TRANSFROM\n").expect_err("typo");
    assert!(err.to_string().contains("line 2"), "{err}");
    let short = KeyboardProgram::parse(APPENDIX_E).expect("parses");
    let err = short
        .run(&AnalyserSettings::thesis(1024, 2_000.0), &signal(1024 * 3))
        .expect_err("too few samples");
    assert!(err.to_string().contains("line 6"), "{err}");
    let missing =
        KeyboardProgram::parse("LABEL 0\nCOUNT LOOP LABEL 7 TIMES 2\nEND\n").expect("parses");
    assert!(
        missing
            .run(&AnalyserSettings::thesis(64, 32.0), &[])
            .is_err()
    );
}
