//! `testrig panel` on a rig file's scenario (issue 33, item 3: the panel takes rig
//! files): live commands reach the plant of any rig, and the panel judges its motion.

mod common;
mod panel_support;

use std::time::Duration;

use common::{folder, scenario};
use panel_support::Panel;

const WAIT: Duration = Duration::from_secs(120);

/// The two-stage rig on the panel: under its reversing oscillating load both meshes
/// strike (the impact count climbs); the motor follows a new set speed (the tacho DVM
/// reads 1000 rev/min); a brake load with no oscillating part lets it settle, and after
/// 15 s of settling and a 10 s window the judge names its motion: the teeth in contact,
/// the shafts ringing down from the change.
#[test]
fn the_panel_drives_a_rig_files_rig_and_judges_its_motion() {
    let out = folder("panel-rig-file");
    let panel = Panel::start(&out, &[&scenario("two-stage-run"), "--pace", "10"]);
    let (_, info) = panel.get("/api/info");
    assert!(info.contains("\"scenario\":\"two-stage-run\""), "{info}");
    let rattling = panel.wait_for(WAIT, |s| s["impacts"].as_u64().unwrap_or(0) > 100);
    assert!(
        rattling["simulated_s"].as_f64().expect("time") < 10.0,
        "{rattling}"
    );
    let mut changed_s = 0.0;
    for command in [
        r#"{"cmd": "set_speed", "rpm": 1000}"#,
        r#"{"cmd": "set_oscillating_load", "nm": 0, "hz": 0}"#,
        r#"{"cmd": "set_load", "nm": 40}"#,
    ] {
        let (status, reply) = panel.command(command);
        assert_eq!(status, 200, "{command}: {reply}");
        assert_eq!(reply["ok"], true, "{command}: {reply}");
        changed_s = reply["at_s"].as_f64().expect("a time");
    }
    panel.wait_for(WAIT, |s| {
        (s["dvm_rpm"].as_f64().unwrap_or(0.0) - 1000.0).abs() < 15.0
    });
    // Once the 15 s of settling are over, no tooth strikes any more.
    let settled = panel.wait_for(WAIT, |s| {
        s["simulated_s"].as_f64().unwrap_or(0.0) > changed_s + 15.0
    });
    let settled_impacts = settled["impacts"].as_u64().expect("count");
    let judged = panel.wait_for(WAIT, |s| {
        s["motion"]
            .as_str()
            .is_some_and(|m| m != "settling" && !m.is_empty())
    });
    // Lightly damped, the shafts still ring from the step 25 s later: two
    // modes at incommensurate frequencies, which the judge calls quasi-periodic; with the
    // ringing gone it would be at rest. Neither rattles, nor is chaotic.
    let motion = judged["motion"].as_str().expect("a motion");
    assert!(
        ["no-vibration", "quasi-periodic"].contains(&motion),
        "judged {motion}"
    );
    assert_eq!(
        judged["impacts"].as_u64().expect("count"),
        settled_impacts,
        "teeth struck under a steady load"
    );
    let (status, reply) = panel.command(r#"{"cmd": "quit"}"#);
    assert_eq!(status, 200, "{reply}");
    let (status, stderr) = panel.wait();
    assert!(status.success(), "{stderr}");
}
