"""Rig files from Python: the same rig by path and as a dict, its signals named after
it, and the load carried through both stages of the two-stage example."""

import time
import tomllib
from pathlib import Path

import numpy as np
import pytest
import testrig

ROOT = Path(__file__).resolve().parents[2]
TWO_STAGE = ROOT / "scenarios" / "rigs" / "two-stage.toml"


def test_a_rig_file_runs_by_path_and_as_a_dict_with_the_same_numbers():
    by_path = testrig.simulate(1200, 45, rig=TWO_STAGE, settle_s=1, duration_s=0.5,
                               rate_hz=10240)
    with TWO_STAGE.open("rb") as f:
        tables = tomllib.load(f)
    by_dict = testrig.simulate(1200, 45, rig=tables, settle_s=1, duration_s=0.5,
                               rate_hz=10240)
    signals = by_path["signals"]
    assert set(signals) == set(by_dict["signals"])
    for name in signals:
        assert np.array_equal(signals[name], by_dict["signals"][name]), name
    assert len(signals["time_s"]) == 5120
    # 45 N m at the output, 15 N m on the intermediate shaft, 5 N m at the input.
    assert np.mean(signals["torque_output_nm"]) == pytest.approx(45, rel=1e-5)
    assert np.mean(signals["torque_intermediate_nm"]) == pytest.approx(15, rel=1e-5)
    assert np.mean(signals["speed_brake_rpm"]) == pytest.approx(1200 / 9, rel=1e-6)
    assert "strain_output_ue" in signals
    shafts = {s["name"]: s for s in by_path["summary"]["shafts"]}
    assert shafts["input"]["torque_mean_nm"] == pytest.approx(5, rel=1e-5)


def test_set_takes_paths_and_a_bad_one_is_named():
    dragged = testrig.simulate(1200, 45, rig=str(TWO_STAGE), settle_s=1, duration_s=0.5,
                               rate_hz=10240, signals=False,
                               set={"body.wheel1.drag_nms_per_rad": 0.1})
    motor = dragged["summary"]["motor_torque_mean_nm"]
    assert motor == pytest.approx(5 + 0.1 / 9 * 1200 * np.pi / 30, rel=1e-4)
    with pytest.raises(testrig.TestrigError, match="mesh.stage9.backlash_mm"):
        testrig.simulate(600, 10, rig=TWO_STAGE, set={"mesh.stage9.backlash_mm": 0.3})


def test_a_sweep_on_a_rig_file_labels_its_faults(tmp_path):
    # The shipped data set at one point: each kind's residual RMS rises with severity.
    table = testrig.sweep(ROOT / "scenarios" / "fault-dataset.toml", out=tmp_path,
                          set={"grid.rpm": [300], "grid.load_nm": [5.424],
                               "record.formats": ["wav"]})
    assert len(table["rpm"]) == 12
    assert (tmp_path / "labels.csv").exists()
    kinds = list(table["mesh.gears.fault1.kind"])
    severities = list(table["mesh.gears.fault1.severity"])
    residual = list(table["residual_rms_nm"])
    for kind in ["crack", "pit", "broken"]:
        rows = sorted((s, r) for k, s, r in zip(kinds, severities, residual) if k == kind)
        assert all(b[1] > a[1] for a, b in zip(rows, rows[1:])), rows
    assert "measured_fm4" in table


def test_a_rig_file_scenario_runs_and_its_rig_follows_live_commands(tmp_path):
    scenario = ROOT / "scenarios" / "two-stage-run.toml"
    result = testrig.run(scenario, out=tmp_path / "run", set={"duration_s": 6})
    recording = result["recording"]
    assert recording["units"]["torque_intermediate_shaft_nm"] == "N m"
    # The gauged output shaft carries the brake's mean load, 20 N m.
    torque = recording["channels"]["torque_intermediate_shaft_nm"]
    assert np.mean(torque[int(recording["rate_hz"]) * 2:]) == pytest.approx(20, rel=0.02)
    assert result["manifest"]["rig"] == "two-stage"
    with testrig.Rig(scenario, out=tmp_path / "live", pace=20) as rig:
        reply = rig.set_speed(900)
        assert reply["ok"]
        rig.set_oscillating_load(0, 0)
        rig.set_load(45)
        while rig.state()["simulated_s"] < reply["at_s"] + 10:
            time.sleep(0.05)
        block = rig.read()
        # The motor's body follows the set speed (within 2 % after 10 s).
        speed = block["channels"]["speed1_rad_s"]
        assert np.mean(speed) == pytest.approx(900 * np.pi / 30, rel=0.02)
        with pytest.raises(testrig.TestrigError, match="speed"):
            rig.set_speed(-10)
