"""testrig's potential-energy mesh stiffness against ROSS 3.1.0's `GearElementTVMS` and
`Mesh` (run by the Rust test `the_mesh_stiffness_agrees_with_ross`, tests/params_mesh_stiffness.rs).

Two spur pairs, each given to both as the same gears:
- ROSS's own test case (ross/tests/test_gear_element.py): 62/62 teeth, module 2 mm, 20°,
  face 20 mm, bore 35 mm, E 206 GPa, nu 0.3; ROSS's asserted contact ratio 1.7898 and
  first mesh stiffnesses are reproduced first, so that ROSS is known to run as its
  authors test it;
- the 1983 rig's gears: 30/30, module 5 mm, 20°, face 20 mm, steel (206 GPa, 0.3), on
  the rig's Ø20 mm shafts (bore 20 mm).

testrig's numbers come from `testrig params --rig FILE --json` on a rig file giving the
mesh by `face_width_m`: the contact ratio, one pair's stiffness (its mean over the stretch
it carries alone) and the mean mesh stiffness over a tooth period. ROSS's: the same
means over its `stiffness_range` (one tooth period), its single- and double-pair zones
split as its own `Mesh` splits them.

Each figure must agree within the stated tolerance; the differences and their reasons
are printed (docs/faults.md says them too).

    python3 tests/mesh_stiffness/compare_ross.py target/release/testrig OUT_DIR
"""

import json
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
import ross_loader  # noqa: E402

# The agreement asked of each figure (relative): the contact ratio is geometry alone;
# the stiffnesses differ by the modelling choices docs/faults.md lists.
CONTACT_RATIO_WITHIN = 1e-3
STIFFNESS_WITHIN = 0.10

CASES = [
    # name, teeth, module (m), face (m), bore (m)
    ("ROSS's test case", 62, 0.002, 0.020, 0.035),
    ("the 1983 gears", 30, 0.005, 0.020, 0.020),
]


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    return ok


def ross_figures(ross, teeth, module, face, bore):
    q_, material, gear_tvms, mesh_class = ross
    steel = material("Gear_steel", rho=q_(7.81, "g/cm**3"), E=q_(206, "GPa"), Poisson=0.3)
    gears = [gear_tvms(n=i, material=steel, module=module, width=face, n_teeth=teeth,
                       bore_diameter=bore, pr_angle=q_(20, "deg")) for i in range(2)]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        mesh = mesh_class(gears[0], gears[1])
    stiffness = np.asarray(mesh.stiffness_range)
    # ROSS's own split of the tooth period: two pairs while the roll is within (CR - 1)
    # of a pair's span of pressure angles, as Mesh.stiffness_range computes it.
    angles = gears[0].pr_angles_dict
    span = angles["addendum"] - angles["start_point"]
    d_mesh = span / mesh.contact_ratio
    d_alpha = d_mesh / (2 * np.pi / teeth) * np.asarray(mesh.theta_range)
    two = d_alpha <= d_mesh * (mesh.contact_ratio - 1)
    return {
        "contact_ratio": float(mesh.contact_ratio),
        "pair_stiffness_n_per_m": float(stiffness[~two].mean()),
        "mean_mesh_stiffness_n_per_m": float(stiffness.mean()),
        "first_five": stiffness[:5].tolist(),
    }


def testrig_figures(testrig, out, name, teeth, module, face, bore):
    rig = out / f"{name.replace(' ', '-').replace(chr(39), '')}.toml"
    rig.write_text(f'''name = "pair"
description = "{name}: a spur pair given by its face width"

[[body]]
name = "pinion"
inertia_kgm2 = 0.01

[[body]]
name = "wheel"
inertia_kgm2 = 0.01

[[mesh]]
name = "pair"
driver = "pinion"
driven = "wheel"
teeth = [{teeth}, {teeth}]
module_m = {module}
backlash_mm = 0.1
face_width_m = {face}
youngs_modulus_pa = 206e9
poisson_ratio = 0.3
bore_diameter_m = {bore}
''')
    done = subprocess.run([testrig, "params", "--rig", rig, "--json"], capture_output=True,
                          text=True)
    if done.returncode != 0:
        sys.exit(f"testrig params --rig {rig}: {done.stderr}")
    derived = {row["name"]: row["value"] for row in json.loads(done.stdout)["derived"]}
    value = lambda field: float(derived[f"mesh.pair.{field}"])  # noqa: E731
    return {field: value(field) for field in
            ["contact_ratio", "pair_stiffness_n_per_m", "mean_mesh_stiffness_n_per_m"]}


def main():
    testrig, out = sys.argv[1], Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    ross = ross_loader.load(ross_loader.fetch(out / "ross"))
    good = True
    for name, teeth, module, face, bore in CASES:
        theirs = ross_figures(ross, teeth, module, face, bore)
        ours = testrig_figures(testrig, out, name, teeth, module, face, bore)
        if name == "ROSS's test case":
            expected = [396622921.3581085, 396738680.0375346, 396854147.2919756,
                        396969323.136738, 397084207.5865779]
            good &= check(abs(theirs["contact_ratio"] - 1.7897798668330458) < 1e-9
                          and np.allclose(theirs["first_five"], expected, rtol=1e-6),
                          f"{name}: ROSS reproduces its own test's contact ratio "
                          f"{theirs['contact_ratio']:.6f} and first mesh stiffnesses")
        for field, within in [("contact_ratio", CONTACT_RATIO_WITHIN),
                              ("pair_stiffness_n_per_m", STIFFNESS_WITHIN),
                              ("mean_mesh_stiffness_n_per_m", STIFFNESS_WITHIN)]:
            ratio = ours[field] / theirs[field]
            good &= check(abs(ratio - 1) <= within,
                          f"{name}: {field} testrig {ours[field]:.5g}, ROSS {theirs[field]:.5g} "
                          f"({100 * (ratio - 1):+.1f} %, within {100 * within:g} %)")
    sys.exit(0 if good else 1)


if __name__ == "__main__":
    main()
