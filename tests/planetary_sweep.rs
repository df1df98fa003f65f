//! A sweep's measuring chain on a planetary stage's ring sensor (issue 47, item 5): the
//! sensor's signal `sensor_<stage>_n` is a plant signal a sweep's `[[chain.stage]]`, its
//! analyser and its recording may read, as any of the rig's columns. On the shipped
//! bench (three planets 120° apart, each ring mesh seen through a 120° Hann window over
//! its planet's passage) the recorded sensor averages half a ring mesh's force, falls to
//! nothing midway between two planets and repeats at the planet-pass frequency; an
//! AC-coupled stage on it takes the mean out.

mod common;

use common::{csv_rows, folder, number, testrig_ok};

#[test]
fn a_sweeps_chain_reads_and_records_the_ring_sensor() {
    let dir = folder("planetary-sweep-sensor");
    let rig = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenarios/rigs/planetary-bench.toml"
    );
    let text = format!(
        r#"name = "ring-sensor"
rate_hz = 10240
[rig]
file = "{rig}"
[grid]
rpm = [1500]
load_nm = [50.0]
[case]
settle_s = 1
measure_s = 1
[[chain.stage]]
output = "ring_ac_n"
input = "sensor_epi_n"
ac_coupling = {{ corner_hz = 1 }}
[analyser]
fmax_hz = 1000
input = "ring_ac_n"
[record]
signals = ["sensor_epi_n", "ring_ac_n", "keyphasor_v"]
formats = ["csv"]
"#
    );
    let sweep = dir.join("ring-sensor.toml");
    std::fs::write(&sweep, text).expect("written");
    let out = dir.join("out");
    testrig_ok(&[
        "sweep",
        sweep.to_str().expect("utf-8"),
        "--out",
        out.to_str().expect("utf-8"),
    ]);
    let rows = csv_rows(&out.join("recordings/case-00000.csv"));
    assert_eq!(rows.len(), 10240, "the measured second whole");
    let sensor: Vec<f64> = rows.iter().map(|r| number(r, "sensor_epi_n")).collect();
    let coupled: Vec<f64> = rows.iter().map(|r| number(r, "ring_ac_n")).collect();
    // Each ring mesh carries T_s/(N r_s) on average: 10 N m over three planets at the
    // sun's base radius (module 3 mm, 24 teeth, 20°). Each planet's window, a Hann 120°
    // wide, averages 1/2 over its 120°, so the sensor averages N · (1/3) · (1/2) = 1/2 of
    // the share; midway between two planets it sees nothing.
    let share = 10.0 / (3.0 * 0.003 * 24.0 * 20f64.to_radians().cos() / 2.0);
    let mean = |x: &[f64]| x.iter().sum::<f64>() / x.len() as f64;
    let low = sensor.iter().fold(f64::MAX, |l, &v| l.min(v));
    let average = mean(&sensor);
    eprintln!(
        "MEASURED ring sensor in a sweep: mean {average:.3} N (half the share {:.3} N), least {low:.2e} N",
        share / 2.0
    );
    assert!(
        (average / (share / 2.0) - 1.0).abs() < 0.02,
        "the sensor's mean {average} N against half the mesh's {share} N"
    );
    assert!(low.abs() < 1e-3 * share, "midway between planets: {low} N");
    let rms = (coupled.iter().map(|v| v * v).sum::<f64>() / coupled.len() as f64).sqrt();
    assert!(
        mean(&coupled).abs() < 0.02 * rms,
        "AC coupled: mean {} N against an RMS of {rms} N",
        mean(&coupled)
    );
    // The sensor swings at the planet-pass frequency, 3 × 300/60 = 15 Hz: its mean over
    // one planet pass (1/15 s = 682.67 samples) is the same wherever the pass starts.
    let pass = (10240.0_f64 / 15.0).round() as usize;
    let passes: Vec<f64> = (0..10)
        .map(|k| mean(&sensor[k * 97..k * 97 + pass]))
        .collect();
    let spread = passes
        .iter()
        .fold(0.0_f64, |m, p| m.max((p - passes[0]).abs()));
    assert!(spread < 0.02 * share, "pass means {passes:?}");
}
