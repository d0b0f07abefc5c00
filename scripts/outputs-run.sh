#!/usr/bin/env bash
# Runs the fixed set of commands whose outputs a refactor must leave byte-identical (wall-time
# fields aside) with one superlube binary, each in its own folder under OUT.
# Usage: scripts/outputs-run.sh BIN OUT [--full]   (--full adds the default `design --no-dem`, ~1 min)
# Compare two such folders with scripts/outputs-compare.sh. The commands use the flag names
# every build accepts (`--theta`, `--alpha`: hidden aliases of `--theta-deg`, `--alpha-deg`).
set -euo pipefail
bin=$(realpath "$1"); out=$2; full=${3:-}
mkdir -p "$out"; out=$(realpath "$out")
run() { local name=$1; shift; mkdir -p "$out/$name"; (cd "$out/$name" && "$bin" "$@" >stdout.txt 2>stderr.txt) || { echo "FAILED: $name" >&2; exit 1; }; }
run screen screen --pattern tri-tri --theta 0:30:0.5 --load-mn 0.35,1.4,3.86 --out screen.csv
run landscape landscape --pattern square-tri --theta 10.2 --load-mn 1.4 --grid 11 --out dz.csv --plot dz.png
run corrugation corrugation --pattern square-tri --theta 0 --load-mn 1.4 --alpha 0,45,90 --out c.csv
run friction friction --pattern square-tri --theta 10.2 --alpha 90 --load-mn 0.35,1.4,2.1 --out f.csv
run tolerance tolerance --pattern square-tri --theta 0 --alpha 90 --theta-points 5 --direction-points 3 --load-mn 1.4,3.86 --out-dir tol
run slide slide --pattern square-tri --theta 0 --load-mn 1.4 --alpha 90 --relax-us 1 --slide-us 5 --out slide.csv --json slide.json
run patterns patterns --family directional --out-dir cand
run design_nominal design --pattern tri-tri --theta 0:30:2 --load-mn 1.4,2.1 --per-level 2 --no-dem --theta-tol-deg 0 --direction-tol-deg 0 --out-dir d
run design_tol design --pattern tri-tri --theta 0:30:2 --load-mn 1.4,2.1 --per-level 2 --no-dem --theta-tol-deg 0.1 --direction-tol-deg 0.5 --out-dir d
run design_vary design --pattern square-tri --theta 0:30:3 --load-mn 1.4,2.1 --per-level 2 --no-dem --theta-tol-deg 0 --direction-tol-deg 0 --vary slider.material.youngs_GPa=50,100 --out-dir d
run design_seeds design --pattern square-tri --theta 0:30:3 --load-mn 1.4,2.1 --per-level 2 --no-dem --sigma-h-um 0.01 --seeds 1,2 --theta-tol-deg 0.1 --direction-tol-deg 0.5 --out-dir d
if [ "$full" = --full ]; then run design_default design --no-dem --out-dir d; fi
echo "outputs in $out"
