//! `testrig analyse` end to end: a WAV file through filter, ADC and analyser.

mod common;

use std::path::Path;

use common::folder;
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

/// A mono 64-bit IEEE float WAV as scipy.io.wavfile writes one for a float64 array:
/// `fmt ` of 18 bytes (format 3, cbSize 0), a `fact` chunk, then `data`.
fn write_float64_wav(path: &Path, rate: u32, samples: &[f64]) {
    let data_len = (samples.len() * 8) as u32;
    let mut bytes = Vec::new();
    bytes.extend_from_slice(b"RIFF");
    bytes.extend_from_slice(&(4 + 26 + 12 + 8 + data_len).to_le_bytes());
    bytes.extend_from_slice(b"WAVEfmt ");
    bytes.extend_from_slice(&18u32.to_le_bytes());
    bytes.extend_from_slice(&3u16.to_le_bytes());
    bytes.extend_from_slice(&1u16.to_le_bytes());
    bytes.extend_from_slice(&rate.to_le_bytes());
    bytes.extend_from_slice(&(rate * 8).to_le_bytes());
    bytes.extend_from_slice(&8u16.to_le_bytes());
    bytes.extend_from_slice(&64u16.to_le_bytes());
    bytes.extend_from_slice(&0u16.to_le_bytes());
    bytes.extend_from_slice(b"fact");
    bytes.extend_from_slice(&4u32.to_le_bytes());
    bytes.extend_from_slice(&(samples.len() as u32).to_le_bytes());
    bytes.extend_from_slice(b"data");
    bytes.extend_from_slice(&data_len.to_le_bytes());
    for s in samples {
        bytes.extend_from_slice(&s.to_le_bytes());
    }
    std::fs::write(path, bytes).expect("writable");
}

fn tone(rate: u32, freq_hz: f64, amplitude: f64, seconds: f64) -> Vec<f64> {
    (0..(seconds * f64::from(rate)) as usize)
        .map(|k| {
            amplitude * (2.0 * std::f64::consts::PI * freq_hz * k as f64 / f64::from(rate)).sin()
        })
        .collect()
}

#[test]
fn a_64_bit_float_wav_is_read_and_its_tone_has_its_power() {
    let dir = folder("float64");
    let wav = dir.join("scipy.wav");
    // fs = 4 kHz, N = 1024: Δf = 3.90625 Hz and 250 Hz is line 64, so no scalloping.
    write_float64_wav(&wav, 8_000, &tone(8_000, 250.0, 3.0, 3.0));
    let out = dir.join("out");
    let output = analyse(&wav, &out, &["--fmax", "2000", "--averages", "4"]);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let (f, power, _) = peak(&read_spectrum(&out.join("spectrum.csv")));
    assert!((f - 250.0).abs() < 1e-9, "peak at {f} Hz");
    // A sine of amplitude 3 has 4.5 unit² rms; the autorange (±5) keeps it unclipped.
    assert!((power - 4.5).abs() < 4.5 * 1e-3, "power {power}");
    // Cut short (a copy interrupted; issue 23): analysed with a word, and the half frame
    // at the end left out. The tone is still where it was.
    let bytes = std::fs::read(&wav).expect("read");
    let cut = dir.join("cut.wav");
    std::fs::write(&cut, &bytes[..bytes.len() - 8 * 4000 - 3]).expect("written");
    let output = analyse(
        &cut,
        &dir.join("out-cut"),
        &["--fmax", "2000", "--averages", "2"],
    );
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{stderr}");
    assert!(
        stderr.contains("cut short") && stderr.contains("the 19999 whole frames"),
        "{stderr}"
    );
    // The same file marked as 64-bit integer PCM, which no reader takes: the error lists
    // the formats that work.
    let mut bytes = std::fs::read(&wav).expect("read");
    bytes[20] = 1; // PCM
    std::fs::write(&wav, bytes).expect("written");
    let refused = analyse(&wav, &out, &[]);
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert!(!refused.status.success());
    assert!(stderr.contains("64-bit IEEE float"), "{stderr}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_section_of_the_file_is_picked_by_start_and_length() {
    let dir = folder("section");
    let wav = dir.join("two-tones.wav");
    let mut samples = tone(8_000, 250.0, 1.0, 2.0);
    samples.extend(tone(8_000, 500.0, 1.0, 2.0));
    write_float64_wav(&wav, 8_000, &samples);
    for (start, want_hz) in [("0", 250.0), ("2", 500.0)] {
        let out = dir.join(format!("out-{start}"));
        let output = analyse(
            &wav,
            &out,
            &[
                "--fmax",
                "2000",
                "--averages",
                "3",
                "--start",
                start,
                "--length",
                "1.5",
            ],
        );
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        let rows = read_spectrum(&out.join("spectrum.csv"));
        assert!((peak(&rows).0 - want_hz).abs() < 1e-9, "from {start} s");
        let other = if want_hz == 250.0 { 500.0 } else { 250.0 };
        let at_other = rows
            .iter()
            .find(|r| (r.0 - other).abs() < 1e-9)
            .expect("line");
        assert!(
            at_other.1 < 1e-12,
            "the other half's tone is outside the section"
        );
    }
    let late = analyse(&wav, &dir.join("late"), &["--start", "4"]);
    assert!(String::from_utf8_lossy(&late.stderr).contains("--start 4: a time in [0, 4)"));
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn our_own_recording_is_read_with_its_sidecar_names_units_and_full_scale() {
    let dir = folder("own");
    let scenario = format!(
        "{}/scenarios/aliasing-windowing.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let run = Command::new(env!("CARGO_BIN_EXE_testrig"))
        .args([
            "run",
            &scenario,
            "--pace",
            "max",
            "--duration",
            "8",
            "--out",
        ])
        .arg(dir.join("run"))
        .output()
        .expect("runs");
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let wav = dir.join("run").join("recording.wav");
    let out = dir.join("out");
    let output = analyse(
        &wav,
        &out,
        &[
            "--channel",
            "torque_intermediate_shaft_nm",
            "--fmax",
            "200",
            "--block",
            "512",
        ],
    );
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{stderr}");
    assert!(!stderr.contains("overloaded"), "{stderr}");
    let text = std::fs::read_to_string(out.join("spectrum.csv")).expect("CSV");
    assert!(
        text.contains("# channel: 2 (torque_intermediate_shaft_nm, N m)"),
        "{text}"
    );
    // The recording's full scale of a torque is 100 N m (signal catalogue).
    assert!(text.contains("over +-100 N m (the recording's full scale), 0 overloads"));
    assert!(text.contains("(N m^2 rms)"), "scaling in the signal's unit");
    // The shaft's mean torque (2.712 N m) stands at 0 Hz as (2.712)² N m².
    let dc = read_spectrum(&out.join("spectrum.csv"))[0].1;
    assert!((dc.sqrt() - 2.712).abs() < 0.1, "DC {} N m", dc.sqrt());
    // A range far below the signal overloads: warned on the console.
    let clipped = analyse(
        &wav,
        &dir.join("clipped"),
        &[
            "--channel",
            "torque_intermediate_shaft_nm",
            "--range",
            "0.5",
            "--fmax",
            "200",
            "--block",
            "512",
        ],
    );
    assert!(String::from_utf8_lossy(&clipped.stderr).contains("warning: the ADC overloaded"));
    let missing = analyse(&wav, &dir.join("missing"), &["--channel", "speed9"]);
    let stderr = String::from_utf8_lossy(&missing.stderr);
    assert!(
        stderr.contains("--channel speed9") && stderr.contains("filter_v"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_appendix_e_program_runs_on_a_recording() {
    let dir = folder("program");
    let wav = dir.join("tone.wav");
    write_float64_wav(&wav, 8_000, &tone(8_000, 250.0, 1.0, 3.0));
    let out = dir.join("out");
    let program = format!("{}/scenarios/appendix-e.prg", env!("CARGO_MANIFEST_DIR"));
    let output = analyse(&wav, &out, &["--fmax", "2000", "--program", &program]);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let column = |name: &str| -> Vec<f64> {
        let text = std::fs::read_to_string(out.join(name)).expect("display");
        text.lines()
            .skip(1)
            .map(|l| l.split(',').nth(1).expect("value").parse().expect("number"))
            .collect()
    };
    let (linear, db) = (column("display-01.csv"), column("display-02.csv"));
    assert_eq!(linear.len(), 512, "N/2 lines");
    let k = 64; // 250 Hz
    assert!(
        (linear[k] - 0.5).abs() < 1e-3,
        "ten averages of a unit sine: {}",
        linear[k]
    );
    assert!((db[k] - 10.0 * linear[k].log10()).abs() < 1e-9);
    std::fs::remove_dir_all(&dir).ok();
}
