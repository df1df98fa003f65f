"""testrig in Python: the virtual 1983 gear rig (F. Basmaji, The City University, London).

The same engine as the `testrig` command line, on numpy arrays:

- ``simulate(rpm, load_nm, ...)``: the plant alone at a steady point; every true signal
  as an array (units in the names), the impacts and the summary (the physics judge's
  motion with its numbers).
- ``analyse(signal, rate_hz, fmax_hz, ...)``: the Fourier analyser (with its ADC and an
  optional anti-alias filter) on any array, with the ground truth of which lines are
  aliases.
- ``run(scenario, ...)``: a scenario (a path, or a dict shaped like the TOML) run
  unpaced into a folder, byte for byte the files ``testrig run`` writes, read back: the
  recording's channels, the spectra with their alias truth, the meter readings.
- ``sweep(scenario, ...)``: a sweep run into a folder, its ``cases.csv`` as a table (a
  pandas DataFrame when pandas is installed, else a dict of arrays).

Errors are ``TestrigError`` with the command line's message, the argument named.
"""

import csv
import json
import tempfile
from pathlib import Path

import numpy as np

from ._testrig import TestrigError, __version__, analyse, read_recording, run_into, simulate
from ._testrig import sweep_into

__all__ = ["TestrigError", "__version__", "analyse", "run", "simulate", "sweep"]


def _folder(out, prefix):
    if out is None:
        return Path(tempfile.mkdtemp(prefix=prefix))
    return Path(out)


def _column(values):
    """A CSV column as floats where every value is a number, else as strings."""
    try:
        return np.array([float(v) if v != "" else np.nan for v in values])
    except ValueError:
        return np.array(values)


def _read_table(path):
    """A CSV file (``#`` lines are metadata) as a dict of columns."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    header, body = rows[0], rows[1:]
    return {name: _column([row[k] for row in body]) for k, name in enumerate(header)}


def _read_spectrum(path):
    """A spectrum CSV: its metadata (the ``# key: value`` lines) and its lines."""
    metadata = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("# ") and ": " in line:
                key, value = line[2:].rstrip("\n").split(": ", 1)
                metadata[key] = value
    table = _read_table(path)
    return {
        "name": path.stem,
        "metadata": metadata,
        "frequency_hz": table["frequency_hz"],
        "power": table["power"],
        "alias_of_hz": table["alias_of_hz"],
    }


def run(scenario, out=None, set=None, seed=None, duration_s=None):
    """Runs `scenario` (a path, or a dict shaped like the TOML file) unpaced into `out`
    (a new temporary folder if None): the files ``testrig run`` writes, byte for byte.
    `set` changes scenario keys (``{"schedule.speed_rpm": 1500}``), `seed` and
    `duration_s` (s) as the CLI's flags. Returns a dict: ``out`` (the folder),
    ``manifest``, ``recording`` (``rate_hz``, ``channels`` name -> array, ``units``,
    ``sidecar``; None without a WAV), ``spectra`` (one dict a measurement:
    ``frequency_hz``, ``power`` in V², ``alias_of_hz`` NaN where not an alias,
    ``metadata``), ``readings`` (readings.csv by column; None without meters)."""
    folder = _folder(out, "testrig-run-")
    manifest = json.loads(run_into(scenario, str(folder), set, seed, duration_s))
    wav = folder / "recording.wav"
    recording = None
    if wav.exists():
        recording = read_recording(str(wav))
        recording["sidecar"] = json.loads((folder / "recording.wav.json").read_text())
    readings = folder / "readings.csv"
    return {
        "out": folder,
        "manifest": manifest,
        "recording": recording,
        "spectra": [_read_spectrum(p) for p in sorted(folder.glob("spectrum-*.csv"))],
        "readings": _read_table(readings) if readings.exists() else None,
    }


def sweep(scenario, out=None, set=None, jobs=None):
    """Runs the sweep `scenario` (a path or a dict) into `out` (a new temporary folder if
    None) on `jobs` workers (every core if None), as ``testrig sweep``; returns its
    ``cases.csv``: a pandas DataFrame when pandas is installed, else a dict of arrays."""
    folder = _folder(out, "testrig-sweep-")
    sweep_into(scenario, str(folder), set, jobs)
    table = _read_table(folder / "cases.csv")
    try:
        import pandas
    except ImportError:
        return table
    return pandas.DataFrame(table)
