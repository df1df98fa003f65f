"""pyvisa (with the pure-Python pyvisa-py backend) drives the live rig over SCPI, as a lab
script does (run by the Rust test `pyvisa_drives_the_rig`, tests/scpi.rs):

identify; set speed and load; refusals read with pyvisa's default (ASCII) encoding; 10 Hanning averages at 200 Hz span; the spectrum read as
REAL,32 (query_binary_values) and as ASCII (query_ascii_values); the half-order line at
1300 rev/min and 2.712 N m found; the same spectrum as the panel's JSON API within
float32 rounding; then examples/python/scpi_rehearsal.py at three speeds.

    python3 tests/scpi/pyvisa_check.py target/release/testrig OUT_DIR
"""

import json
import subprocess
import sys
import urllib.request
from pathlib import Path

import numpy as np
import pyvisa

ROOT = Path(__file__).resolve().parents[2]


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        sys.exit(1)


def start_panel(testrig, out, pace):
    panel = subprocess.Popen(
        [testrig, "panel", "--listen", "127.0.0.1:0", "--scpi", "127.0.0.1:0",
         "--pace", str(pace), "--out", out, "--replace"],
        stdout=subprocess.PIPE, text=True)
    url = panel.stdout.readline().split("http://")[1].split("/")[0]
    visa = panel.stdout.readline().split("SCPI at ")[1].split(";")[0].split(" ")[0]
    return panel, url, visa


def main():
    testrig, out = sys.argv[1], Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    panel, url, visa = start_panel(testrig, out / "panel", 50)
    try:
        rm = pyvisa.ResourceManager("@py")
        inst = rm.open_resource(visa, read_termination="\n", write_termination="\n",
                                timeout=120_000)
        idn = inst.query("*IDN?")
        check(idn.startswith("testrig,"), f"*IDN? {idn}")
        inst.write("*RST;*CLS")
        inst.write("RIG:SPEED 1300;LOAD 2.712")
        inst.write("SENSE:FREQUENCY:SPAN 200;:SENS:WINDOW:TYPE HANNING;:AVERAGE:COUNT 10;STATE ON")
        check(inst.query("SYST:ERR?").startswith("0,"), "settings taken without error")
        # pyvisa decodes answers as ASCII by default (the encoding is left as it is): a
        # refusal's range, and a header of bytes beyond ASCII echoed back, must decode.
        inst.write("SENS:FREQ:SPAN -5")
        refusal = inst.query("SYST:ERR?")
        check(refusal.startswith("-222,") and "0.001 to " in refusal,
              f"a range refused in ASCII through pyvisa's default encoding: {refusal}")
        inst.write_raw("RIG:SP\u00c9ED 1\n".encode("utf-8"))
        echoed = inst.query("SYST:ERR?")
        check(echoed.startswith("-1") and "\\xC3\\x89" in echoed,
              f"a header beyond ASCII echoed as \\xNN: {echoed}")
        while float(inst.query("RIG:TIME?")) < 60.0:     # settled (docs/physics.md)
            pass
        inst.write("INIT:IMM")
        check(inst.query("*OPC?") == "1", "*OPC? after 10 averages")
        inst.write("FORMAT:DATA REAL,32")
        real = np.array(inst.query_binary_values("CALC:DATA?", datatype="f",
                                                 is_big_endian=True))
        freq = np.array(inst.query_binary_values("CALC:X:DATA?", datatype="f",
                                                 is_big_endian=True))
        inst.write("FORM ASC")
        text = np.array(inst.query_ascii_values("CALC:DATA?"))
        check(len(real) == len(text) == len(freq) and len(real) > 100,
              f"{len(real)} lines as REAL,32 and ASCII")
        check(np.allclose(real, text.astype(np.float32), rtol=0, atol=0),
              "REAL,32 is the ASCII spectrum rounded to float32")
        state = json.load(urllib.request.urlopen(f"http://{url}/api/state"))
        power = np.array(state["spectrum"]["power_v2"])
        check(state["spectrum"]["averages"] == 10 and np.array_equal(power, text),
              "the JSON API shows the same spectrum")
        half = np.argmin(np.abs(freq - 1300 / 120))
        db = 10 * np.log10(real[half - 1:half + 2].max() / np.median(real[half + 3:half + 20]))
        check(db > 20, f"the half-order line at {freq[half]:.2f} Hz stands {db:.0f} dB above its neighbours")
        alias = np.array(inst.query_ascii_values("CALC:ALIAS:DATA?"))
        check(len(alias) == len(text), "the alias truth, line by line (9.91E37: none)")
        inst.close()
    finally:
        panel.terminate()
        panel.wait(timeout=60)
    panel, url, visa = start_panel(testrig, out / "rehearsal", 50)
    try:
        done = subprocess.run([sys.executable, ROOT / "examples" / "python" / "scpi_rehearsal.py",
                               visa, out / "scpi-rehearsal.png"], capture_output=True, text=True)
        print(done.stdout, done.stderr)
        check(done.returncode == 0 and "1300" in done.stdout, "the rehearsal example ran")
    finally:
        panel.terminate()
        panel.wait(timeout=60)


if __name__ == "__main__":
    main()
