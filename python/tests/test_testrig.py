"""The Python package against physics and against the command line's engine."""

import json
import math
import subprocess
import time
from pathlib import Path

import numpy as np
import pytest
import testrig

ROOT = Path(__file__).resolve().parents[2]
BINARY = ROOT / "target" / "release" / "testrig"


def test_simulate_returns_every_true_signal_with_units():
    sim = testrig.simulate(1300, 2.712, preset="basmaji-1983-rig", settle_s=5, duration_s=2,
                           rate_hz=10240)
    signals = sim["signals"]
    assert len(signals["time_s"]) == 2 * 10240
    # The preset's rig file names the columns after its bodies, shafts and mesh.
    for name in ["angle_motor_rad", "speed_brake_rpm", "torque_intermediate_nm",
                 "force_gears_n", "motor_torque_nm", "contact_gears", "strain_intermediate_ue"]:
        assert len(signals[name]) == len(signals["time_s"]), name
    # The mean output-shaft torque carries the load (2.712 N m plus the preset's
    # 0.6 N m residual drag at the brake).
    mean = signals["torque_intermediate_nm"].mean()
    assert abs(mean - 3.312) < 0.05, mean
    # The driven gear turns at the set speed, 1300 rev/min, in its own sense.
    assert abs(signals["speed_driven_gear_rpm"].mean() - 1300) < 5
    assert sim["summary"]["motion"]["motion"]
    impacts = sim["impacts"]
    assert len(impacts["time_s"]) == sim["summary"]["impacts"]
    assert set(np.unique(impacts["flank"])) <= {-1, 1}


@pytest.mark.skipif(not BINARY.exists(), reason="needs the CLI: cargo build --release")
def test_simulate_is_the_command_lines_engine():
    # No preset named on either side: the one default (basmaji-1983) serves both.
    args = ["simulate", "--rpm", "1100", "--load", "0", "--settle", "3", "--duration", "2",
            "--rate", "10240", "--json"]
    cli = json.loads(subprocess.run([str(BINARY), *args], check=True,
                                    capture_output=True, text=True).stdout)
    py = testrig.simulate(1100, 0, settle_s=3, duration_s=2, rate_hz=10240)["summary"]
    bare = testrig.simulate(1100, 0, settle_s=3, duration_s=2, rate_hz=10240,
                            signals=False)
    assert bare["signals"] == {}
    for key in ["impacts", "impacts_per_tooth", "torque_mean_nm", "torque_ac_rms_nm",
                "regime", "motion", "revolutions"]:
        assert py[key] == cli[key], key
        assert bare["summary"][key] == cli[key], key


@pytest.mark.skipif(not BINARY.exists(), reason="needs the CLI: cargo build --release")
def test_the_approach_reaches_the_motion_the_command_line_does():
    # 1500 rev/min, 5.424 N m on the rig with its drive as built: the slow run-up arrives
    # on period 1, the run-down on period 2 (tests/approach.rs), here by Python.
    point = dict(preset="basmaji-1983-drive", settle_s=60, duration_s=30, rate_hz=10240,
                 signals=False)
    up = testrig.simulate(1500, 5.424, approach="up", **point)["summary"]
    down = testrig.simulate(1500, 5.424, approach="down", **point)["summary"]
    assert up["approach"] == {"start": "ramp", "from_rpm": 250.0, "ramp_s": 125.0}
    assert (up["motion"]["motion"], down["motion"]["motion"]) == ("period-1", "period-2")
    args = ["simulate", "--preset", "basmaji-1983-drive", "--rpm", "1500", "--load", "5.424",
            "--rate", "10240", "--settle", "60", "--duration", "30", "--approach", "up",
            "--json"]
    cli = json.loads(subprocess.run([str(BINARY), *args], check=True,
                                    capture_output=True, text=True).stdout)
    for key in ["torque_ac_rms_nm", "impacts", "motion", "simulated_s"]:
        assert up[key] == cli[key], key
    with pytest.raises(testrig.TestrigError, match="static, rest, up, down"):
        testrig.simulate(1500, 0, approach="sideways")
    with pytest.raises(testrig.TestrigError, match="ramp rate 0"):
        testrig.simulate(1500, 0, approach="up", ramp_rate=0)


def test_overrides_and_refusals_name_the_argument():
    with pytest.raises(testrig.TestrigError, match="load_nm 99"):
        testrig.simulate(1300, 99, settle_s=1, duration_s=1)
    with pytest.raises(testrig.TestrigError, match="rpm -5"):
        testrig.simulate(-5, 1, settle_s=1, duration_s=1)
    with pytest.raises(testrig.TestrigError, match="teeth"):
        testrig.simulate(600, 1, settle_s=1, duration_s=1, set={"teeth": -3})
    # 31 teeth (the thesis's name, set on the preset's rig): the driven gear turns at
    # 600 rev/min still, its impacts fall on 31 teeth.
    sim = testrig.simulate(600, 2.712, settle_s=1, duration_s=1, rate_hz=5120,
                           set={"teeth": 31})
    assert len(sim["summary"]["impacts_per_tooth"]) == 31
    struck = sim["impacts"]["driver_tooth"]
    assert len(struck) > 0 and struck.min() >= 1 and struck.max() <= 31


def test_analyse_agrees_with_scipy_welch():
    scipy_signal = _require("scipy.signal")
    rng = np.random.default_rng(7)
    rate = 4096.0
    t = np.arange(int(rate * 20)) / rate
    x = 0.5 * np.sin(2 * np.pi * 100.0 * t) + 0.05 * rng.standard_normal(len(t))
    out = testrig.analyse(x, rate, fmax_hz=rate / 2, block=1024, window="hanning",
                          averages=40, bits=24, range=1.0)
    f, pxx = scipy_signal.welch(x, fs=rate, window="hann", nperseg=1024, noverlap=0,
                                scaling="spectrum", detrend=False)
    line = np.argmin(abs(out["frequency_hz"] - 100.0))
    # The tone's power: 0.5²/2 = 0.125 in both.
    assert abs(out["power"][line] / 0.125 - 1) < 0.02
    assert abs(pxx[np.argmin(abs(f - 100.0))] / 0.125 - 1) < 0.02
    # The noise floor agrees away from the tone (median over the band, within 10 %).
    band = (out["frequency_hz"] > 300) & (out["frequency_hz"] < 1500)
    ours = np.median(out["power"][band])
    theirs = np.median(pxx[(f > 300) & (f < 1500)])
    assert abs(ours / theirs - 1) < 0.1, (ours, theirs)


def test_analyse_flags_an_alias_where_the_truth_puts_it():
    rate = 8192.0
    t = np.arange(int(rate * 10)) / rate
    # A 700 Hz tone analysed with fmax 200 Hz (fs 400 Hz) without a filter folds to
    # |700 - 2 * 400| = 100 Hz.
    x = np.sin(2 * np.pi * 700.0 * t)
    out = testrig.analyse(x, rate, fmax_hz=200, block=256, averages=4, range=1.0)
    line = np.argmax(out["power"])
    assert abs(out["frequency_hz"][line] - 100.0) < 2.0
    assert abs(out["alias_of_hz"][line] - 700.0) < 2.0
    with pytest.raises(testrig.TestrigError, match="block 1000"):
        testrig.analyse(x, rate, fmax_hz=200, block=1000)


def _files(folder):
    return {p.name: p.read_bytes() for p in sorted(Path(folder).iterdir())
            if p.name != "manifest.json"}


@pytest.mark.skipif(not BINARY.exists(), reason="needs the CLI: cargo build --release")
def test_run_writes_the_command_lines_bytes(tmp_path):
    scenario = ROOT / "scenarios" / "subharmonic-2712nm.toml"
    sets = {"duration_s": 40}
    subprocess.run([str(BINARY), "run", str(scenario), "--pace", "max", "--set",
                    "duration_s=40", "--out", str(tmp_path / "cli")], check=True,
                   capture_output=True)
    result = testrig.run(scenario, out=tmp_path / "py", set=sets)
    cli, py = _files(tmp_path / "cli"), _files(tmp_path / "py")
    assert cli.keys() == py.keys()
    different = [name for name in cli if cli[name] != py[name]]
    assert not different, different
    # Read back: the recorded output-shaft torque and the filter's volts, units kept.
    recording = result["recording"]
    assert recording["units"]["torque_intermediate_shaft_nm"] == "N m"
    assert recording["units"]["filter_v"] == "V"
    torque = recording["channels"]["torque_intermediate_shaft_nm"]
    assert abs(len(torque) / recording["rate_hz"] - 40) < 0.01
    assert result["manifest"]["ending"] == "completed"
    assert result["spectra"], "spectra read back"
    spectrum = result["spectra"][0]
    assert len(spectrum["frequency_hz"]) == len(spectrum["power"])
    assert "label" in result["readings"]


def test_read_recording_reads_a_runs_wav_and_refuses_a_file_that_is_no_wav(tmp_path):
    result = testrig.run(ROOT / "scenarios" / "subharmonic-2712nm.toml", out=tmp_path / "run",
                         set={"duration_s": 10})
    recording = testrig.read_recording(tmp_path / "run" / "recording.wav")
    assert recording["units"] == result["recording"]["units"]
    for name, samples in recording["channels"].items():
        assert np.array_equal(samples, result["recording"]["channels"][name]), name
    text = tmp_path / "notes.wav"
    text.write_text("not a recording\n")
    with pytest.raises(testrig.TestrigError) as refused:
        testrig.read_recording(text)
    message = str(refused.value)
    assert "notes.wav" in message and "RIFF" in message and "sidecar" not in message, message


def test_dir_lists_the_packages_own_names_only():
    listed = dir(testrig)
    assert listed == sorted(testrig.__all__)
    for module in ["np", "csv", "json", "shutil", "tempfile", "time", "weakref", "Path"]:
        assert module not in listed, module
    assert {"simulate", "run", "sweep", "analyse", "Rig", "read_recording"} <= set(listed)


def test_run_takes_a_dict_shaped_like_the_toml(tmp_path):
    scenario = {
        "name": "from-python",
        "duration_s": 2,
        "schedule": {"speed_rpm": 600, "load_nm": 2.712},
        "record": {"signals": ["strain", "torque_intermediate_shaft_nm"],
                   "formats": ["wav"]},
    }
    result = testrig.run(scenario, out=tmp_path)
    rec = result["recording"]
    assert rec["units"]["strain"] == "µε"
    # The gauged shaft: 3.85 µε per N m of its torque (Ø20 mm, G 82.7 GPa).
    ratio = rec["channels"]["strain"] / rec["channels"]["torque_intermediate_shaft_nm"]
    assert abs(np.median(ratio) - 8 / (math.pi * 0.02 ** 3 * 82.7e9) * 1e6) < 1e-3
    with pytest.raises(testrig.TestrigError, match="speed_rpm"):
        testrig.run({**scenario, "schedule": {"speed_rpm": -5, "load_nm": 0}}, out=tmp_path)


def test_sweep_returns_its_cases(tmp_path):
    sweep = {
        "name": "small",
        "seed": 1,
        "rate_hz": 10240,
        "rig": {"preset": "basmaji-1983-rig"},
        "grid": {"rpm": [600, 1300], "load_nm": [2.712]},
        "case": {"settle_s": 5, "measure_s": 5},
        "analyser": {"fmax_hz": 200, "block": 512, "averages": 2},
    }
    table = testrig.sweep(sweep, out=tmp_path)
    rpm = list(table["rpm"])
    assert sorted(rpm) == [600.0, 1300.0]
    assert (tmp_path / "cases.csv").exists()


def test_a_live_rig_follows_its_commands_and_stops_cleanly(tmp_path):
    scenario = ROOT / "scenarios" / "panel.toml"
    with testrig.Rig(scenario, out=tmp_path, pace=20) as rig:
        reply = rig.set_speed(900)
        assert reply["ok"] and reply["at_s"] >= 0
        rig.set_load(1.5)
        with pytest.raises(testrig.TestrigError, match="speed: -10 rev.min is not allowed"):
            rig.set_speed(-10)
        # The motor follows (0.5 Hz speed loop): within 2 % after 10 s of rig time.
        deadline = reply["at_s"] + 10
        while rig.state()["simulated_s"] < deadline:
            time.sleep(0.05)
        block = rig.read()
        speed = block["channels"]["speed1_rad_s"]
        assert abs(speed.mean() - 900 * math.pi / 30) < 0.02 * 900 * math.pi / 30
        assert len(speed) == len(block["channels"]["strain"])
        state = rig.state()
        assert state["speed_set_rpm"] == 900 and state["load_set_nm"] == 1.5
        assert state["overruns"] == 0
    manifest = json.loads((tmp_path / "manifest.json").read_text())
    assert manifest["ending"] in ("completed", "interrupted")


def test_a_rig_with_scpi_answers_a_socket_client_and_shows_its_settings():
    import socket

    scenario = ROOT / "scenarios" / "panel.toml"
    with testrig.Rig(scenario, pace=20, scpi="127.0.0.1:0") as rig:
        parts = rig.scpi_address.split("::")
        assert parts[0] == "TCPIP" and parts[3] == "SOCKET", rig.scpi_address
        with socket.create_connection((parts[1], int(parts[2])), timeout=30) as s:
            stream = s.makefile("rwb")

            def query(line):
                stream.write(line.encode() + b"\n")
                stream.flush()
                return stream.readline().decode().strip()

            assert query("*IDN?").startswith("testrig,panel")
            stream.write(b"RIG:SPE 900;LOAD 1.5\n")
            assert query("SYST:ERR?") == '0,"No error"'
            assert query("RIG:SPE 9999;:SYST:ERR?").startswith("-222,")
        state = rig.state()
        assert state["speed_set_rpm"] == 900 and state["load_set_nm"] == 1.5


def test_read_right_after_a_command_waits_for_the_next_block():
    scenario = ROOT / "scenarios" / "panel.toml"
    with testrig.Rig(scenario, pace=20) as rig:
        reply = rig.set_speed(900)
        block = rig.read()
        assert block is not None
        # A block made after the command: it starts at or after the command took effect.
        assert block["start_s"] >= reply["at_s"]
        later = rig.read()
        assert later["start_s"] > block["start_s"]
        folder = rig.out
        assert folder.exists()
    assert not folder.exists(), "the temporary folder of a Rig goes at close"


def test_temporary_outputs_go_with_the_result_unless_kept():
    import gc
    small = {"name": "tiny", "duration_s": 1, "schedule": {"speed_rpm": 600, "load_nm": 1.0}}
    result = testrig.run(small)
    folder = result["out"]
    assert (folder / "manifest.json").exists()
    del result
    gc.collect()
    assert not folder.exists(), "a temporary run folder goes when the result is dropped"
    kept = testrig.run(small, keep=True)
    del_folder = kept["out"]
    del kept
    gc.collect()
    assert (del_folder / "manifest.json").exists(), "keep=True keeps the folder"
    import shutil
    shutil.rmtree(del_folder)


def _require(module):
    """`module`, or a skip saying why (a failure where CI sets TESTRIG_REQUIRE_ALL)."""
    import importlib
    import os
    try:
        return importlib.import_module(module)
    except ImportError:
        if os.environ.get("TESTRIG_REQUIRE_ALL") == "1":
            raise
        pytest.skip(f"needs {module}: python3 -m pip install {module}")


def test_the_examples_run(tmp_path, monkeypatch):
    _require("matplotlib")
    import runpy
    examples = ROOT / "examples" / "python"
    monkeypatch.chdir(tmp_path)
    runpy.run_path(str(examples / "aliasing_study.py"), run_name="__main__")
    assert (tmp_path / "aliasing-study.png").stat().st_size > 10_000
    dataset = runpy.run_path(str(examples / "labelled_dataset.py"))
    dataset["main"](tmp_path / "dataset")
    rows = (tmp_path / "dataset" / "labels.csv").read_text().splitlines()
    assert len(rows) == 1 + 36
    assert (tmp_path / "dataset" / "case-035.wav").exists()


@pytest.mark.parametrize("call", [
    "testrig.simulate(1300, 2.712, settle_s=100000, duration_s=1)",
    "testrig.run({'name': 'long', 'duration_s': 100000, "
    "'schedule': {'speed_rpm': 1300, 'load_nm': 2.712}}, out=OUT)",
])
def test_ctrl_c_stops_a_long_call(call, tmp_path):
    import signal
    import sys
    script = f"import testrig\nOUT = {str(tmp_path)!r}\nprint('started', flush=True)\n{call}\n"
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, cwd=tmp_path)
    assert child.stdout.readline().strip() == "started"
    time.sleep(1.0)
    sent = time.perf_counter()
    child.send_signal(signal.SIGINT)
    _, err = child.communicate(timeout=30)
    stopped_s = time.perf_counter() - sent
    assert "KeyboardInterrupt" in err, err
    assert stopped_s < 3.0, stopped_s
