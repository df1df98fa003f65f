"""The thesis's figure points against the campaign's preset, from each approach.

For every operating point our digest of the thesis (rig-spec) ties to a spectrum or a
time response, runs `testrig simulate` from the static load, from rest, by the lab's
slow run-up and by its run-down, and prints the Markdown table of docs/physics.md
("Figure by figure"): the judged motion, the half-order line's height over the floor,
and whether the motor held the set speed.

    python3 docs/physics/figure_table.py target/release/testrig
"""

import json
import subprocess
import sys

PRESET = "basmaji-1983-drive"
APPROACHES = ["static", "rest", "up", "down"]
# Settling from rest counts from t = 0: give the drive its run-up (up to 140 s at
# 2000 rev/min and 5.424 N m with this preset), then the campaign's 60 s.
SETTLE_S = {"static": 60, "rest": 200, "up": 60, "down": 60}

# (figures, rev/min, N m, what the thesis shows there, as our digest words it)
POINTS = [
    ("4.20-4.33 (200 rev/min series)", 200, 0.0,
     "brake-side frequency, fundamental, running-speed harmonics"),
    ("", 200, 1.356, "as at 0 N m"),
    ("", 200, 2.712, "as at 0 N m"),
    ("", 200, 3.389, "running-speed harmonics dominate; the second natural frequency excited"),
    ("", 200, 4.068, "as at 3.389 N m"),
    ("", 200, 5.424, "as at 3.389 N m"),
    ("4.31-4.32", 200, 6.78, "as at 3.389 N m; 6.78 N m plus the rig's drag carried"),
    ("4.34-4.35", 600, 0.0, "running speed and its multiples only (below 1000 rev/min)"),
    ("", 600, 2.712, "running speed and its multiples only"),
    ("", 600, 5.424, "running speed and its multiples only"),
    ("4.39", 1100, 0.0, "half-order line (9.17 Hz); trace repeats every two revolutions"),
    ("", 1100, 2.712, "half-order line, with and without load"),
    ("", 1100, 5.424, "half-order line, with and without load"),
    ("4.65-4.70", 1500, 0.0, "clean subharmonic and its multiples"),
    ("", 1500, 2.712, "clean subharmonic and its multiples"),
    ("", 1700, 5.424, "half-order line weakens"),
    ("", 1900, 5.424, "half-order line gone: the load keeps the teeth together"),
    ("4.74", 1000, 2.712, "a 1/3-order line"),
    ("4.74", 1900, 2.712, "a 1/3-order line"),
]


def run(binary, rpm, load, approach):
    args = [binary, "simulate", "--preset", PRESET, "--rpm", str(rpm), "--load", str(load),
            "--rate", "10240", "--settle", str(SETTLE_S[approach]), "--duration", "30",
            "--approach", approach, "--json"]
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        return "refused: " + done.stderr.strip().splitlines()[-1].split(": ")[-1]
    out = json.loads(done.stdout)
    motion = out["motion"]["motion"]
    height = out["motion"].get("half_order_db")
    cell = motion if height is None else f"{motion}, {min(height, 150):.0f} dB"
    offset = out["speed_offset_rpm"]
    if abs(offset) > 0.01 * rpm:
        cell += f", sags {offset:.0f} rev/min"
    return cell


def main():
    binary = sys.argv[1] if len(sys.argv) > 1 else "target/release/testrig"
    print("| Fig | rev/min | N m | the thesis shows | " + " | ".join(APPROACHES) + " |")
    print("|---|---|---|---|" + "---|" * len(APPROACHES))
    for figure, rpm, load, shows in POINTS:
        cells = [run(binary, rpm, load, a) for a in APPROACHES]
        print(f"| {figure} | {rpm} | {load} | {shows} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
