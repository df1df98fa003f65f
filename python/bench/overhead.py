"""Python overhead against the CLI (issue 25): `testrig.simulate` of 10 s at 1300 rev/min
and 2.712 N m against `testrig simulate` of the same point, medians of 5; then 1 000
calls in one process, the peak RSS after every 100 (flat: nothing leaks).

    cargo build --release && python3 -m pip install ./python
    python3 python/bench/overhead.py
"""

import resource
import statistics
import subprocess
import time
from pathlib import Path

import testrig

BINARY = Path(__file__).resolve().parents[2] / "target" / "release" / "testrig"
POINT = ["--rpm", "1300", "--load", "2.712", "--duration", "10"]  # the one default preset


def wall_s(run):
    start = time.perf_counter()
    run()
    return time.perf_counter() - start


def main():
    cli = [wall_s(lambda: subprocess.run([str(BINARY), "simulate", *POINT, "--json"],
                                         check=True, capture_output=True))
           for _ in range(5)]
    py = [wall_s(lambda: testrig.simulate(1300, 2.712, duration_s=10)) for _ in range(5)]
    bare = [wall_s(lambda: testrig.simulate(1300, 2.712, duration_s=10, signals=False))
            for _ in range(5)]
    print(f"CLI simulate --json median {statistics.median(cli):.3f} s; "
          f"testrig.simulate(signals=False) median {statistics.median(bare):.3f} s "
          f"(ratio {statistics.median(bare) / statistics.median(cli):.3f}); "
          f"with the {len(testrig.simulate(1300, 2.712, settle_s=0, duration_s=0.01)['signals'])} "
          f"signal arrays {statistics.median(py):.3f} s "
          f"(ratio {statistics.median(py) / statistics.median(cli):.2f})")
    peaks = []
    for k in range(1000):
        testrig.simulate(1300, 2.712, settle_s=0.1, duration_s=0.1, rate_hz=10240)
        if k % 100 == 99:
            peaks.append(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024)
    print("peak RSS (MiB) after every 100 calls:", " ".join(f"{p:.1f}" for p in peaks))


if __name__ == "__main__":
    main()
