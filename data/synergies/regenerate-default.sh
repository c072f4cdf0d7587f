#!/bin/sh
# Regenerates sah_tx90_default.yaml, the synergy model the planner uses by default, from the
# SYNTHETIC operator's 13,500-frame recording (seed 1) through the real pipeline (read -> calibrate
# -> map -> PCA). Deterministic: the same pmdplan gives the same bytes (tests/cli checks this).
# Usage: data/synergies/regenerate-default.sh [path/to/pmdplan]
set -eu
pmdplan=${1:-pmdplan}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$pmdplan" glove synth --frames 13500 --seed 1 -o "$work/sah_tx90_synthetic_seed1.csv"
"$pmdplan" synergies "$work/sah_tx90_synthetic_seed1.csv" --robot sah_tx90 -o "$here/sah_tx90_default.yaml"
