#!/bin/bash
# The hard cases at study size (issue 35, item 3): prints the rows of the table "Hard cases at
# study size" of docs/validation/work-precision.md. Every DEM model equilibrated under load
# (`superlube equilibrate`, 10 µs; the explicit model on the 20 000-sphere slider 2 µs) and every
# surrogate solver at the placement (`superlube screen --solver`), on the study's 3505-sphere
# slider, a 19 949-sphere slider, and the tri-tri 0° scene at 0.9 and 1.1 of each model's stable
# step estimate (2 µs). A DEM cell is |ΣF_z/W − 1| (contacts, P_max; steps, wall s) or the
# refusal; a solver cell contacts, P_max, force residual and the process's wall time (ms).
#
#   bash docs/validation/hard-cases-study.sh [path/to/superlube]
set -u
B=${1:-superlube}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

dem_cell() { # flags load_mN model time_us [dt_us]
  local dt=()
  [ $# -ge 5 ] && dt=(--dt-us "$5")
  # shellcheck disable=SC2086
  if $B equilibrate $1 --load-mn "$2" --model "$3" --equilibrate-us "$4" "${dt[@]}" \
    --json "$T/e.json" --out "$T/e.csv" 2>"$T/e.err"; then
    python3 - "$T/e.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
print(f"{abs(j['force_balance'] - 1):.1e} ({j['contacts']} c, {j['p_max_GPa']:.3f} GPa; "
      f"{j['steps']} steps, {j['wall_s']:.1f} s)", end="")
PY
  else
    printf '**stops**: %s' "$(grep -v '^warning' "$T/e.err" | tail -1 | cut -c1-160)"
  fi
}

solver_cell() { # flags load_mN
  local out=""
  for s in rigid-z rigid-tilt compliant; do
    local t0 t1
    t0=$(date +%s.%N)
    # shellcheck disable=SC2086
    if $B screen $1 --load-mn "$2" --solver $s --out "$T/s.csv" 2>"$T/s.err"; then
      t1=$(date +%s.%N)
      out+=$(python3 - "$T/s.csv" "$s" "$t0" "$t1" <<'PY'
import csv, sys
r = next(csv.DictReader(open(sys.argv[1])))
ms = (float(sys.argv[4]) - float(sys.argv[3])) * 1e3
res = float(r['residual_rel'] or 'nan')
print(f"{sys.argv[2]} {r['contacts']} c, {float(r['p_max_GPa']):.3f} GPa, residual {res:.0e}, {ms:.0f} ms; ", end="")
PY
)
    else
      out+="$s: refused ($(tail -1 "$T/s.err" | cut -c1-120)); "
    fi
  done
  printf '%s' "$out"
}

row() { # name flags load_mN explicit_us
  local cells=""
  for m in reduced full full-explicit; do
    local t=10
    [ "$m" = full-explicit ] && t=$4
    cells+=" | $(dem_cell "$2" "$3" "$m" "$t")"
  done
  echo "| $1$cells | $(solver_cell "$2" "$3") |"
}

python3 - "$T/sites.csv" <<'PY'
import sys
# the study's square slider (3 µm spacing, radius 100 µm: 3505 sites), every other sphere 1.5 µm
with open(sys.argv[1], "w") as f:
    f.write("x_um,y_um,diameter_um\n")
    k = 0
    for i in range(-40, 41):
        for j in range(-40, 41):
            if 9 * (i * i + j * j) <= 100 * 100:
                f.write(f"{3 * i},{3 * j},{3.0 if k % 2 == 0 else 1.5}\n")
                k += 1
PY

echo "| case | reduced | full | full-explicit | surrogate solvers |"
echo "|---|---|---|---|---|"
row "tri-tri 0° commensurate, 3.86 mN" "--pattern tri-tri --theta 0" 3.86 10
row "tri-tri 30° coating failure, 3.86 mN" "--pattern tri-tri --theta 30" 3.86 10
row "square-tri 0° (stick-slip scene), 1.4 mN" "--pattern square-tri --theta 0" 1.4 10
row "σ_h 0.01 µm seed 1, 1.4 mN" "--pattern square-tri --theta 0 --sigma-h-um 0.01 --seed 1" 1.4 10
row "σ_h 0.01 µm seed 2, 1.4 mN" "--pattern square-tri --theta 0 --sigma-h-um 0.01 --seed 2" 1.4 10
row "per-site sizes 3 : 1.5 µm, 1.4 mN" "--pattern square-tri --theta 0 --slider-sites $T/sites.csv" 1.4 10
# 19 949 spheres (radius 239 µm), loaded per sphere as the study's at 1.4 mN
row "19 949-sphere slider, 7.97 mN" "--pattern square-tri --theta 0 --slider-radius-um 239 --substrate-um 500x500" \
  "$(python3 -c 'print(1.4 * 19949 / 3505)')" 2
# the step: 0.9 and 1.1 of each model's stable estimate (from its run above on tri-tri 0°)
row_dt() { # factor
  local cells=""
  for m in reduced full full-explicit; do
    $B equilibrate --pattern tri-tri --theta 0 --load-mn 3.86 --model $m --equilibrate-us 0.01 \
      --json "$T/p.json" --out "$T/p.csv" 2>/dev/null
    local dt
    dt=$(python3 -c "import json,sys; print($1 * json.load(open(sys.argv[1]))['dt_crit_us'])" "$T/p.json")
    cells+=" | $(dem_cell "--pattern tri-tri --theta 0" 3.86 "$m" 2 "$dt")"
  done
  echo "| tri-tri 0°, 3.86 mN, step $1 × stable estimate, 2 µs$cells | |"
}
row_dt 0.9
row_dt 1.1
