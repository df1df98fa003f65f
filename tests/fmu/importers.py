"""Third-party importers judge the FMU of the 1983 rig file (run by the Rust test
`fmu_importers_agree`, tests/fmu_export.rs):

1. FMPy's validator and the FMU Manipulation Toolbox's checker (the FMI 3.0 schema and
   its semantic rules) find no problem;
2. FMPy simulates 5 s from rest at 1300 rev/min and 2.712 N m: every shaft torque at
   every 1 ms output point equals `testrig simulate --rig ... --approach rest` within
   1e-9 relative, and 1 ms and 10 ms communication steps agree at every 10 ms point,
   also with the inputs set before every step (FMPy's input=), constant and stepped;
3. the Toolbox's container (its own C runtime, loading our binary) run by FMPy gives
   the same shaft torques;
4. a value out of range is refused through FMPy with the FMU's message;
5. the example examples/python/fmu_cosim.py runs (its first 8 s) and writes its plot.

    python3 tests/fmu/importers.py target/release/testrig OUT_DIR
"""

import csv
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
from fmpy import simulate_fmu
from fmpy.validation import validate_fmu

ROOT = Path(__file__).resolve().parents[2]
RIG = ROOT / "scenarios" / "rigs" / "basmaji-1983.toml"
TORQUES = ["torque_input_nm", "torque_intermediate_nm", "torque_final_nm"]
POINT = {"set_speed_rpm": 1300.0, "load_nm": 2.712}


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        sys.exit(1)


def tool(name):
    """A console command of the FMU Manipulation Toolbox, through this Python."""
    call = f"import sys; from fmu_manipulation_toolbox.cli.{name} import {name}; sys.exit({name}())"
    return [sys.executable, "-c", call]


def relative_error(got, want):
    scale = max(np.max(np.abs(want)), 1e-12)
    return float(np.max(np.abs(got - want)) / scale)


def main():
    testrig, out = Path(sys.argv[1]), Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    fmu = out / "basmaji-1983.fmu"
    subprocess.run([testrig, "fmu", "--rig", RIG, "--out", fmu], check=True)

    problems = validate_fmu(str(fmu))
    check(problems == [], f"fmpy validate: {problems or 'no problems'}")
    report = subprocess.run(tool("fmutool") + ["-input", fmu, "-check"],
                            capture_output=True, text=True)
    text = report.stdout + report.stderr
    check("compliant with FMI-3.0" in text and "No semantic error" in text
          and report.returncode == 0, "FMU Manipulation Toolbox: schema and semantic checks")

    sim = out / "simulate"
    subprocess.run([testrig, "simulate", "--rig", RIG, "--rpm", "1300", "--load", "2.712",
                    "--approach", "rest", "--settle", "0", "--duration", "5.01",
                    "--rate", "10000", "--out", sim, "--replace"], check=True,
                   stdout=subprocess.DEVNULL)
    with open(sim / "signals.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    reference = {name: np.array([float(r[name]) for r in rows]) for name in TORQUES}

    fine = simulate_fmu(str(fmu), stop_time=5.0, output_interval=0.001,
                        start_values=POINT, output=TORQUES + ["impacts_gears"])
    coarse = simulate_fmu(str(fmu), stop_time=5.0, output_interval=0.01,
                          start_values=POINT, output=TORQUES)
    index = np.round(fine["time"] * 10000).astype(int)
    check(len(fine) == 5001 and index[-1] < len(rows), "FMPy: 5001 output points")
    worst = max(relative_error(fine[n], reference[n][index]) for n in TORQUES)
    check(worst <= 1e-9, f"FMPy vs testrig simulate: shaft torques within {worst:.1e} relative")
    worst_steps = max(relative_error(coarse[n], fine[n][::10]) for n in TORQUES)
    check(worst_steps <= 1e-9,
          f"1 ms vs 10 ms communication steps: within {worst_steps:.1e} relative")
    # A co-simulation master sets its connected inputs before every step (FMPy's input=):
    # held constant they must give the start values' run, and a speed stepped at 2 s (a
    # communication point of both) the same motion with 1 ms and 10 ms steps.
    for label, rows in [("constant", [(0.0, 1300.0), (5.0, 1300.0)]),
                        ("stepped to 1000 rev/min at 2 s",
                         [(0.0, 1300.0), (2.0, 1300.0), (2.0, 1000.0), (5.0, 1000.0)])]:
        signals = np.array([(t, rpm, 2.712) for t, rpm in rows],
                           dtype=[("time", np.float64), ("set_speed_rpm", np.float64),
                                  ("load_nm", np.float64)])
        every_ms = simulate_fmu(str(fmu), stop_time=5.0, output_interval=0.001,
                                input=signals, output=TORQUES)
        every_10ms = simulate_fmu(str(fmu), stop_time=5.0, output_interval=0.01,
                                  input=signals, output=TORQUES)
        worst = max(relative_error(every_10ms[n], every_ms[n][::10]) for n in TORQUES)
        check(worst <= 1e-9, f"inputs set every step ({label}): 1 ms vs 10 ms steps "
                             f"within {worst:.1e} relative")
        if label == "constant":
            worst = max(relative_error(every_ms[n], fine[n]) for n in TORQUES)
            check(worst <= 1e-9, f"constant inputs set every step vs start values only: "
                                 f"within {worst:.1e} relative")
    impacts = int(fine["impacts_gears"][-1])
    check(impacts > 100, f"the run-up rattles: {impacts} gear impacts in 5 s")

    container_dir = out / "container"
    container_dir.mkdir(exist_ok=True)
    (container_dir / "rig.fmu").write_bytes(fmu.read_bytes())
    (container_dir / "container.json").write_text(json.dumps({
        "name": "container.fmu", "step_size": 0.001, "auto_input": True,
        "auto_output": True, "fmu": ["rig.fmu"]}))
    subprocess.run(tool("fmucontainer") + ["-container", "container.json", "-fmi", "3",
                    "-fmu-directory", "."], cwd=container_dir, check=True,
                   capture_output=True)
    wrapped = simulate_fmu(str(container_dir / "container.fmu"), stop_time=5.0,
                           output_interval=0.001, start_values=POINT, output=TORQUES)
    worst = max(relative_error(wrapped[n], reference[n][index]) for n in TORQUES)
    check(worst <= 1e-9,
          f"the Toolbox's container runtime (a second C importer): within {worst:.1e} relative")

    messages = []
    try:
        simulate_fmu(str(fmu), stop_time=0.1, start_values={"set_speed_rpm": 5000.0},
                     logger=lambda *args: messages.append(args[-1].decode()))
        refused = False
    except Exception:
        refused = True
    check(refused and any("above speed_ceiling_rpm" in m for m in messages),
          f"a set speed above the ceiling is refused with the FMU's message: {messages[-1:]}")

    png = out / "fmu-cosim.png"
    # The example's first 8 s (its whole 40 s, a master setting the ramped speed every
    # millisecond, takes minutes: each change rebuilds the modes the harmonics turn in).
    subprocess.run([sys.executable, ROOT / "examples" / "python" / "fmu_cosim.py", fmu, png,
                    "8"], check=True)
    check(png.stat().st_size > 10_000, f"the example wrote {png.name}")


if __name__ == "__main__":
    main()
