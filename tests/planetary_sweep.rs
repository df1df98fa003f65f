//! The measuring chain on a planetary stage's ring sensor (issue 47, item 5), in a run and
//! in a sweep: the sensor's signal `sensor_<stage>_n` is a plant signal a
//! `[[chain.stage]]`, the analyser, the scope and the recording may read, as any of the
//! rig's columns. The shipped scenario `planetary-run.toml` analyses it: its strongest
//! line is the planet-pass frequency N f_c, and the mesh line z_r f_c stands above its
//! neighbours. On the shipped
//! bench (three planets 120° apart, each ring mesh seen through a 120° Hann window over
//! its planet's passage) the recorded sensor averages half a ring mesh's force, falls to
//! nothing midway between two planets and repeats at the planet-pass frequency; an
//! AC-coupled stage on it takes the mean out.

mod common;

use common::{csv_rows, folder, number, run_ok, scenario, testrig_ok};

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

/// A spectrum CSV's (frequency in Hz, power) rows, its `#` header lines passed over.
fn spectrum_rows(path: &std::path::Path) -> Vec<(f64, f64)> {
    std::fs::read_to_string(path)
        .expect("spectrum")
        .lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| {
            let mut fields = l.split(',');
            let mut next = || {
                fields
                    .next()
                    .expect("field")
                    .parse::<f64>()
                    .expect("number")
            };
            (next(), next())
        })
        .collect()
}

#[test]
fn the_shipped_planetary_run_analyses_the_ring_sensor() {
    // 1500 rev/min: the carrier at 5 Hz, three planets pass the sensor at 15 Hz, the
    // meshes at 96 × 5 = 480 Hz, a line some 300 times the median about it; 1000 rev/min:
    // 10 Hz (its mesh line at 320 Hz, in a quasi-periodic motion, stands only 6 times above
    // the floor about it: not held).
    let (out, _) = run_ok("planetary-run", &scenario("planetary-run"), &[]);
    for (k, pass_hz, mesh_hz) in [(1, 15.0, Some(480.0)), (2, 10.0, None)] {
        let lines = spectrum_rows(&out.path().join(format!("spectrum-0{k}.csv")));
        let bin_hz = lines[1].0 - lines[0].0;
        let strongest = lines
            .iter()
            .copied()
            .fold((0.0, 0.0), |a, b| if b.1 > a.1 { b } else { a });
        assert!(
            (strongest.0 - pass_hz).abs() <= bin_hz,
            "measurement {k}: the strongest line at {} Hz, not the planet pass {pass_hz} Hz",
            strongest.0
        );
        let Some(mesh_hz) = mesh_hz else {
            continue;
        };
        let at = lines
            .iter()
            .position(|l| (l.0 - mesh_hz).abs() <= bin_hz / 2.0)
            .expect("the mesh bin");
        let top = (at - 1..=at + 1).map(|i| lines[i].1).fold(0.0, f64::max);
        let mut around: Vec<f64> = (at - 12..=at + 12)
            .filter(|i| i.abs_diff(at) > 3)
            .map(|i| lines[i].1)
            .collect();
        around.sort_by(f64::total_cmp);
        let median = around[around.len() / 2];
        eprintln!(
            "MEASURED planetary-run {k}: planet pass {:.2} Hz; mesh line {top:.3e} against a median {median:.3e} about it",
            strongest.0
        );
        assert!(
            top > 10.0 * median,
            "measurement {k}: no mesh line at {mesh_hz} Hz"
        );
    }
}
