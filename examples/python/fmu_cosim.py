"""FMPy drives the 1983 rig's FMU: a co-simulation master ramps the motor's set speed
from rest to 1300 rev/min over 20 s against 2.712 N m, then holds it, and plots the
torque in the gauged (intermediate) shaft with the impacts of the gears. The FMU is any
rig file's plant (`testrig fmu`, docs/fmu.md); FMPy is the importer.

    cargo build --release
    target/release/testrig fmu --rig scenarios/rigs/basmaji-1983.toml --out out/rig.fmu
    python3 -m pip install fmpy matplotlib
    python3 examples/python/fmu_cosim.py out/rig.fmu      # writes out/fmu-cosim.png, beside the FMU
    python3 examples/python/fmu_cosim.py out/rig.fmu out/short.png 8   # the first 8 s only
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from fmpy import simulate_fmu  # noqa: E402

fmu = sys.argv[1] if len(sys.argv) > 1 else "rig.fmu"
out = sys.argv[2] if len(sys.argv) > 2 else str(Path(fmu).with_name("fmu-cosim.png"))
stop_s = float(sys.argv[3]) if len(sys.argv) > 3 else 40.0   # simulated seconds

# The master's input signal: FMPy holds each row's values until the next row's time.
times = np.arange(0.0, 40.0, 0.1)
ramp = np.minimum(times / 20.0, 1.0) * 1300.0
zero = np.zeros_like(times)
signal = np.array(list(zip(times, ramp, np.full_like(times, 2.712), zero, zero)),
                  dtype=[("time", np.float64), ("set_speed_rpm", np.float64),
                         ("load_nm", np.float64), ("oscillating_load_nm", np.float64),
                         ("oscillating_load_hz", np.float64)])
result = simulate_fmu(fmu, stop_time=stop_s, output_interval=0.001, input=signal,
                      output=["speed_motor_rpm", "torque_intermediate_nm", "impacts_gears"])

t = result["time"]
fig, (ax_speed, ax_torque) = plt.subplots(2, 1, figsize=(11, 7), sharex=True,
                                          constrained_layout=True)
ax_speed.plot(t, result["speed_motor_rpm"], lw=0.8, label="motor speed")
ax_speed.plot(times, ramp, "k--", lw=0.8, label="set speed (input)")
ax_speed.set_ylabel("rev/min")
ax_speed.legend(loc="lower right")
ax_speed.set_title("testrig's 1983 rig as an FMU, driven by FMPy: run-up against 2.712 N m")
ax_torque.plot(t, result["torque_intermediate_nm"], lw=0.4, color="C3")
ax_torque.set_ylabel("intermediate shaft torque (N m)")
ax_torque.set_xlabel("time (s)")
impacts = result["impacts_gears"]
ax_torque.text(0.01, 0.95, f"{impacts[-1]} gear impacts in {t[-1]:.0f} s",
               transform=ax_torque.transAxes, va="top")
fig.savefig(out, dpi=110)
print(f"{out}: {len(t)} points, {impacts[-1]} impacts, "
      f"final speed {result['speed_motor_rpm'][-1]:.1f} rev/min")
