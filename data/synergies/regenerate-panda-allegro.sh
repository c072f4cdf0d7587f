#!/bin/sh
# Regenerates panda_allegro_default.yaml, the synergy model the planner uses by default for the
# panda_allegro robot, from the same SYNTHETIC operator recording as sah_tx90_default.yaml (13,500
# frames, seed 1) through the real pipeline (read -> calibrate -> map -> PCA), mapped onto the
# Allegro Hand by data/glove/cyberglove22_to_allegro.yaml. Deterministic: the same pmdplan gives the
# same bytes (tests/cli checks this).
# Usage: data/synergies/regenerate-panda-allegro.sh [path/to/pmdplan]
set -eu
pmdplan=${1:-pmdplan}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$pmdplan" glove synth --frames 13500 --seed 1 -o "$work/sah_tx90_synthetic_seed1.csv"
"$pmdplan" synergies "$work/sah_tx90_synthetic_seed1.csv" --robot panda_allegro \
  --mapping "$here/../glove/cyberglove22_to_allegro.yaml" -o "$here/panda_allegro_default.yaml"
