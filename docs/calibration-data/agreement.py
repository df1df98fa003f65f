#!/usr/bin/env python3
"""Does `testrig simulate` with a preset agree with the campaign's cases, on the thesis's
grid and between it?

Runs the campaign (scenarios/thesis-campaign.toml) and the off-grid sweep
(docs/calibration-data/off-grid.toml) with the given preset, then `testrig simulate
--preset P --rpm R --load L --json` (its defaults: 60 s settling, the regime of the last
stretch) at every point of both, and compares the regime (period-k or aperiodic) of each
point. Also scores each sweep's half-order verdicts against the thesis's findings.

    python3 docs/calibration-data/agreement.py [--preset basmaji-1983-calibrated] [--bin target/release/testrig]
"""
import argparse
import csv
import json
import subprocess
import sys
import tempfile
from pathlib import Path


def expects_half_order(rpm, load):
    return rpm >= 1100 and not (load >= 5.424 - 1e-6 and rpm >= 1900)


def sweep(binary, file, preset, out):
    subprocess.run([binary, "sweep", str(file), "--out", str(out), "--set", f"rig.preset={preset}"],
                   check=True, stdout=subprocess.DEVNULL)
    return list(csv.DictReader(open(out / "cases.csv")))


def simulate(binary, preset, rpm, load):
    done = subprocess.run([binary, "simulate", "--preset", preset, "--rpm", str(rpm), "--load", str(load), "--json"],
                          check=True, capture_output=True, text=True)
    return json.loads(done.stdout)["regime"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--preset", default="basmaji-1983-calibrated")
    parser.add_argument("--bin", default="target/release/testrig")
    args = parser.parse_args()
    root = Path(__file__).resolve().parents[2]
    files = {"grid": root / "scenarios/thesis-campaign.toml", "off-grid": root / "docs/calibration-data/off-grid.toml"}
    with tempfile.TemporaryDirectory() as tmp:
        for name, file in files.items():
            rows = sweep(args.bin, file, args.preset, Path(tmp) / name)
            thesis = sum((r["half_order_present"] == "true") == expects_half_order(float(r["rpm"]), float(r["load_nm"])) for r in rows)
            agree, differ = 0, []
            for r in rows:
                regime = simulate(args.bin, args.preset, r["rpm"], r["load_nm"])
                if regime == r["regime"]:
                    agree += 1
                else:
                    differ.append(f'{r["rpm"]} rev/min {r["load_nm"]} N m: simulate {regime}, case {r["regime"]}')
            print(f"{name}: {len(rows)} points; half order as the thesis {thesis}/{len(rows)}; "
                  f"simulate's regime = the case's at {agree}/{len(rows)}")
            for line in differ:
                print("   ", line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
