#!/bin/bash
# The scan that chose the second search's start (docs/calibration.md): the half-order
# line's height (dB over its neighbours) at 0 N m, 1000-2000 rev/min, for the first
# search's preset with one or more parameters changed. Each case settles 30 s and is
# measured 12 s (the search's timing) from the static start.
#   bash docs/calibration-data/search-profile/scan.sh OUT_DIR   (from the project root)
set -euo pipefail
out=${1:?usage: scan.sh OUT_DIR}
testrig=${TESTRIG:-./target/release/testrig}
mkdir -p "$out"
scan() {
  local name=$1
  shift
  local args=()
  for kv in "$@"; do args+=(--set "rig.set.$kv"); done
  "$testrig" sweep scenarios/thesis-campaign.toml \
    --set 'rig.preset="../docs/calibration-data/search/preset.toml"' \
    --set 'grid.rpm=[1000,1100,1200,1300,1400,1500,1600,1700,1800,1900,2000]' \
    --set 'grid.load_nm=[0.0]' --set case.settle_s=30 --set case.measure_s=12 \
    "${args[@]+"${args[@]}"}" --out "$out/$name" >"$out/$name.log"
  printf '%-44s' "$name $*"
  grep -E '^\| (1[0-9]00|2000) ' "$out/$name/report.md" | awk -F'|' '{split($3, h, " "); printf "%5s", h[1]}'
  echo
}
printf '%-44s' "rev/min:"; for r in 1000 1100 1200 1300 1400 1500 1600 1700 1800 1900 2000; do printf '%5s' $r; done; echo
scan preset
scan profile-5 te_mesh_frequency_um=5
scan profile-10 te_mesh_frequency_um=10
scan profile-15 te_mesh_frequency_um=15
scan profile-20 te_mesh_frequency_um=20
scan profile-30 te_mesh_frequency_um=30
scan profile-15-no-te te_mesh_frequency_um=15 te_once_per_rev_um=0
scan profile-13-no-te-alt te_mesh_frequency_um=13 te_once_per_rev_um=0 'mesh_pairs="alternating"' mesh_stiffness_smoothing=0
scan profile-15-no-te-alt te_mesh_frequency_um=15 te_once_per_rev_um=0 'mesh_pairs="alternating"' mesh_stiffness_smoothing=0
scan damping-136 c23_mesh_nms_per_rad=135.8
scan no-te te_once_per_rev_um=0
