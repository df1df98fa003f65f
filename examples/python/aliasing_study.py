"""The windowing and aliasing study with a physical signal whose truth is known.

The rig at 1300 rev/min and 2.712 N m with a 3 µm profile error at mesh frequency: its
mesh line stands at 30 × 21.67 = 650 Hz. The analyser is set for a 200 Hz band
(fs = 400 Hz). Without an anti-alias filter the 650 Hz line folds to |650 − 2·400| =
150 Hz, where testrig's ground truth flags it; an 8th-order Butterworth at 180 Hz
removes it. Below: the same signal through uniform, Hanning and flat-top windows
(leakage against amplitude accuracy).

    python3 -m pip install ./python matplotlib
    python3 examples/python/aliasing_study.py      # writes aliasing-study.png
"""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import testrig  # noqa: E402

RATE_HZ = 10240
sim = testrig.simulate(1300, 2.712, settle_s=10, duration_s=40, rate_hz=RATE_HZ,
                       set={"te_mesh_frequency_um": 3})
torque = sim["signals"]["torque_intermediate_nm"]
# The output shaft's strain as the gauges see it (µε per N m of the Ø20 mm shaft).
strain = torque * 8 / (np.pi * 0.02 ** 3 * 82.7e9) * 1e6

fig, axes = plt.subplots(2, 2, figsize=(12, 8), constrained_layout=True)
for ax, (title, filt) in zip(axes[0], [("no anti-alias filter", None),
                                       ("Butterworth 8 at 180 Hz", "butterworth")]):
    # The HP 5451C's 12-bit ADC over the signal's peak: aliases below its quantisation
    # noise are not flagged.
    out = testrig.analyse(strain, RATE_HZ, fmax_hz=200, averages=10, bits=12,
                          filter=filt, cutoff_hz=180)
    f, p = out["frequency_hz"], out["power"]
    aliased = ~np.isnan(out["alias_of_hz"])
    ax.semilogy(f, p, color="tab:green", lw=0.8, label="analyser")
    ax.semilogy(f[aliased], p[aliased], "o", color="tab:red", ms=4,
                label="alias (ground truth)")
    labelled = []
    for k in np.flatnonzero(aliased)[np.argsort(p[aliased])[::-1]]:
        if len(labelled) == 3:
            break
        if any(abs(f[k] - f[j]) < 10 for j in labelled):
            continue
        labelled.append(k)
        ax.annotate(f"{out['alias_of_hz'][k]:.0f} Hz", (f[k], p[k]), fontsize=8,
                    xytext=(4, 4), textcoords="offset points", color="tab:red")
    ax.set(title=f"strain, 1300 rev/min: {title}", xlabel="frequency (Hz)",
           ylabel="power (µε² rms)")
    ax.legend()

ax = axes[1][0]
for window, colour in [("uniform", "tab:gray"), ("hanning", "tab:blue"),
                       ("flattop", "tab:orange")]:
    out = testrig.analyse(strain, RATE_HZ, fmax_hz=200, averages=10, bits=12,
                          window=window, filter="butterworth", cutoff_hz=180)
    ax.semilogy(out["frequency_hz"], out["power"], lw=0.8, color=colour, label=window)
ax.set(title="windows: leakage around the running-speed lines", xlabel="frequency (Hz)",
       ylabel="power (µε² rms)", xlim=(0, 60))
ax.legend()

ax = axes[1][1]
t = sim["signals"]["time_s"]
window = t < t[0] + 0.3
ax.plot((t[window] - t[0]) * 1e3, strain[window], lw=0.8)
ax.set(title=f"the true strain (motion: {sim['summary']['motion']['motion']})",
       xlabel="time (ms)", ylabel="strain (µε)")
fig.savefig("aliasing-study.png", dpi=110)
print("aliasing-study.png written")
