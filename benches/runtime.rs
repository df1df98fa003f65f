//! Benchmarks of `testrig run` as a whole process (cargo bench --bench runtime):
//!
//! - memory: peak resident memory of an unpaced recording run of 10 simulated minutes
//!   against 1 minute (recordings stream to disk, so the two should match within 10 %);
//! - pacing: a run at pace 1 for 60 s with the full chain: overruns, lateness p50/p99/max,
//!   CPU share of one core.
//!
//! - campaign: `testrig sweep scenarios/thesis-campaign.toml` (78 points, each 10 s
//!   settling + 30 s measured, ten-average spectra) on every core: wall time, median of 3.
//!
//! The first two read the figures from the run's manifest.json. `TESTRIG_BENCH=memory`,
//! `pacing` or `campaign` runs one of them only.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The full chain at the thesis's subharmonic point, recording two channels at 51.2 kHz.
const SCENARIO: &str = r#"name = "runtime-bench"
seed = 1
duration_s = 60

[rig]
backlash_mm = 0.73

[schedule]
speed_rpm = 1300
load_nm = 2.712

[chain.slip_rings]
broadband_rms = 0.005
per_rev_amplitude = 0.01
contact_noise_v_rms = 2e-6

[chain.scope]
volts_per_div = 0.5
seconds_per_div = 0.02

[analyser]
fmax_hz = 200
block = 512
averages = 10

[record]
signals = ["filter_v", "torque_intermediate_shaft_nm"]
formats = ["wav"]
"#;

fn run(dir: &Path, pace: &str, duration_s: f64) -> serde_json::Value {
    let scenario = dir.join("bench.toml");
    std::fs::write(&scenario, SCENARIO).expect("scenario written");
    let out = dir.join(format!("out-{pace}-{duration_s}"));
    let status = Command::new(env!("CARGO_BIN_EXE_testrig"))
        .args(["run", scenario.to_str().expect("utf-8"), "--pace", pace])
        .args(["--duration", &duration_s.to_string()])
        .args(["--out", out.to_str().expect("utf-8")])
        .status()
        .expect("testrig runs");
    assert!(status.success());
    let text = std::fs::read_to_string(out.join("manifest.json")).expect("manifest");
    std::fs::remove_dir_all(&out).ok();
    serde_json::from_str(&text).expect("JSON")
}

fn memory(dir: &Path) {
    let short = run(dir, "max", 60.0);
    let long = run(dir, "max", 600.0);
    let (a, b) = (
        short["peak_rss_mib"].as_f64().expect("rss"),
        long["peak_rss_mib"].as_f64().expect("rss"),
    );
    println!(
        "memory: peak RSS 1 min {a:.1} MiB, 10 min {b:.1} MiB, ratio {:.3} (target ≤ 1.10); {:.0}x and {:.0}x real time",
        b / a,
        short["realtime_factor"].as_f64().unwrap_or(0.0),
        long["realtime_factor"].as_f64().unwrap_or(0.0)
    );
}

fn pacing(dir: &Path) {
    let m = run(dir, "1", 60.0);
    let l = &m["lateness_ms"];
    println!(
        "pacing: pace 1 for 60 s: {} overruns, lateness p50 {:.3} ms, p99 {:.3} ms, max {:.3} ms over {} releases, CPU {:.1} % of one core",
        m["overruns"],
        l["p50"].as_f64().unwrap_or(f64::NAN),
        l["p99"].as_f64().unwrap_or(f64::NAN),
        l["max"].as_f64().unwrap_or(f64::NAN),
        l["releases"],
        100.0 * m["cpu_share_of_one_core"].as_f64().unwrap_or(f64::NAN)
    );
}

fn campaign(dir: &Path) {
    let file = format!(
        "{}/scenarios/thesis-campaign.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let mut walls: Vec<f64> = (0..3)
        .map(|k| {
            let out = dir.join(format!("campaign-{k}"));
            let started = std::time::Instant::now();
            let status = Command::new(env!("CARGO_BIN_EXE_testrig"))
                .args(["sweep", &file, "--out", out.to_str().expect("utf-8")])
                .stdout(std::process::Stdio::null())
                .status()
                .expect("testrig runs");
            assert!(status.success());
            std::fs::remove_dir_all(&out).ok();
            started.elapsed().as_secs_f64()
        })
        .collect();
    walls.sort_by(f64::total_cmp);
    println!(
        "campaign: 78 points in {:.2} s wall (median of 3; range {:.2}-{:.2} s; target ≤ 10 s)",
        walls[1], walls[0], walls[2]
    );
}

fn main() {
    let dir: PathBuf = std::env::temp_dir().join(format!("testrig-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp folder");
    let which = std::env::var("TESTRIG_BENCH").unwrap_or_default();
    if which.is_empty() || which == "memory" {
        memory(&dir);
    }
    if which.is_empty() || which == "pacing" {
        pacing(&dir);
    }
    if which.is_empty() || which == "campaign" {
        campaign(&dir);
    }
    std::fs::remove_dir_all(&dir).ok();
}
