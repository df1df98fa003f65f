//! Helpers the end-to-end tests of `testrig run` and `testrig sweep` share.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

pub fn testrig(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_testrig"))
        .args(args)
        .output()
        .expect("the binary runs")
}

/// The JSON object a successful run of the binary printed (else fails with its stderr).
pub fn json(output: &Output) -> serde_json::Value {
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).expect("one JSON object")
}

/// Runs the binary with `args`, checks that it succeeded (else fails with its stderr) and
/// returns its stdout.
pub fn testrig_ok(args: &[&str]) -> String {
    let output = testrig(args);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8_lossy(&output.stdout).into_owned()
}

/// A fresh folder in the temp directory for one test's files: removed when it goes out of
/// scope, kept where the test failed (a panic is unwinding), its path then printed.
pub struct Scratch {
    path: PathBuf,
}

impl Scratch {
    /// The folder's path.
    pub fn path(&self) -> &Path {
        &self.path
    }
}

impl std::ops::Deref for Scratch {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.path
    }
}

impl AsRef<Path> for Scratch {
    fn as_ref(&self) -> &Path {
        &self.path
    }
}

impl AsRef<std::ffi::OsStr> for Scratch {
    fn as_ref(&self) -> &std::ffi::OsStr {
        self.path.as_os_str()
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        if std::thread::panicking() {
            eprintln!("kept for the failed test: {}", self.path.display());
        } else {
            std::fs::remove_dir_all(&self.path).ok();
        }
    }
}

/// A fresh, empty [`Scratch`] folder named after `name` and this process.
pub fn folder(name: &str) -> Scratch {
    let path = std::env::temp_dir().join(format!("testrig-e2e-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&path).ok();
    std::fs::create_dir_all(&path).expect("temp folder");
    Scratch { path }
}

pub fn scenario(name: &str) -> String {
    format!("{}/scenarios/{name}.toml", env!("CARGO_MANIFEST_DIR"))
}

/// Runs `scenario_path` unpaced with `extra` arguments into a fresh folder; checks success.
pub fn run_ok(tag: &str, scenario_path: &str, extra: &[&str]) -> (Scratch, serde_json::Value) {
    let out = folder(tag);
    let mut args = vec!["run", scenario_path, "--out", out.to_str().expect("utf-8")];
    if !extra.contains(&"--pace") {
        args.extend(["--pace", "max"]);
    }
    args.extend(extra);
    let output = testrig(&args);
    assert!(
        output.status.success(),
        "{tag}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    let manifest = read_manifest(&out);
    (out, manifest)
}

pub fn read_manifest(out: &Path) -> serde_json::Value {
    let text = std::fs::read_to_string(out.join("manifest.json")).expect("manifest.json");
    serde_json::from_str(&text).expect("JSON")
}

/// Every file the manifest lists exists and is not empty; no `.partial` file is left.
pub fn check_files(out: &Path, manifest: &serde_json::Value) {
    for f in manifest["files"].as_array().expect("files") {
        let path = out.join(f.as_str().expect("name"));
        let size = std::fs::metadata(&path).map(|m| m.len()).unwrap_or(0);
        assert!(size > 0, "{} missing or empty", path.display());
    }
    for entry in std::fs::read_dir(out).expect("folder") {
        let name = entry.expect("entry").file_name();
        assert!(
            !name.to_string_lossy().contains(".partial"),
            "{name:?} left half-written"
        );
    }
}

pub fn has_file(manifest: &serde_json::Value, name: &str) -> bool {
    manifest["files"]
        .as_array()
        .expect("files")
        .iter()
        .any(|f| f == name)
}

/// (frequency, power, alias flag) of each line of a spectrum CSV.
pub fn spectrum(path: &Path) -> Vec<(f64, f64, bool)> {
    let text = std::fs::read_to_string(path).expect("spectrum CSV");
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| {
            let cols: Vec<&str> = l.split(',').collect();
            (
                cols[0].parse().expect("frequency"),
                cols[1].parse().expect("power"),
                !cols[2].is_empty(),
            )
        })
        .collect()
}

/// Rows of a CSV file as maps from header to text.
pub fn csv_rows(path: &Path) -> Vec<std::collections::HashMap<String, String>> {
    let mut reader = csv::Reader::from_path(path).expect("CSV");
    let header: Vec<String> = reader
        .headers()
        .expect("header")
        .iter()
        .map(String::from)
        .collect();
    reader
        .records()
        .map(|r| {
            let r = r.expect("row");
            header
                .iter()
                .cloned()
                .zip(r.iter().map(String::from))
                .collect()
        })
        .collect()
}

pub fn number(row: &std::collections::HashMap<String, String>, key: &str) -> f64 {
    row[key].parse().expect("number")
}

/// `--set` before each of `items`, then `extra`.
pub fn sets<'a>(items: &[&'a str], extra: &[&'a str]) -> Vec<&'a str> {
    let mut args: Vec<&str> = items.iter().flat_map(|item| ["--set", *item]).collect();
    args.extend(extra);
    args
}

/// Fails the test, naming the modules and the command that installs them, unless
/// `python3` can import every one of `modules`.
pub fn require_python(modules: &[&str]) {
    let probe = Command::new("python3")
        .args(["-c", &format!("import {}", modules.join(", "))])
        .output();
    let missing = match probe {
        Ok(out) if out.status.success() => return,
        Ok(out) => String::from_utf8_lossy(&out.stderr)
            .lines()
            .last()
            .unwrap_or("an import failed")
            .to_string(),
        Err(e) => format!("python3 does not run: {e}"),
    };
    panic!(
        "needs the Python modules {} ({missing}); install them with `python3 -m pip install -r tests/requirements.txt`",
        modules.join(", ")
    );
}

/// Runs the Python check `script` (a path under `tests/`) with the testrig binary and a
/// scratch folder `tag`, after checking its `modules` import; fails if it fails.
pub fn run_python_check(script: &str, tag: &str, modules: &[&str]) {
    require_python(modules);
    let dir = folder(tag);
    let status = Command::new("python3")
        .arg(format!("{}/tests/{script}", env!("CARGO_MANIFEST_DIR")))
        .arg(env!("CARGO_BIN_EXE_testrig"))
        .arg(dir.path())
        .status()
        .expect("python3");
    assert!(status.success(), "{script} failed");
}

/// The path of the shipped rig file `name` (`scenarios/rigs/NAME.toml`).
pub fn rig_file(name: &str) -> String {
    format!("{}/scenarios/rigs/{name}.toml", env!("CARGO_MANIFEST_DIR"))
}

/// The JSON a successful testrig command prints.
pub fn json_of(args: &[&str]) -> serde_json::Value {
    let out = testrig(args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON")
}

/// Writes `text` as the rig file `name.toml` in `dir` and runs `modes --rig` on it: the
/// stderr of its refusal (fails if it was accepted or panicked).
pub fn refused_rig(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).expect("written");
    let out = testrig(&["modes", "--rig", path.to_str().expect("utf-8")]);
    assert!(!out.status.success(), "{name} accepted");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(!stderr.contains("panicked"), "{stderr}");
    stderr
}

/// The shipped planetary bench's text (`scenarios/rigs/planetary-bench.toml`), each of
/// `edits` (from, to) made once, every `from` asserted there.
pub fn shipped_bench(edits: &[(&str, &str)]) -> String {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/scenarios/rigs/planetary-bench.toml"
    );
    let text = std::fs::read_to_string(path).expect("shipped bench");
    edits.iter().fold(text, |t, (from, to)| {
        assert!(t.contains(from), "{from:?} in the bench");
        t.replacen(from, to, 1)
    })
}

/// The shipped bench with one pair always (a stiffness that does not change in contact:
/// static solutions, energy).
pub fn single_pair_bench() -> String {
    let pairs = ", pairs = \"alternating\"";
    shipped_bench(&[(pairs, ""), (pairs, "")])
}

/// The shipped bench with one pair always, its sun floating on a soft bearing of
/// `sun_bearing` N/m and its planets on their pins' bearings, with `more` after the
/// planets' inertia (a pin error, say).
pub fn bench_in_the_plane(sun_bearing: &str, more: &str) -> String {
    let sun = format!(
        "name = \"sun\"\nmass_kg = 0.4\nbearing_stiffness_n_per_m = {sun_bearing}\nbearing_damping_ns_per_m = 200.0\n"
    );
    let planets = format!(
        "planet_inertia_kgm2 = 0.0015\nplanet_mass_kg = 0.66\nplanet_bearing_stiffness_n_per_m = 1.0e8\nplanet_bearing_damping_ns_per_m = 500.0\n{more}"
    );
    let pairs = ", pairs = \"alternating\"";
    shipped_bench(&[
        (pairs, ""),
        (pairs, ""),
        ("name = \"sun\"\n", &sun),
        ("planet_inertia_kgm2 = 0.0015\n", &planets),
    ])
}

/// Runs `simulate --rig rig` at `rpm` and `load` N m, settled `settle` s, for `seconds`,
/// its signals into `out`, with `more` arguments (fails with its stderr if refused).
pub fn simulate_rig(
    rig: &str,
    (rpm, load): (&str, &str),
    (settle, seconds): (&str, &str),
    out: &std::path::Path,
    more: &[&str],
) {
    let mut args = vec![
        "simulate",
        "--rig",
        rig,
        "--rpm",
        rpm,
        "--load",
        load,
        "--settle",
        settle,
        "--duration",
        seconds,
        "--out",
        out.to_str().expect("utf-8"),
    ];
    args.extend_from_slice(more);
    testrig_ok(&args);
}

/// The number `field` of the entry named `name` in the JSON array `report[list]` (a
/// `simulate --json` summary's `bodies` or `shafts`).
pub fn named_number(report: &serde_json::Value, list: &str, name: &str, field: &str) -> f64 {
    report[list]
        .as_array()
        .unwrap_or_else(|| panic!("no {list} in {report}"))
        .iter()
        .find(|entry| entry["name"] == name)
        .unwrap_or_else(|| panic!("no {name} in {list}"))[field]
        .as_f64()
        .unwrap_or_else(|| panic!("{list} {name}: {field} is no number"))
}
