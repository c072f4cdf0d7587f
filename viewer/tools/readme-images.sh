#!/usr/bin/env bash
# Remakes the README's pictures (docs/images/) with the commands the README documents:
# plan can_on_table, view it, view a bench folder's paths of one seed, synthesise the glove recording of the default synergy model and
# plot its synergies; then photographs them with headless chromium (viewer/tools/capture.mjs).
# Usage: viewer/tools/readme-images.sh [BUILD_DIR]   (default build; run scripts/build first)
set -euo pipefail
cd "$(dirname "$0")/../.."
pmdplan="${1:-build}/pmdplan"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p docs/images

"$pmdplan" plan can_on_table --seed 1 -o "$work/can_on_table.path.json"
"$pmdplan" view "$work/can_on_table.path.json" --out "$work/can_on_table-viewer"
node viewer/tools/capture.mjs --viewer "$work/can_on_table-viewer" --state 0.55 --out docs/images/viewer.png

"$pmdplan" bench can_on_table --planners pmd,full,ompl:RRTConnect --runs 1 --seed 1 --time-limit 20 --paths "$work/bench-paths" >/dev/null
"$pmdplan" view "$work/bench-paths" --seed 1 --out "$work/bench-viewer"
node viewer/tools/capture.mjs --viewer "$work/bench-viewer" --state 0.55 --out docs/images/viewer_bench_paths.png

"$pmdplan" glove synth --frames 13500 --seed 1 -o "$work/sah_tx90_synthetic_seed1.csv"
"$pmdplan" synergies "$work/sah_tx90_synthetic_seed1.csv" --robot sah_tx90 --plots "$work/plots" >/dev/null
for figure in cumulative_variance joint_pairs; do
  node viewer/tools/capture.mjs --svg "$work/plots/$figure.svg" --out "docs/images/$figure.png"
done
