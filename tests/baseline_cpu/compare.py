"""The default build on a CPU without AVX2 or FMA: `testrig simulate --json` run under
qemu's baseline `qemu64` CPU against the same command on this machine. The numbers agree
within 1e-5 relative (glibc picks other variants of sin, cos and exp on a CPU without
FMA, so the last bits may differ; the plant's own multiply-adds are exact on both paths).

    python3 tests/baseline_cpu/compare.py target/release/testrig
"""

import json
import subprocess
import sys

ARGS = ["simulate", "--rpm", "1300", "--load", "2.712", "--settle", "1", "--duration", "2", "--json"]
TIMING = {"wall_s", "realtime_factor"}


def numbers(value, path=""):
    """Every number in a JSON value, by its path."""
    if isinstance(value, dict):
        for key, item in value.items():
            if key not in TIMING:
                yield from numbers(item, f"{path}.{key}")
    elif isinstance(value, list):
        for i, item in enumerate(value):
            yield from numbers(item, f"{path}[{i}]")
    elif isinstance(value, (int, float)) and not isinstance(value, bool):
        yield path, float(value)
    else:
        yield path, value


def main(binary):
    native = json.loads(subprocess.run([binary, *ARGS], check=True, capture_output=True, text=True).stdout)
    baseline = json.loads(subprocess.run(["qemu-x86_64", "-cpu", "qemu64", binary, *ARGS],
                                         check=True, capture_output=True, text=True).stdout)
    a, b = dict(numbers(native)), dict(numbers(baseline))
    assert a.keys() == b.keys(), "the two runs report different fields"
    worst = 0.0
    for path, x in a.items():
        y = b[path]
        if isinstance(x, float):
            scale = max(abs(x), abs(y), 1e-12)
            worst = max(worst, abs(x - y) / scale)
            assert abs(x - y) <= 1e-5 * scale, f"{path}: {x} here, {y} on qemu64"
        else:
            assert x == y, f"{path}: {x} here, {y} on qemu64"
    print(f"the default build runs on a baseline x86-64 CPU (qemu64): {len(a)} fields agree, worst relative difference {worst:.1e}")


if __name__ == "__main__":
    main(sys.argv[1])
