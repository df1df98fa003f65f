"""A labelled dataset of strain recordings across speeds, loads and backlash: one WAV a
case (float32, the output-shaft strain in µε through the thesis's chain, with its JSON
sidecar) and labels.csv, which a training script reads as it is: the file, the
operating point, the backlash, and the motion the physics judge saw (period-1, period-2,
chaotic…) with the impacts a revolution.

    python3 -m pip install ./python
    python3 examples/python/labelled_dataset.py out/dataset
"""

import csv
import shutil
import sys
from pathlib import Path

import testrig

SPEEDS_RPM = [600, 1000, 1300, 1700]
LOADS_NM = [0.0, 2.712, 5.424]
BACKLASH_MM = [0.5, 0.73, 1.0]


def case_scenario(rpm, load_nm, backlash_mm, seed):
    return {
        "name": f"dataset-{rpm}-{load_nm}-{backlash_mm}",
        "seed": seed,
        "rate_hz": 10240,
        "duration_s": 15,
        "rig": {"preset": "basmaji-1983-rig", "backlash_mm": backlash_mm},
        "schedule": {"speed_rpm": rpm, "load_nm": load_nm},
        "chain": {"slip_rings": {"broadband_rms": 0.005, "per_rev_amplitude": 0.01,
                                 "contact_noise_v_rms": 2e-6}},
        "record": {"signals": ["strain"], "formats": ["wav"],
                   "wav_format": "float32"},
    }


def main(folder):
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    rows = []
    seed = 1983
    for backlash_mm in BACKLASH_MM:
        for load_nm in LOADS_NM:
            for rpm in SPEEDS_RPM:
                seed += 1
                result = testrig.run(case_scenario(rpm, load_nm, backlash_mm, seed))
                # The case is one point: its motion judged over the run's last stretch.
                point = result["manifest"]["points"][0]
                name = f"case-{len(rows):03d}.wav"
                shutil.copy(result["out"] / "recording.wav", folder / name)
                shutil.copy(result["out"] / "recording.wav.json", folder / f"{name}.json")
                rows.append({
                    "file": name, "speed_rpm": rpm, "load_nm": load_nm,
                    "backlash_mm": backlash_mm, "seed": seed,
                    "motion": point["motion"]["motion"],
                    "regime": point["regime"],
                    "impacts_per_rev": point["impacts_per_rev"],
                })
                print(f"{name}: {rpm} rev/min, {load_nm} N m, {backlash_mm} mm: "
                      f"{rows[-1]['motion']}")
    with open(folder / "labels.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print(f"{len(rows)} recordings and labels.csv in {folder}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "out/dataset")
