"""ROSS 3.1.0's gear and mesh code (`ross-rotordynamics`, PyPI), loaded unmodified on
the Python this machine has.

ROSS's wheel declares Python >= 3.13, but the files the time-varying mesh stiffness needs
parse and run on 3.11: the wheel is downloaded (`pip download --no-deps`, never
installed) and only these files are imported from it, as they are:

    ross/units.py, ross/materials.py, ross/disk_element.py,
    ross/multi_rotor/utils.py, ross/multi_rotor/gear_element.py, ross/multi_rotor/mesh.py

The rest of the package (`ross/__init__.py` imports bearings, seals, plotting ...) is not
run; what those files import but the stiffness does not use is stubbed: numba's `njit`
(an identity decorator: ROSS compiles small helpers with it), plotly and ROSS's plotting
theme, `ross.element.Element` (a base class) and `ross.utils.read_table_file`. They need
pint and toml (tests/requirements.txt).
"""

import importlib
import subprocess
import sys
import types
import zipfile
from pathlib import Path

VERSION = "3.1.0"


def fetch(folder):
    """The wheel of ROSS `VERSION` unpacked under `folder` (downloaded once); its path."""
    folder = Path(folder)
    unpacked = folder / f"ross-{VERSION}"
    if (unpacked / "ross" / "multi_rotor" / "gear_element.py").is_file():
        return unpacked
    folder.mkdir(parents=True, exist_ok=True)
    subprocess.run([sys.executable, "-m", "pip", "download", "--quiet",
                    "--disable-pip-version-check", f"ross-rotordynamics=={VERSION}",
                    "--no-deps", "--python-version", "3.13", "--only-binary=:all:",
                    "-d", str(folder)], check=True)
    wheel = next(folder.glob(f"ross_rotordynamics-{VERSION}-*.whl"))
    with zipfile.ZipFile(wheel) as z:
        z.extractall(unpacked)
    return unpacked


def _module(name, **attrs):
    module = types.ModuleType(name)
    module.__dict__.update(attrs)
    sys.modules[name] = module
    return module


def load(unpacked):
    """Imports ROSS's gear and mesh modules from `unpacked`; returns (Q_, Material,
    GearElementTVMS, Mesh)."""
    ross_dir = Path(unpacked) / "ross"

    def njit(*args, **kwargs):
        if len(args) == 1 and callable(args[0]) and not kwargs:
            return args[0]
        return lambda f: f

    _module("numba", njit=njit, jit=njit)
    graph_objects = _module("plotly.graph_objects", Figure=object, Scatter=object)
    _module("plotly", graph_objects=graph_objects, io=_module("plotly.io"))
    ross = _module("ross")
    ross.__path__ = [str(ross_dir)]
    multi_rotor = _module("ross.multi_rotor")
    multi_rotor.__path__ = [str(ross_dir / "multi_rotor")]
    ross.multi_rotor = multi_rotor
    _module("ross.plotly_theme", color_shades=lambda *a, **k: None)
    _module("ross.element", Element=object)
    _module("ross.utils", read_table_file=None)
    for name in ["ross.units", "ross.materials", "ross.disk_element",
                 "ross.multi_rotor.utils", "ross.multi_rotor.gear_element",
                 "ross.multi_rotor.mesh"]:
        importlib.import_module(name)
    units = sys.modules["ross.units"]
    return (units.Q_, sys.modules["ross.materials"].Material,
            sys.modules["ross.multi_rotor.gear_element"].GearElementTVMS,
            sys.modules["ross.multi_rotor.mesh"].Mesh)
