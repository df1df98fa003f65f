"""The thesis's measurement rehearsed as a lab script over SCPI: at 1100, 1300 and 1500
rev/min against 2.712 N m, wait for the rig to settle, take 10 Hanning averages of the
strain signal at a 200 Hz span, and read the spectrum; print the half-order and
first-order lines and plot the three spectra. The script speaks plain SCPI through pyvisa:
pointed at a bench analyser's address instead (with that instrument's own commands for
the rig), it is the lab's script.

    testrig panel --scpi 127.0.0.1:5025 --pace 20 &
    python3 -m pip install pyvisa pyvisa-py matplotlib
    python3 examples/python/scpi_rehearsal.py TCPIP::127.0.0.1::5025::SOCKET
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pyvisa  # noqa: E402

address = sys.argv[1] if len(sys.argv) > 1 else "TCPIP::127.0.0.1::5025::SOCKET"
out = sys.argv[2] if len(sys.argv) > 2 else "scpi-rehearsal.png"
SETTLE_S = 60.0  # the rig wanders up to 60 s at some points (docs/physics.md)

rm = pyvisa.ResourceManager("@py")
rig = rm.open_resource(address, read_termination="\n", write_termination="\n",
                       timeout=300_000)
print(rig.query("*IDN?"))
rig.write("*RST;*CLS")
rig.write("SENS:FREQ:SPAN 200;:SENS:WIND HANN;:SENS:AVER:COUN 10;STAT ON;:FORM REAL,32")
rig.write("RIG:LOAD 2.712")
fig, ax = plt.subplots(figsize=(10, 5), constrained_layout=True)
for rpm in (1100, 1300, 1500):
    rig.write(f"RIG:SPE {rpm}")
    start = float(rig.query("RIG:TIME?"))
    while float(rig.query("RIG:TIME?")) < start + SETTLE_S:
        pass
    rig.write("INIT")
    rig.query("*OPC?")
    power = np.array(rig.query_binary_values("CALC:DATA?", datatype="f", is_big_endian=True))
    freq = np.array(rig.query_binary_values("CALC:X:DATA?", datatype="f", is_big_endian=True))
    db = 10 * np.log10(power)
    line = {order: db[np.argmin(np.abs(freq - order * rpm / 60))] for order in (0.5, 1.0)}
    motion = rig.query("RIG:MOT?")
    print(f"{rpm} rev/min: half order {line[0.5]:.1f} dB, first order {line[1.0]:.1f} dB "
          f"(V² rms), motion {motion}")
    ax.plot(freq, db, lw=0.8, label=f"{rpm} rev/min ({motion.strip(chr(34))})")
error = rig.query("SYST:ERR?")
assert error.startswith("0,"), error
ax.set_xlabel("frequency (Hz)")
ax.set_ylabel("dB re 1 V² rms")
ax.set_title("SCPI rehearsal: strain spectra at 2.712 N m, 10 Hanning averages")
ax.legend()
fig.savefig(out, dpi=110)
print(f"wrote {out}")
