#!/usr/bin/env bash
# DEM confirmation of one recipe over its tolerance box (θ ± 0.1°, pull direction ± 0.5° in the
# substrate frame: --line-deg 0 makes α the direction from the substrate x axis) at every seed,
# with design's confirmation protocol (2 + 2 + 60 µs).
# usage: dem_confirm.sh RECIPE.toml THETA DIRECTION LOAD_MN MODEL SEEDS OUT_DIR
set -euo pipefail
scene=$1 th=$2 dir=$3 load=$4 model=$5 seeds=$6 out=$7
l=$(python3 -c "print(f'{$th-0.1:.4g},{$th:.4g},{$th+0.1:.4g}')")
a=$(python3 -c "print(f'{$dir-0.5:.6g},{$dir:.6g},{$dir+0.5:.6g}')")
nice -n 5 "${SUPERLUBE:-superlube}" slide --scene "$scene" --theta "$l" --line-deg 0 --alpha "$a" --load-mn "$load" \
  --seeds "$seeds" --model "$model" --equilibrate-us 2 --relax-us 2 --slide-us 60 --out-dir "$out"
