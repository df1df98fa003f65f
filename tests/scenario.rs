//! Scenario files: `--set` edits of the text, and the pacing statistics.

use testrig::runtime::LatenessHistogram;
use testrig::scenario::apply_override;

const TEXT: &str = "name = \"t\"\nduration_s = 1\n\n[schedule]\nspeed_rpm = 600\nload_nm = 2.712\n\n[chain.filter]\nkind = \"bessel\"\n";

fn parse(text: &str) -> toml::Table {
    toml::from_str(text).expect("valid TOML")
}

#[test]
fn set_replaces_a_key_in_place_keeping_every_line_where_it_was() {
    let edited = apply_override(TEXT, "schedule.speed_rpm=1300").expect("applies");
    assert_eq!(edited.lines().count(), TEXT.lines().count());
    assert_eq!(
        edited.lines().nth(4),
        Some("speed_rpm = 1300 # --set schedule.speed_rpm=1300")
    );
    assert_eq!(
        parse(&edited)["schedule"]["speed_rpm"].as_integer(),
        Some(1300)
    );
}

#[test]
fn set_adds_a_key_to_its_table_or_the_table_itself() {
    let edited = apply_override(TEXT, "chain.filter.cutoff_hz=180").expect("applies");
    assert_eq!(
        parse(&edited)["chain"]["filter"]["cutoff_hz"].as_integer(),
        Some(180)
    );
    assert_eq!(
        parse(&edited)["chain"]["filter"]["kind"].as_str(),
        Some("bessel")
    );
    let edited = apply_override(TEXT, "rig.set.teeth=31").expect("applies");
    assert_eq!(parse(&edited)["rig"]["set"]["teeth"].as_integer(), Some(31));
    let edited = apply_override(TEXT, "seed=9").expect("applies");
    assert_eq!(parse(&edited)["seed"].as_integer(), Some(9));
    assert!(edited.find("seed = 9").expect("added") < edited.find("[schedule]").expect("table"));
}

#[test]
fn set_takes_toml_values_and_bare_words_as_strings() {
    let edited = apply_override(TEXT, "chain.filter.kind=none").expect("applies");
    assert_eq!(
        parse(&edited)["chain"]["filter"]["kind"].as_str(),
        Some("none")
    );
    let edited = apply_override(TEXT, "survey.loads_nm=[0.0, 2.712]").expect("applies");
    assert_eq!(
        parse(&edited)["survey"]["loads_nm"]
            .as_array()
            .map(Vec::len),
        Some(2)
    );
    assert!(apply_override(TEXT, "no-equals-sign").is_err());
    assert!(apply_override(TEXT, "schedule.=3").is_err());
}

#[test]
fn lateness_quantiles_come_from_the_histogram_to_its_10_us_bins() {
    let mut h = LatenessHistogram::default();
    for k in 0..1000 {
        h.add(k as f64 * 1e-6);
    }
    h.add(0.5);
    assert_eq!(h.count(), 1001);
    // The upper edge of the quantile's bin: never below the true quantile, at most one bin above.
    for (q, truth) in [(0.5, 500e-6), (0.99, 990e-6)] {
        let got = h.quantile_s(q);
        assert!(got >= truth && got <= truth + 10e-6 + 1e-12, "{q}: {got}");
    }
    assert_eq!(h.max_s(), 0.5);
    assert_eq!(h.quantile_s(1.0), 0.5);
    assert_eq!(LatenessHistogram::default().quantile_s(0.99), 0.0);
}

#[test]
fn set_takes_a_bare_rig_parameter_or_backlash_as_simulate_does() {
    let edited = apply_override(TEXT, "teeth=31").expect("applies");
    assert_eq!(parse(&edited)["rig"]["set"]["teeth"].as_integer(), Some(31));
    let edited = apply_override(TEXT, "backlash_mm=1.46").expect("applies");
    assert_eq!(parse(&edited)["rig"]["backlash_mm"].as_float(), Some(1.46));
    let edited = apply_override(TEXT, "preset=basmaji-1983-calibrated").expect("applies");
    assert_eq!(
        parse(&edited)["rig"]["preset"].as_str(),
        Some("basmaji-1983-calibrated")
    );
    // Top-level scenario keys stay where they are.
    let edited = apply_override(TEXT, "duration_s=3").expect("applies");
    assert_eq!(parse(&edited)["duration_s"].as_integer(), Some(3));
}

/// A table written inline (`[rig]` … `set = { teeth = 30 }`) is edited in place: a
/// `--set rig.set.NAME` once appended a `[rig.set]` table beside it, a duplicate key.
#[test]
fn set_edits_a_table_written_inline() {
    let text = "name = \"t\"\n\n[rig]\npreset = \"basmaji-1983-rig\"\nset = { teeth = 30, addendum_coefficient = 1.0 }\n\n[schedule]\nspeed_rpm = 600\nload_nm = 1\n";
    let edited = apply_override(text, "rig.set.teeth=31").expect("applies");
    let edited = apply_override(&edited, "rig.set.brake_drag_nm=0.8").expect("applies");
    assert_eq!(edited.lines().count(), text.lines().count(), "{edited}");
    let table = parse(&edited);
    let set = &table["rig"]["set"];
    assert_eq!(set["teeth"].as_integer(), Some(31), "{edited}");
    assert_eq!(set["brake_drag_nm"].as_float(), Some(0.8), "{edited}");
    assert_eq!(
        set["addendum_coefficient"].as_float(),
        Some(1.0),
        "{edited}"
    );
    assert!(
        edited.contains("# --set rig.set.brake_drag_nm=0.8"),
        "{edited}"
    );
}
