//! Benchmarks of `testrig run` as a whole process (cargo bench --bench runtime):
//!
//! - memory: peak resident memory of an unpaced recording run of 10 simulated minutes
//!   against 1 minute (recordings stream to disk, so the two should match within 10 %);
//! - pacing: a run at pace 1 for 60 s with the full chain: overruns, lateness p50/p99/max,
//!   CPU share of one core.
//!
//! - campaign: `testrig sweep` on `scenarios/thesis-campaign.toml` (78 points from rest)
//!   and `scenarios/thesis-campaign-lab.toml` (387 cases: up, down, from rest and two
//!   knocked repeats), each
//!   case 60 s settling + 30 s measured with ten-average spectra, on every core: wall time,
//!   median of 3.
//!
//! - soak (only when asked, `TESTRIG_BENCH=soak`): the same chain at pace 1 for 30 minutes
//!   (`TESTRIG_SOAK_S` to change) recording a WAV: overruns, lateness, the process's
//!   resident memory sampled every 10 s (flat: the last minute's against the fifth
//!   minute's), and every file complete (the WAV holds every sample of the run).
//!
//! The first two read the figures from the run's manifest.json. `TESTRIG_BENCH=memory`,
//! `pacing`, `campaign` or `soak` runs one of them only.

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

fn write_scenario(dir: &Path) -> PathBuf {
    let scenario = dir.join("bench.toml");
    std::fs::write(&scenario, SCENARIO).expect("scenario written");
    scenario
}

fn run(dir: &Path, pace: &str, duration_s: f64) -> serde_json::Value {
    let scenario = write_scenario(dir);
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

/// The paced rig's CPU on a shipped scenario: `aliasing-windowing.toml` (the thesis's
/// chain, analyser, and a WAV and UFF58 recording of four signals at 51.2 kHz) at pace
/// 1, the process's own CPU time over the wall time (getrusage), median of 3.
fn paced_cpu(dir: &Path) {
    let scenario = format!(
        "{}/scenarios/aliasing-windowing.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let mut shares: Vec<f64> = (0..3)
        .map(|k| {
            let out = dir.join(format!("aliasing-{k}"));
            let status = Command::new(env!("CARGO_BIN_EXE_testrig"))
                .args(["run", &scenario, "--pace", "1", "--replace", "--out"])
                .arg(&out)
                .stdout(std::process::Stdio::null())
                .status()
                .expect("testrig runs");
            assert!(status.success());
            let text = std::fs::read_to_string(out.join("manifest.json")).expect("manifest");
            let m: serde_json::Value = serde_json::from_str(&text).expect("JSON");
            std::fs::remove_dir_all(&out).ok();
            100.0 * m["cpu_share_of_one_core"].as_f64().expect("cpu share")
        })
        .collect();
    shares.sort_by(f64::total_cmp);
    println!(
        "paced CPU: aliasing-windowing.toml at pace 1: {:.1} % of one core (median of 3, {:.1}-{:.1} %; target <= 10 %)",
        shares[1], shares[0], shares[2]
    );
}

fn campaign(dir: &Path) {
    for (name, points) in [("thesis-campaign", 78), ("thesis-campaign-lab", 387)] {
        let file = format!("{}/scenarios/{name}.toml", env!("CARGO_MANIFEST_DIR"));
        let mut walls: Vec<f64> = (0..3)
            .map(|k| {
                let out = dir.join(format!("{name}-{k}"));
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
            "{name}: {points} cases in {:.2} s wall (median of 3; range {:.2}-{:.2} s)",
            walls[1], walls[0], walls[2]
        );
    }
}

/// Resident memory of process `pid` (MiB), from /proc.
fn rss_mib(pid: u32) -> Option<f64> {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let line = status.lines().find(|l| l.starts_with("VmRSS:"))?;
    let kib: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib / 1024.0)
}

fn soak(dir: &Path) {
    let duration_s: f64 = std::env::var("TESTRIG_SOAK_S")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1800.0);
    let scenario = write_scenario(dir);
    let out = dir.join("soak");
    let mut child = Command::new(env!("CARGO_BIN_EXE_testrig"))
        .args(["run", scenario.to_str().expect("utf-8"), "--pace", "1"])
        .args(["--duration", &duration_s.to_string()])
        .args(["--out", out.to_str().expect("utf-8")])
        .stdout(std::process::Stdio::null())
        .spawn()
        .expect("testrig runs");
    let mut samples: Vec<(f64, f64)> = Vec::new();
    let started = std::time::Instant::now();
    while child.try_wait().expect("waits").is_none() {
        if let Some(rss) = rss_mib(child.id()) {
            samples.push((started.elapsed().as_secs_f64(), rss));
        }
        std::thread::sleep(std::time::Duration::from_secs(10));
    }
    let text = std::fs::read_to_string(out.join("manifest.json")).expect("manifest");
    let m: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    let complete = m["files"].as_array().expect("files").iter().all(|f| {
        std::fs::metadata(out.join(f.as_str().unwrap_or(""))).is_ok_and(|meta| meta.len() > 0)
    });
    let frames = hound::WavReader::open(out.join("recording.wav"))
        .map(|r| u64::from(r.duration()))
        .unwrap_or(0);
    let expected = (duration_s * 51_200.0).round() as u64;
    let mean_over = |from: f64, to: f64| {
        let v: Vec<f64> = samples
            .iter()
            .filter(|(t, _)| (from..to).contains(t))
            .map(|s| s.1)
            .collect();
        v.iter().sum::<f64>() / v.len().max(1) as f64
    };
    let end = samples.last().map_or(0.0, |s| s.0);
    let (fifth, last) = (mean_over(240.0, 300.0), mean_over(end - 60.0, end + 1.0));
    let peak = samples.iter().map(|s| s.1).fold(0.0, f64::max);
    let l = &m["lateness_ms"];
    println!(
        "soak: pace 1 for {duration_s} s: ending {}, {} overruns, lateness p50 {:.3} ms, p99 {:.3} ms, max {:.3} ms over {} releases, CPU {:.1} % of one core; RSS fifth minute {fifth:.1} MiB, last minute {last:.1} MiB (ratio {:.3}), peak {peak:.1} MiB over {} samples; files complete: {complete}; WAV frames {frames} of {expected}",
        m["ending"],
        m["overruns"],
        l["p50"].as_f64().unwrap_or(f64::NAN),
        l["p99"].as_f64().unwrap_or(f64::NAN),
        l["max"].as_f64().unwrap_or(f64::NAN),
        l["releases"],
        100.0 * m["cpu_share_of_one_core"].as_f64().unwrap_or(f64::NAN),
        last / fifth,
        samples.len()
    );
    std::fs::remove_dir_all(&out).ok();
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
    if which.is_empty() || which == "paced-cpu" {
        paced_cpu(&dir);
    }
    if which.is_empty() || which == "campaign" {
        campaign(&dir);
    }
    if which == "soak" {
        soak(&dir);
    }
    std::fs::remove_dir_all(&dir).ok();
}
