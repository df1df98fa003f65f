//! The condition indicators of a sweep's cases (issue 35): every case carries the driven
//! gear's indicators in `cases.csv`, from the same synchronous average `testrig simulate`
//! takes of the same window.

mod common;

use common::{csv_rows, folder, number, testrig};

/// Issue 35, item 3: every case carries the driven gear's condition indicators in
/// `cases.csv`, from the same synchronous average `testrig simulate` takes of the same
/// window: at 1300 rev/min and 2.712 N m (period 2: half the revolutions differ from the
/// other half, a residual of 0.3 N m) they agree with simulate's to the printed digits.
#[test]
fn cases_carry_the_condition_indicators_simulate_gives_for_the_same_window() {
    let dir = folder("sweep-condition");
    let out = dir.join("out");
    let file = format!(
        "{}/scenarios/thesis-campaign.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let done = testrig(&[
        "sweep",
        &file,
        "--set",
        "grid.rpm=[1300]",
        "--set",
        "grid.load_nm=[2.712]",
        "--out",
        out.to_str().expect("utf-8"),
    ]);
    assert!(
        done.status.success(),
        "{}",
        String::from_utf8_lossy(&done.stderr)
    );
    let row = csv_rows(&out.join("cases.csv")).remove(0);
    let sim = common::json_of(&[
        "simulate",
        "--preset",
        "basmaji-1983-rig",
        "--rpm",
        "1300",
        "--load",
        "2.712",
        "--rate",
        "10240",
        "--settle",
        "60",
        "--duration",
        "30",
        "--json",
    ]);
    let condition = &sim["condition"];
    for (column, key) in [
        ("fm0", "fm0"),
        ("fm4", "fm4"),
        ("na4", "na4"),
        ("sideband_level", "sideband_level"),
        ("residual_rms_nm", "residual_rms_nm"),
    ] {
        let (case, point) = (number(&row, column), condition[key].as_f64().expect(key));
        assert!(
            (case / point - 1.0).abs() < 1e-5,
            "{column}: the case {case}, simulate {point}"
        );
    }
    assert!(number(&row, "residual_rms_nm") > 0.1, "{row:?}");
    assert_eq!(
        row["revolutions_averaged"],
        condition["revolutions_averaged"].to_string()
    );
    std::fs::remove_dir_all(&dir).ok();
}
