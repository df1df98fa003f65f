//! `testrig analyse` end to end: a WAV file through filter, ADC and analyser.

use std::path::{Path, PathBuf};
use std::process::Command;

use instruments::{AntiAliasFilter, Block, FilterKind, LowPassSpec};

fn write_wav(path: &Path, rate: u32, freq_hz: f64, amplitude: f32, seconds: f64) {
    let spec = hound::WavSpec {
        channels: 1,
        sample_rate: rate,
        bits_per_sample: 32,
        sample_format: hound::SampleFormat::Float,
    };
    let mut writer = hound::WavWriter::create(path, spec).expect("writable");
    for k in 0..(seconds * f64::from(rate)) as usize {
        let t = k as f64 / f64::from(rate);
        writer
            .write_sample(amplitude * (2.0 * std::f64::consts::PI * freq_hz * t).sin() as f32)
            .expect("written");
    }
    writer.finalize().expect("closed");
}

fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("testrig-analyse-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp folder");
    dir
}

/// (frequency, power, alias_of) rows of spectrum.csv.
fn read_spectrum(path: &Path) -> Vec<(f64, f64, Option<f64>)> {
    let text = std::fs::read_to_string(path).expect("spectrum.csv");
    let mut rows = text.lines().filter(|l| !l.starts_with('#'));
    assert_eq!(rows.next(), Some("frequency_hz,power,alias_of_hz"));
    rows.map(|row| {
        let cells: Vec<&str> = row.split(',').collect();
        (
            cells[0].parse().expect("number"),
            cells[1].parse().expect("number"),
            cells[2].parse().ok(),
        )
    })
    .collect()
}

fn analyse(wav: &Path, out: &Path, extra: &[&str]) -> std::process::Output {
    let mut args = vec![
        "analyse",
        wav.to_str().expect("utf-8"),
        "--out",
        out.to_str().expect("utf-8"),
    ];
    args.extend_from_slice(extra);
    Command::new(env!("CARGO_BIN_EXE_testrig"))
        .args(&args)
        .output()
        .expect("runs")
}

fn peak(rows: &[(f64, f64, Option<f64>)]) -> (f64, f64, Option<f64>) {
    *rows
        .iter()
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .expect("rows")
}

#[test]
fn a_2_2_khz_tone_shows_at_1_8_khz_as_an_alias_and_the_filter_cuts_it_as_designed() {
    let dir = folder("alias");
    let wav = dir.join("tone.wav");
    write_wav(&wav, 48_000, 2_200.0, 0.5, 3.0);
    let open = analyse(&wav, &dir.join("open"), &[]);
    assert!(
        open.status.success(),
        "{}",
        String::from_utf8_lossy(&open.stderr)
    );
    let rows = read_spectrum(&dir.join("open/spectrum.csv"));
    assert_eq!(rows.len(), 512, "N/2 lines in the thesis convention");
    let (f, p_open, alias) = peak(&rows);
    assert!((f - 1_800.0).abs() <= 4.0, "peak at {f} Hz");
    assert!((alias.expect("flagged as an alias") - 2_200.0).abs() <= 4.0);
    assert!(
        std::fs::metadata(dir.join("open/spectrum.png"))
            .expect("png")
            .len()
            > 10_000
    );

    let filtered = analyse(
        &wav,
        &dir.join("filtered"),
        &["--filter", "butterworth:8", "--cutoff", "2000"],
    );
    assert!(
        filtered.status.success(),
        "{}",
        String::from_utf8_lossy(&filtered.stderr)
    );
    let (_, p_filtered, _) = peak(&read_spectrum(&dir.join("filtered/spectrum.csv")));
    let spec = LowPassSpec {
        kind: FilterKind::Butterworth,
        order: 8,
        cutoff_hz: 2_000.0,
    };
    let designed = AntiAliasFilter::new(Some(spec), 48_000.0)
        .expect("valid")
        .response(2_200.0)
        .expect("linear")
        .norm_sqr();
    let measured = p_filtered / p_open;
    assert!(
        (10.0 * (measured / designed).log10()).abs() < 0.1,
        "{measured} vs {designed}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_cd_rate_recording_is_sampled_between_its_samples() {
    let dir = folder("cd");
    let wav = dir.join("cd.wav");
    write_wav(&wav, 44_100, 2_200.0, 0.5, 3.0);
    let out = analyse(&wav, &dir.join("out"), &[]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let (f, power, alias) = peak(&read_spectrum(&dir.join("out/spectrum.csv")));
    assert!((f - 1_800.0).abs() <= 4.0, "peak at {f} Hz");
    assert!((alias.expect("flagged") - 2_200.0).abs() <= 4.0);
    // A 0.5 amplitude sine reads its mean square 0.125 within the Hann scalloping (1.42 dB).
    assert!(
        power < 0.125 * 1.001 && power > 0.125 * 10f64.powf(-0.143),
        "{power}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn bad_input_is_refused_naming_the_field() {
    let dir = folder("bad");
    let wav = dir.join("low.wav");
    write_wav(&wav, 8_000, 1_000.0, 0.5, 0.5);
    let out = analyse(&wav, &dir.join("out"), &["--fmax", "5000"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(
        stderr.contains("--fmax") && stderr.contains("8000"),
        "{stderr}"
    );
    let window = analyse(
        &wav,
        &dir.join("out"),
        &["--fmax", "1000", "--window", "kaiser"],
    );
    assert!(String::from_utf8_lossy(&window.stderr).contains("--window"));
    let missing = analyse(&dir.join("nope.wav"), &dir.join("out"), &[]);
    assert!(String::from_utf8_lossy(&missing.stderr).contains("nope.wav"));
    std::fs::remove_dir_all(&dir).ok();
}
