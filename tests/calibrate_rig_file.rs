//! `testrig calibrate` on a rig file's rig (issue 33, item 3: free parameters by path): a
//! search recovers a shaft's stiffness from the natural frequency it gives, and writes the
//! best as the `[rig.set]` table a sweep file takes.

mod common;

use common::{folder, rig_file, testrig, testrig_ok};

/// The two-stage rig's fundamental (42.6 Hz with its output shaft's 60 000 N m/rad, from
/// the rig's own eigen-solution) as the target: searching that stiffness over 20 000 to
/// 200 000 N m/rad (log scale), the search lands within 2 % of 60 000 (0.2 Hz, the target's tolerance, is 1.3 % of stiffness), and its
/// `rig-set.toml` sets the path to it; a path the rig lacks is refused at its line.
#[test]
fn a_search_on_a_rig_file_recovers_a_shafts_stiffness_from_its_natural_frequency() {
    let dir = folder("calibrate-rig-file");
    let rig = testrig::scenario::read_rig_file(std::path::Path::new(&rig_file("two-stage")))
        .expect("rig");
    let fundamental_hz = rig.natural_frequencies_hz()[0];
    let campaign = dir.join("campaign.toml");
    std::fs::write(
        &campaign,
        format!(
            "name = \"two-stage\"\n[rig]\nfile = \"{}\"\n[grid]\nrpm = [1500]\nload_nm = [50.0]\n[case]\nsettle_s = 2\nmeasure_s = 4\n[analyser]\nfmax_hz = 500\n",
            rig_file("two-stage")
        ),
    )
    .expect("campaign");
    let calibration = |free: &str| {
        format!(
            "name = \"stiffness\"\ncampaign = \"{}\"\nseed = 3\n[search]\nbudget = 48\npopulation = 6\nsigma = 0.3\n[[natural]]\nmode = 1\nhz = {fundamental_hz}\ntolerance_hz = 0.2\n[[free]]\nname = \"{free}\"\nmin = 20000\nmax = 200000\nscale = \"log\"\n",
            campaign.display()
        )
    };
    let file = dir.join("calibration.toml");
    std::fs::write(&file, calibration("shaft.output.stiffness_nm_per_rad")).expect("write");
    let out = dir.join("out");
    testrig_ok(&[
        "calibrate",
        file.to_str().expect("utf-8"),
        "--out",
        out.to_str().expect("utf-8"),
    ]);
    let best: toml::Table = std::fs::read_to_string(out.join("rig-set.toml"))
        .expect("rig-set.toml")
        .parse()
        .expect("TOML");
    let k = best["rig"]["set"]["shaft.output.stiffness_nm_per_rad"]
        .as_float()
        .expect("a number");
    assert!((k / 60_000.0 - 1.0).abs() < 0.02, "found {k} N m/rad");
    std::fs::write(&file, calibration("shaft.nowhere.stiffness_nm_per_rad")).expect("write");
    let refused = testrig(&[
        "calibrate",
        file.to_str().expect("utf-8"),
        "--out",
        dir.join("refused").to_str().expect("utf-8"),
    ]);
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert!(!refused.status.success());
    assert!(
        stderr.contains("calibration.toml:")
            && stderr.contains("free")
            && stderr.contains("shaft.nowhere"),
        "{stderr}"
    );
}
