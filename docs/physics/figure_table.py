"""The thesis's figure points against the campaign's preset, from each approach.

For every figure of our digest of the thesis (rig-spec §6) that shows an operating
point -- chapter IV's measured spectra and time responses and chapter VI's own
simulations -- runs `testrig simulate` from the static load, from rest, by the lab's
slow run-up and by its run-down, and prints the Markdown table of docs/physics.md
("Figure by figure"): the judged motion and the half-order line's height over the
floor from each approach, the period in revolutions for time responses, and whether
the preset shows what the thesis shows.

    python3 docs/physics/figure_table.py target/release/testrig

Agreement rule (one per row, from rig-spec's words; applied to each approach's run):

- "half order" / "subharmonic" (incl. "half order, weaker": weaker is not judged):
  the half-order line clear by the judge's rule: 20 dB over its floor and at least
  1e-6 of the band's power (the judge reads it as period 2 or an even period).
- "running speed and its multiples only" / "running speed the first line" /
  "running-speed harmonics" at 200 rev/min / "no subharmonic" / "period one
  revolution" (300 ms, 180 ms, 100 ms at 600 rev/min) / "settles to one revolution":
  motion period-1 with the half-order line not clear.
- "a 1/3-order line": the 1/3-order line clear by the same rule.
- No backlash (Figs 6.2, 6.3, "oscillation at 17.84 Hz"): the rig is linear, so any
  period-1 motion, or a steady "no-vibration", agrees; the 17.84 Hz free oscillation
  itself (not an order of the running speed) is not judged.
- Words that decide nothing ("a sample spectrum", "time response, no loading", "the
  model runs", "(text cut in our copy)"): "?".
- A refused run (load plus the preset's drag beyond the drive) disagrees.

A row is flagged ✗ when the run-up ("up", the strict approach) disagrees, ✓ when it
agrees; the cell also names the approaches that agree. "The lab's" count takes a row
as agreeing when any approach agrees.

A row is a time response when rig-spec's words say "time response", "time trace",
"trace" or a period in ms, and for every chapter VI figure; its period column gives the
judge's motion in revolutions ("period-k" -> "k rev").
"""

import json
import re
import subprocess
import sys
import time
from concurrent.futures import ProcessPoolExecutor

PRESET = "basmaji-1983-drive"
APPROACHES = ["static", "rest", "up", "down"]
# Settling from rest counts from t = 0: give the drive its run-up (up to 140 s at
# 2000 rev/min and 5.424 N m with this preset), then the campaign's 60 s.
SETTLE_S = {"static": 60, "rest": 200, "up": 60, "down": 60}
CLEAR_DB = 20  # a line this far over the floor ...
VISIBLE_SHARE = 1e-6  # ... carrying this share of the power stands clear (rig::judge)
SLOW_S = 60  # a single simulate slower than this is reported on stderr

# Chapter VI settings, as the preset's parameters.
C1 = ("backlash_variation_c1=0.38",)  # the thesis's 6.5.1 value (the preset: 0.6)
SHIFT = ("tooth_shifting=true",)  # the preset shifts at every tooth pass
NO_BACKLASH = ("backlash_mm=1e-6",)  # backlash_mm must be > 0: 1 nm stands for none
NO_DAMPING = ("c12_input_shaft_nms_per_rad=0", "c23_mesh_nms_per_rad=0",
              "c34_intermediate_shaft_nms_per_rad=0", "c45_final_shaft_nms_per_rad=0")

# (figures, rev/min, N m, --set words, the point's note, cut-off, what the thesis
#  shows (rig-spec, shortened), time response?, expectation: sub | one | third |
#  linear | None)
POINTS = [
    ("4.17", 750, 0, (), "", "—",
     "time response, no loading", True, None),
    ("4.19", 600, 0, (), "load not given: 0", "—",
     "a sample spectrum", False, None),
    ("4.20, 4.21", 200, 0, (), "", "—",
     "spectrum, time trace: brake-side frequency, fundamental, running-speed harmonics",
     True, "one"),
    ("4.22–4.24", 200, 1.356, (), "", "—",
     "spectra, time trace: as at 0 N m", True, "one"),
    ("4.25, 4.26", 200, 2.712, (), "", "—",
     "spectrum, time trace: as at 0 N m", True, "one"),
    ("(text of 4.27–4.33)", 200, 3.389, (), "", "—",
     "from here up running-speed harmonics dominate, 2nd natural frequency excited; "
     "trace: one revolution (300 ms), ~30 ripples", True, "one"),
    ("4.27, 4.28", 200, 4.068, (), "", "1800 Hz (4.28)",
     "spectrum, time trace: as at 3.389 N m", True, "one"),
    ("4.29, 4.30", 200, 5.424, (), "", "—",
     "spectrum, time trace: as at 3.389 N m", True, "one"),
    ("4.31–4.33", 200, 6.78, (), "", "180 Hz (4.32), 1800 Hz (4.33)",
     "spectra, time trace: as at 3.389 N m", True, "one"),
    ("4.34, 4.35", 600, 0, (), "", "2 kHz (4.35)",
     "first line 10 Hz = running speed, its multiples, no subharmonic; period 100 ms",
     True, "one"),
    ("4.36, 4.37", 800, 0, (), "", "—",
     "spectrum, time trace; no subharmonic at or below 1000 rev/min", True, "one"),
    ("4.38, 4.39", 1100, 0, (), "", "2 kHz (4.39)",
     "half-order line 9.166 Hz; trace period 109 ms = two revolutions", True, "sub"),
    ("4.40, 4.41", 1300, 0, (), "", "2 kHz (4.41)",
     "half-order line; trace over two revolutions", True, "sub"),
    ("4.42, 4.43", 250, 2.712, (), "", "80 Hz / none",
     "running speed 4.166 Hz the first line", False, "one"),
    ("4.44, 4.45", 350, 2.712, (), "", "80 Hz / none",
     "running speed the first line", False, "one"),
    ("4.46, 4.47", 600, 2.712, (), "", "80 Hz / —",
     "running speed the first line", False, "one"),
    ("4.48, 4.49", 900, 2.712, (), "", "— / none",
     "running speed the first line", False, "one"),
    ("4.50", 1100, 2.712, (), "", "—",
     "half order 9.166 Hz and its multiples, then 18.33 Hz", False, "sub"),
    ("4.51, 4.52", 1200, 2.712, (), "", "—", "half order at 10 Hz", False, "sub"),
    ("4.53, 4.54", 1400, 2.712, (), "", "— / none", "half order, clearly", False, "sub"),
    ("4.55, 4.56", 1700, 2.712, (), "", "80 Hz / none", "half order, clearly", False, "sub"),
    ("4.57, 4.58", 250, 5.424, (), "", "180 Hz (4.57)",
     "running speed and its multiples only", False, "one"),
    ("4.59, 4.60", 600, 5.424, (), "", "—",
     "running speed and its multiples only", False, "one"),
    ("4.61, 4.62", 850, 5.424, (), "", "—",
     "running speed and its multiples only", False, "one"),
    ("4.63, 4.64", 900, 5.424, (), "", "180 Hz (4.63)",
     "running speed and its multiples only (traces include the load's DC)", True, "one"),
    ("4.65, 4.66", 1100, 5.424, (), "", "—",
     "first speed with the half order: the subharmonic and its multiples", False, "sub"),
    ("4.67, 4.68", 1400, 5.424, (), "", "—", "half order and its multiples", False, "sub"),
    ("4.69, 4.70", 1700, 5.424, (), "", "—", "half order, weaker", False, "sub"),
    ("4.71, 4.72", 1900, 5.424, (), "", "180 Hz (4.71)",
     "running speed and multiples; no subharmonic", False, "one"),
    ("4.73–4.75", 1000, 2.712, (), "", "—", "a 1/3-order line", False, "third"),
    ("4.73–4.75", 1900, 2.712, (), "", "—", "a 1/3-order line", False, "third"),
    ("6.1", 200, 0.05, ("backlash_mm=1.46", *NO_DAMPING, *C1),
     "backlash 1.46 mm, no damping (c12, c23, c34, c45 = 0), C1 0.38", "—",
     "the model runs", True, None),
    ("6.2", 1200, 0.05, (*NO_BACKLASH, "tooth_shifting=false", *C1),
     "no backlash (1e-6 mm: must be > 0), no tooth shift, C1 0.38", "—",
     "oscillation at the computed 17.84 Hz (T ≈ 56 ms)", True, "linear"),
    ("6.3", 1200, 0.05, (*NO_BACKLASH, *SHIFT, *C1),
     "0.05 N m as the text (caption: 0); no backlash (1e-6 mm), tooth shift "
     "(thesis 2 ms; preset: every tooth pass), C1 0.38", "—",
     "as 6.2 with the shift", True, "linear"),
    ("6.4", 1200, 5.0, ("backlash_mm=1.46", *C1),
     "backlash 1.46 mm, C1 0.38", "—", "a subharmonic", True, "sub"),
    ("6.5", 200, 1.0, ("backlash_mm=0.73", *SHIFT, *C1),
     "backlash 0.73 mm, tooth shift (thesis 2 ms; preset: every tooth pass, 10 ms), "
     "C1 0.38", "—", "period 300 ms (one revolution), no subharmonic", True, "one"),
    ("6.6", 200, 2.0, ("backlash_mm=0.73", *SHIFT, *C1),
     "as 6.5", "—", "period 300 ms (one revolution), no subharmonic", True, "one"),
    ("6.7", 1600, 1.0, (*SHIFT, *C1),
     "tooth shift (thesis 2 ms; preset: every tooth pass), C1 0.38", "—",
     "subharmonic at both loads", True, "sub"),
    ("6.8", 1600, 2.0, (*SHIFT, *C1), "as 6.7", "—",
     "subharmonic at both loads", True, "sub"),
    ("6.9", 1200, 1.5, C1, "C1 0.38", "—", "(text cut in our copy)", True, None),
    ("6.10", 1200, 5.0, C1, "C1 0.38", "—", "(text cut in our copy)", True, None),
    ("6.11", 200, 4.0, (*SHIFT, *C1),
     "tooth shift (thesis 10 ms = 300 ms / 30 teeth), C1 0.38", "—",
     "(text cut; the shift is 300 ms / 30 teeth)", True, None),
    ("6.12", 333.33, 4.0, (*SHIFT, *C1),
     "tooth shift (thesis 6 ms = one tooth pass), C1 0.38", "—",
     "settles to a period of 180 ms (one revolution)", True, "one"),
    ("6.13", 200, 1.7, (*SHIFT, *C1),
     "tooth shift (thesis 10 ms = one tooth pass), C1 0.38", "—",
     "no subharmonic at 200", True, "one"),
    ("6.14", 1000, 1.7, (*SHIFT, *C1),
     "tooth shift (thesis 2 ms = one tooth pass), C1 0.38", "—",
     "a subharmonic at 1000", True, "sub"),
]
SKIPPED = ("Skipped: Figs 4.3–4.15 (RMS meter curves over loads, not one point) and "
           "4.76a,b (sketch of the impact cycle).")


def simulate(binary, rpm, load, sets, approach):
    """One run's judged motion as a dict, or {"refused": reason}."""
    args = [binary, "simulate", "--preset", PRESET, "--rpm", str(rpm), "--load", str(load),
            "--rate", "10240", "--settle", str(SETTLE_S[approach]), "--duration", "30",
            "--approach", approach, "--json"]
    for word in sets:
        args += ["--set", word]
    start = time.monotonic()
    done = subprocess.run(args, capture_output=True, text=True)
    wall = time.monotonic() - start
    if wall > SLOW_S:
        print(f"slow: {wall:.0f} s for {' '.join(args[1:])}", file=sys.stderr)
    if done.returncode != 0:
        return {"refused": refusal(done.stderr)}
    out = json.loads(done.stdout)
    return {**out["motion"], "offset": out["speed_offset_rpm"], "rpm": rpm}


def refusal(stderr):
    message = stderr.strip().splitlines()[-1]
    limit = re.search(r"torque limit ([\d.]+) N m", message)
    if limit:
        return f"load + drag beyond the drive's {limit.group(1)} N m"
    return message.split(": ")[-1]


def db(height):
    """A line's height over the floor, capped at the judge's 150 dB, without "-0"."""
    return f"{round(min(height, 150)) + 0} dB"


def motion_cell(run, expect):
    if "refused" in run:
        return "refused: " + run["refused"]
    cell = f"{run['motion']}, {db(run['half_order_db'])}"
    if expect == "third":
        cell += f", 1/3: {db(run['third_order_db'])}"
    if abs(run["offset"]) > 0.01 * run["rpm"]:
        cell += f", sags {run['offset']:.0f} rev/min"
    return cell


def period(run):
    if "refused" in run:
        return "refused"
    match = re.fullmatch(r"period-(\d+)", run["motion"])
    return f"{match.group(1)} rev" if match else run["motion"]


def period_cell(runs):
    periods = [period(runs[a]) for a in APPROACHES]
    if len(set(periods)) == 1:
        return periods[0]
    return ", ".join(f"{a} {p}" for a, p in zip(APPROACHES, periods))


def clear(run, line):
    """The judge's one rule for a subharmonic line (`rig::judge::stands_clear`): 20 dB
    over its floor and at least 1e-6 of the band's power."""
    height, share = run[f"{line}_order_db"], run[f"{line}_order_share"]
    return (height is not None and share is not None and height >= CLEAR_DB
            and share >= VISIBLE_SHARE)


def agrees(run, expect):
    """The agreement rule of the module's docstring, for one run."""
    if "refused" in run:
        return False
    half_clear = clear(run, "half")
    if expect == "sub":
        return half_clear
    if expect == "one":
        return run["motion"] == "period-1" and not half_clear
    if expect == "third":
        return clear(run, "third")
    if expect == "linear":
        return run["motion"] in ("period-1", "no-vibration") and not half_clear
    raise ValueError(expect)


def flag_cell(runs, expect):
    if expect is None:
        return "?"
    agreeing = [a for a in APPROACHES if agrees(runs[a], expect)]
    flag = "✓" if "up" in agreeing else "✗"
    if len(agreeing) == len(APPROACHES):
        return f"{flag} (all agree)"
    return f"{flag} (agree: {', '.join(agreeing) or 'none'})"


def point_cell(rpm, load, note):
    return f"{rpm:g} rev/min, {load:g} N m" + (f"; {note}" if note else "")


def main():
    binary = sys.argv[1] if len(sys.argv) > 1 else "target/release/testrig"
    jobs = [(binary, p[1], p[2], p[3], a) for p in POINTS for a in APPROACHES]
    with ProcessPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(simulate, *zip(*jobs)))
    runs_by_row = [dict(zip(APPROACHES, results[i:i + len(APPROACHES)]))
                   for i in range(0, len(results), len(APPROACHES))]

    print("| Fig | point | cut-off | the thesis shows | " + " | ".join(APPROACHES)
          + " | period seen (rev) | agrees |")
    print("|---|---|---|---|" + "---|" * len(APPROACHES) + "---|---|")
    judged = strict_no = lab_no = 0
    for (figure, rpm, load, _, note, cutoff, shows, trace, expect), runs in zip(
            POINTS, runs_by_row):
        cells = [figure, point_cell(rpm, load, note), cutoff, shows]
        cells += [motion_cell(runs[a], expect) for a in APPROACHES]
        cells += [period_cell(runs) if trace else "", flag_cell(runs, expect)]
        print("| " + " | ".join(cells) + " |")
        if expect is not None:
            judged += 1
            strict_no += not agrees(runs["up"], expect)
            lab_no += not any(agrees(runs[a], expect) for a in APPROACHES)
    print()
    print(SKIPPED)
    print()
    print(f"{strict_no} of {judged} rows disagree (run-up); "
          f"{lab_no} of {judged} rows disagree (the lab's: no approach agrees); "
          f"{len(POINTS) - judged} more rows undecided (?).")


if __name__ == "__main__":
    main()
