"""The fault data set as its users read it: pandas for labels.csv and the CSV recordings,
scipy.io.wavfile for the WAVs (run by the Rust test `the_fault_dataset_reads_in_pandas_and_scipy`,
tests/sweep_rig_file.rs).

The shipped scenarios/fault-dataset.toml at one point (300 rev/min, 5.424 N m): 12 cases.
Checks: every case's WAV is 10.24 kHz, two float32 channels, the 4 s window whole, and
equals its CSV (pandas) to float32 rounding; severity 0 is labelled healthy; for each
kind the residual RMS rises with severity; and, from the recording alone, a synchronous
average of the anti-alias filter's output over the keyphasor's revolutions (each
resampled to 360 points, as a condition-monitoring engineer would take it) has its
residual (shaft orders 0-3 and the mesh harmonics taken out) largest within a tooth of
the faulted tooth 7's span (72-84 degrees) for the worst crack, pit and broken tooth,
under the slip rings' noise.

    python3 tests/dataset/read_dataset.py target/release/testrig OUT_DIR
"""

import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
from scipy.io import wavfile

ROOT = Path(__file__).resolve().parents[2]
TEETH = 30
POINTS = 360


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        sys.exit(1)


def synchronous_average(signal, keyphasor):
    """The signal averaged over the keyphasor's whole revolutions, each resampled to POINTS."""
    edges = np.flatnonzero((keyphasor[:-1] < 2.5) & (keyphasor[1:] >= 2.5)) + 1
    revolutions = []
    for a, b in zip(edges[:-1], edges[1:]):
        at = np.linspace(a, b, POINTS, endpoint=False)
        revolutions.append(np.interp(at, np.arange(len(signal)), signal))
    return np.mean(revolutions, axis=0), len(revolutions)


def worst_degrees(average):
    """Where the average's residual (less shaft orders 0-3 and every mesh harmonic) is
    largest (degrees)."""
    spectrum = np.fft.rfft(average)
    order = np.arange(len(spectrum))
    spectrum[(order <= 3) | (order % TEETH == 0)] = 0.0
    residual = np.fft.irfft(spectrum, len(average))
    return float(np.argmax(np.abs(residual))) * 360.0 / POINTS


def main():
    testrig, out = sys.argv[1], Path(sys.argv[2]) / "dataset"
    subprocess.run(
        [testrig, "sweep", str(ROOT / "scenarios/fault-dataset.toml"),
         "--set", "grid.rpm=[300]", "--set", "grid.load_nm=[5.424]", "--out", str(out)],
        check=True)
    labels = pd.read_csv(out / "labels.csv")
    check(len(labels) == 12, f"12 cases labelled ({len(labels)})")
    for _, row in labels.iterrows():
        wav_name, _, csv_name = row["recordings"].split(" ")
        rate, data = wavfile.read(out / wav_name)
        check(rate == 10240 and data.dtype == np.float32 and data.shape == (40960, 2),
              f"case {row['index']}: {rate} Hz, {data.dtype}, {data.shape}")
        table = pd.read_csv(out / csv_name)
        same = np.allclose(table[["filter_v", "keyphasor_v"]].to_numpy(), data,
                           rtol=1e-6, atol=1e-6)
        check(same, f"case {row['index']}: the WAV equals the CSV")
        healthy = row["fault_kind"] == "healthy"
        check(healthy == (row["mesh.gears.fault1.severity"] == 0.0),
              f"case {row['index']}: labelled {row['fault_kind']} at severity "
              f"{row['mesh.gears.fault1.severity']}")
    for kind in ["crack", "pit", "broken"]:
        rows = labels[labels["mesh.gears.fault1.kind"] == kind].sort_values(
            "mesh.gears.fault1.severity")
        residual = rows["residual_rms_nm"].to_numpy()
        check(bool(np.all(np.diff(residual) > 0)),
              f"{kind}: residual RMS rises with severity {residual}")
    for kind in ["crack", "pit", "broken"]:
        row = labels[(labels["mesh.gears.fault1.kind"] == kind)
                     & (labels["mesh.gears.fault1.severity"] == 0.75)].iloc[0]
        _, data = wavfile.read(out / row["recordings"].split(" ")[0])
        average, count = synchronous_average(data[:, 0].astype(float), data[:, 1])
        at = worst_degrees(average)
        check(60.0 <= at <= 96.0,
              f"{kind} 0.75: the recording's average over {count} revolutions departs "
              f"most at {at:.0f} degrees (tooth 7: 72-84)")


if __name__ == "__main__":
    main()
