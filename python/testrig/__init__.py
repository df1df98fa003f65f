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
- ``Rig(scenario, ...)``: a live rig paced in real time, driven as the panel drives it
  (every panel command, the panel's state) and read block by block; a context manager.
- ``read_recording(path)``: a WAV recording testrig wrote, its channels by name.
- ``sweep(scenario, ...)``: a sweep run into a folder, its ``cases.csv`` as a table (a
  pandas DataFrame when pandas is installed, else a dict of arrays).

Errors are ``TestrigError`` with the command line's message, the argument named.
"""

import csv
import json
import shutil
import tempfile
import time
import weakref
from pathlib import Path

import numpy as np

from ._testrig import TestrigError, __version__, analyse, run_into, simulate
from ._testrig import read_recording as _read_recording
from ._testrig import Rig as _Rig
from ._testrig import sweep_into

__all__ = ["Rig", "TestrigError", "__version__", "analyse", "read_recording", "run", "simulate",
           "sweep"]


def __dir__():
    """What ``dir(testrig)`` lists: the package's own names, not the modules it uses."""
    return sorted(__all__)


def read_recording(path):
    """The channels of a WAV recording testrig wrote (``run``'s ``recording.wav``, a sweep
    case's ``recordings/case-NNNNN.wav``): a dict of ``rate_hz``, ``channels`` (name ->
    array, in its unit), ``units`` and ``sidecar`` (the JSON sidecar ``<file>.json`` that
    names and scales the channels). A file that is no WAV is refused as such."""
    recording = _read_recording(str(path))
    recording["sidecar"] = json.loads(Path(f"{path}.json").read_text())
    return recording


class _Folder:
    """Where a call writes: `out`, or a new temporary folder that is removed with this
    object (when the result holding it is dropped) unless `keep`."""

    def __init__(self, out, prefix, keep):
        self._remover = None
        if out is not None:
            self.path = Path(out)
            return
        self.path = Path(tempfile.mkdtemp(prefix=prefix))
        if not keep:
            self._remover = weakref.finalize(self, shutil.rmtree, str(self.path), True)

    def remove(self):
        """Removes the folder now if it is a temporary one not kept."""
        if self._remover is not None:
            self._remover()


class RunResult(dict):
    """What ``run`` returns: a dict (see ``run``) that also holds its temporary folder,
    removed when the result is dropped unless ``keep=True`` was asked for."""

    __slots__ = ("_folder",)


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


def run(scenario, out=None, set=None, seed=None, duration_s=None, replace=False, keep=False):
    """Runs `scenario` (a path, or a dict shaped like the TOML file) unpaced into `out`
    (if None, a new temporary folder, removed when the result is dropped unless
    `keep`): the files ``testrig run`` writes, byte for byte.
    `set` changes scenario keys (``{"schedule.speed_rpm": 1500}``), `seed` and
    `duration_s` (s) and `replace` (remove another scenario's run from `out`) as the
    CLI's flags. Returns a dict: ``out`` (the folder),
    ``manifest``, ``recording`` (``rate_hz``, ``channels`` name -> array, ``units``,
    ``sidecar``; None without a WAV), ``spectra`` (one dict a measurement:
    ``frequency_hz``, ``power`` in the signal's unit squared (V² through the chain,
    N² for a force sensor), ``alias_of_hz`` NaN where not an alias,
    ``metadata``), ``readings`` (readings.csv by column; None without meters)."""
    holder = _Folder(out, "testrig-run-", keep)
    folder = holder.path
    manifest = json.loads(run_into(scenario, str(folder), set, seed, duration_s, replace))
    wav = folder / "recording.wav"
    recording = None
    if wav.exists():
        recording = read_recording(wav)
    readings = folder / "readings.csv"
    result = RunResult(
        out=folder,
        manifest=manifest,
        recording=recording,
        spectra=[_read_spectrum(p) for p in sorted(folder.glob("spectrum-*.csv"))],
        readings=_read_table(readings) if readings.exists() else None,
    )
    result._folder = holder
    return result


def sweep(scenario, out=None, set=None, jobs=None, resume=False, keep=False):
    """Runs the sweep `scenario` (a path or a dict) into `out` on `jobs` workers (every
    core if None), as ``testrig sweep``; returns its ``cases.csv``: a pandas DataFrame
    when pandas is installed, else a dict of arrays. Without `out` the sweep runs in a
    temporary folder that is removed once the table is read, unless `keep` (then the
    folder's path is in the table's ``attrs["out"]`` or under the key ``"out"``).
    Ctrl-C starts no further case; ``resume=True`` then finishes the rest."""
    holder = _Folder(out, "testrig-sweep-", keep)
    folder = holder.path
    try:
        sweep_into(scenario, str(folder), set, jobs, resume)
        table = _read_table(folder / "cases.csv")
    finally:
        holder.remove()
    if out is not None or keep:
        table_out = str(folder)
    else:
        table_out = None
    try:
        import pandas
    except ImportError:
        if table_out is not None:
            table["out"] = table_out
        return table
    frame = pandas.DataFrame(table)
    if table_out is not None:
        frame.attrs["out"] = table_out
    return frame


def _command(cmd, **fields):
    return {"cmd": cmd, **{k: v for k, v in fields.items() if v is not None}}


class Rig:
    """A live rig: `scenario` (a path or a dict, e.g. ``scenarios/panel.toml``) paced at
    `pace` (1: real time), writing into `out` (if None, a new temporary folder removed at
    ``close`` unless `keep`). Use it in a ``with``
    block; leaving it (normally, by an exception or Ctrl-C) stops the rig and writes its
    manifest. Each method sends the panel's command of the same name (docs/api.md) and
    waits for the rig to carry it out, returning ``{"ok", "at_s"}`` (the virtual time it
    took effect, s); a refusal raises ``TestrigError`` with the reason. With `scpi`
    ("127.0.0.1:5025"; port 0 picks a free one) lab scripts drive the same rig over SCPI
    (docs/scpi.md) at ``scpi_address``, a VISA resource name."""

    def __init__(self, scenario, out=None, pace=1.0, set=None, keep=False, scpi=None):
        self._folder = _Folder(out, "testrig-rig-", keep)
        self.out = self._folder.path
        self._rig = _Rig(scenario, str(self.out), pace, set, scpi)
        self.scpi_address = self._rig.scpi_address

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def close(self):
        """Stops the rig, closes its files and writes its manifest; returns the folder
        (removed now if it was a temporary one not kept)."""
        self._rig.close()
        self._folder.remove()
        return self.out

    def send(self, command):
        """Any panel command as a dict, e.g. ``{"cmd": "set_speed", "rpm": 1300}``."""
        return self._rig.send(command)

    def state(self):
        """The state as the panel shows it: set points, tacho DVM (V, rev/min), RMS meter
        (V), the analyser's display, the scope's trace, overruns, the judged motion."""
        return self._rig.state()

    def read(self, timeout_s=5.0):
        """The next block of every signal made after this call: ``{"start_s", "rate_hz",
        "channels": name -> array}`` (units in the names, ``strain`` in µε). Waits for it
        up to `timeout_s` (s of wall time), then raises ``TimeoutError``."""
        latest = self._rig.read()
        after_s = None if latest is None else latest["start_s"]
        deadline = time.monotonic() + timeout_s
        while True:
            block = self._rig.read()
            if block is not None and (after_s is None or block["start_s"] > after_s):
                return block
            if time.monotonic() >= deadline:
                raise TimeoutError(f"no new block within {timeout_s} s")
            time.sleep(0.005)

    def set_speed(self, rpm):
        """Motor speed set point (rev/min)."""
        return self.send(_command("set_speed", rpm=rpm))

    def set_load(self, nm):
        """Brake load (N m)."""
        return self.send(_command("set_load", nm=nm))

    def set_oscillating_load(self, nm, hz):
        """The function generator on the brake: amplitude (N m; 0 off) at `hz` (Hz)."""
        return self.send(_command("set_oscillating_load", nm=nm, hz=hz))

    def set_amplifier_gain(self, gain):
        """Carrier amplifier gain (V per V of bridge output)."""
        return self.send(_command("set_amplifier_gain", gain=gain))

    def set_filter(self, kind, order=None, cutoff_hz=None):
        """Anti-alias filter: "none", "butterworth" or "bessel", order 1-12, cut-off (Hz)."""
        return self.send(_command("set_filter", kind=kind, order=order, cutoff_hz=cutoff_hz))

    def set_adc_range(self, range_v):
        """The ADC's ±full scale (V)."""
        return self.send(_command("set_adc_range", range_v=range_v))

    def set_analyser(self, fmax_hz=None, block=None, window=None, averages=None,
                     overlap_pct=None):
        """The analyser's band (Hz), block, window, averages and overlap (%)."""
        return self.send(_command("set_analyser", fmax_hz=fmax_hz, block=block,
                                  window=window, averages=averages,
                                  overlap_pct=overlap_pct))

    def start_average(self):
        """A fresh average from now."""
        return self.send(_command("start_average"))

    def hold_average(self):
        """Stops the average (written as it stands)."""
        return self.send(_command("hold_average"))

    def set_scope(self, volts_per_div=None, seconds_per_div=None, trigger_v=None,
                  mode=None):
        """The scope's scales (V/div, s/div), trigger level (V) and mode ("auto", "single")."""
        return self.send(_command("set_scope", volts_per_div=volts_per_div,
                                  seconds_per_div=seconds_per_div, trigger_v=trigger_v,
                                  mode=mode))

    def arm_scope(self):
        """A stored sweep from now."""
        return self.send(_command("arm_scope"))

    def record(self, on):
        """Starts or stops the recording of the scenario's [record] signals."""
        return self.send(_command("record", on=on))

    def save_displays(self):
        """Writes the spectrum and scope on screen."""
        return self.send(_command("save_displays"))
