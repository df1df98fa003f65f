"""Type stubs of testrig (units in every name)."""

import os
from pathlib import Path
from typing import Any, Literal, Mapping, Optional, TypedDict, Union

import numpy as np
import numpy.typing as npt

__version__: str

class TestrigError(Exception):
    """A value testrig refuses, or a run that failed; the message names the argument."""

class Impacts(TypedDict):
    time_s: npt.NDArray[np.float64]
    mesh: list[str]
    flank: npt.NDArray[np.int8]
    """+1 drive flank, -1 back flank."""
    closing_speed_m_s: npt.NDArray[np.float64]
    driver_tooth: npt.NDArray[np.uint32]
    driven_tooth: npt.NDArray[np.uint32]

class Simulation(TypedDict):
    signals: dict[str, npt.NDArray[Any]]
    """Named after the rig (a preset's is its rig file's): time_s, speed_<body>_rpm,
    angle_<body>_rad, torque_<shaft>_nm, contact_<mesh> (+1/0/-1), force_<mesh>_n,
    motor_torque_nm, strain_<gauged shaft>_ue."""
    impacts: Impacts
    summary: dict[str, Any]
    """As `testrig simulate --json`: rig, preset (None for a rig file), regime, motion
    (the physics judge), impacts per tooth, the judged shaft's torque mean and RMS
    (N m), each body, shaft and mesh, simulated_s, wall_s, realtime_factor, and
    condition: the gauged shaft's torque averaged over the revolutions of the watched
    gear, with FM0, FM4, NA4, M6A, M8A, the sideband level and the residual RMS (None
    under two revolutions)."""

def simulate(
    rpm: float,
    load_nm: float,
    preset: str = "basmaji-1983",
    settle_s: float = 60.0,
    duration_s: float = 10.0,
    rate_hz: float = 51200.0,
    set: Optional[Mapping[str, Union[float, int, str, bool]]] = None,
    signals: bool = True,
    rig: Optional[Union[str, os.PathLike[str], Mapping[str, Any]]] = None,
    approach: Literal["static", "rest", "up", "down"] = "static",
    ramp_rate: float = 10.0,
) -> Simulation:
    """The plant at `rpm` rev/min and `load_nm` N m, reached by `approach`: "static"
    (in steady motion from the static load), "rest" (from standstill, the knob at the
    set speed; settling counts from t = 0), "up" (the lab's slow run-up from 250 rev/min)
    or "down" (its run-down from 2000 rev/min), the ramps at `ramp_rate` rev/min per s;
    then `settle_s` s settling (from a ramp's end) and `duration_s` s measured at
    `rate_hz` Hz. Where motions coexist, each approach may reach another; the summary's
    `approach` says how the point was reached. `set` overrides the rig's numbers by path
    (`testrig params --rig`, `mesh.gears.backlash_mm`) or, on a preset, by the
    thesis's names too (`testrig params`); `signals=False` returns no signal arrays
    (impacts and summary only). Releases the GIL; Ctrl-C stops it.

    `rig`: a rig file (docs/rig-files.md) or a dict of its tables, run instead of the
    preset, as `testrig simulate --rig`. A preset is the short name of its rig file
    (`scenarios/rigs/NAME.toml`): the same signals, impacts and summary either way."""

class Analysed(TypedDict):
    frequency_hz: npt.NDArray[np.float64]
    power: npt.NDArray[np.float64]
    """Power of each line in the signal's unit squared (RMS)."""
    alias_of_hz: npt.NDArray[np.float64]
    """The true frequency (Hz) a line is an alias of; NaN where it is none."""
    averages: int
    adc_overloads: int
    floor: float
    """The ADC's quantisation noise in one line (the signal's unit squared)."""

def analyse(
    signal: npt.NDArray[np.float64],
    rate_hz: float,
    fmax_hz: float,
    block: int = 1024,
    window: str = "hanning",
    averages: int = 10,
    overlap_pct: float = 0.0,
    sampling: str = "thesis",
    bits: int = 12,
    range: Optional[float] = None,
    filter: Optional[str] = None,
    filter_order: int = 8,
    cutoff_hz: Optional[float] = None,
) -> Analysed:
    """The averaged spectrum of `signal` sampled at `rate_hz` Hz, up to `fmax_hz` Hz,
    through an optional low-pass `filter` ("butterworth" or "bessel"), an ADC of `bits`
    over ±`range` (default: the signal's peak) and the analyser."""

Scenario = Union[str, "os.PathLike[str]", Mapping[str, Any]]

class Recording(TypedDict):
    rate_hz: float
    channels: dict[str, npt.NDArray[np.float64]]
    units: dict[str, str]
    """Each channel's unit: V, µε, N m, rad/s…"""
    sidecar: dict[str, Any]

def read_recording(path: Union[str, "os.PathLike[str]"]) -> Recording:
    """The channels of a WAV recording testrig wrote, by the names its JSON sidecar
    (`<file>.json`) gives, as arrays in their units; a file that is no WAV is refused as
    such, and one without its sidecar names the sidecar it looked for."""

class MeasuredSpectrum(TypedDict):
    name: str
    metadata: dict[str, str]
    frequency_hz: npt.NDArray[np.float64]
    power: npt.NDArray[np.float64]
    """The analysed signal's power (RMS), in its unit squared (V² through the chain)."""
    alias_of_hz: npt.NDArray[np.float64]

class Run(TypedDict):
    out: Path
    manifest: dict[str, Any]
    recording: Optional[Recording]
    spectra: list[MeasuredSpectrum]
    readings: Optional[dict[str, npt.NDArray[Any]]]

def run(
    scenario: Scenario,
    out: Optional[Union[str, "os.PathLike[str]"]] = None,
    set: Optional[Mapping[str, Any]] = None,
    seed: Optional[int] = None,
    duration_s: Optional[float] = None,
    replace: bool = False,
    keep: bool = False,
) -> Run:
    """A scenario run unpaced into `out`: the files `testrig run` writes, byte for byte,
    read back. Without `out`, a temporary folder removed when the result is dropped
    unless `keep`. Ctrl-C stops it, its files kept."""

def sweep(
    scenario: Scenario,
    out: Optional[Union[str, "os.PathLike[str]"]] = None,
    set: Optional[Mapping[str, Any]] = None,
    jobs: Optional[int] = None,
    resume: bool = False,
    keep: bool = False,
) -> Any:
    """A sweep run into `out`; its cases.csv as a pandas DataFrame (pandas installed) or
    a dict of arrays. Without `out`, a temporary folder removed once the table is read
    unless `keep` (its path then in `attrs["out"]`, or the key "out")."""

class Reply(TypedDict):
    ok: bool
    at_s: float
    """The virtual time the command took effect (s)."""

class Block(TypedDict):
    start_s: float
    rate_hz: float
    channels: dict[str, npt.NDArray[np.float64]]

class Rig:
    """A live rig paced at `pace` (1: real time), driven with the panel's commands; a
    context manager that stops it and writes its manifest on exit (Ctrl-C included)."""
    out: Path
    scpi_address: Optional[str]
    def __init__(self, scenario: Scenario, out: Optional[Union[str, "os.PathLike[str]"]] = None,
                 pace: float = 1.0, set: Optional[Mapping[str, Any]] = None,
                 keep: bool = False, scpi: Optional[str] = None) -> None: ...
    def __enter__(self) -> "Rig": ...
    def __exit__(self, *exc: Any) -> bool: ...
    def close(self) -> Path: ...
    def send(self, command: Mapping[str, Any]) -> Reply: ...
    def state(self) -> dict[str, Any]: ...
    def read(self, timeout_s: float = 5.0) -> Block:
        """The next block made after the call; TimeoutError after `timeout_s` (s)."""
    def set_speed(self, rpm: float) -> Reply: ...
    def set_load(self, nm: float) -> Reply: ...
    def set_oscillating_load(self, nm: float, hz: float) -> Reply: ...
    def set_amplifier_gain(self, gain: float) -> Reply: ...
    def set_filter(self, kind: str, order: Optional[int] = None,
                   cutoff_hz: Optional[float] = None) -> Reply: ...
    def set_adc_range(self, range_v: float) -> Reply: ...
    def set_analyser(self, fmax_hz: Optional[float] = None, block: Optional[int] = None,
                     window: Optional[str] = None, averages: Optional[int] = None,
                     overlap_pct: Optional[float] = None) -> Reply: ...
    def start_average(self) -> Reply: ...
    def hold_average(self) -> Reply: ...
    def set_scope(self, volts_per_div: Optional[float] = None,
                  seconds_per_div: Optional[float] = None, trigger_v: Optional[float] = None,
                  mode: Optional[str] = None) -> Reply: ...
    def arm_scope(self) -> Reply: ...
    def record(self, on: bool) -> Reply: ...
    def save_displays(self) -> Reply: ...
