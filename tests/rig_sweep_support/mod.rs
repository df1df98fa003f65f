//! What the rig-file sweep tests share (`sweep_rig_file.rs`, `sweep_rig_file_lab.rs`): the
//! chain and analyser their sweeps take, and a sweep file written with them.

use std::path::Path;

/// The chain and analyser every rig-file sweep of these tests takes (the thesis's chain, Fmax 1 kHz).
const CHAIN: &str = r#"
[chain.slip_rings]
broadband_rms = 0.005
per_rev_amplitude = 0.01
contact_noise_v_rms = 2e-6

[chain.amplifier]
carrier_hz = 2000
output_lowpass_hz = 1000

[chain.filter]
kind = "butterworth"
order = 8
cutoff_hz = 1000

[analyser]
fmax_hz = 1000
block = 1024
averages = 4
window = "hanning"
range_v = 5
"#;

/// Writes a sweep file into `dir` with `body` (its rig, grid, case and record tables)
/// and the chain above; returns its path.
pub fn sweep_file(dir: &Path, body: &str) -> String {
    let path = dir.join("sweep.toml");
    let text = format!("name = \"rig-file-sweep\"\nseed = 7\nrate_hz = 10240\n{body}\n{CHAIN}");
    std::fs::write(&path, text).expect("write the sweep");
    path.to_string_lossy().into_owned()
}
