#!/usr/bin/env bash
# Runs the benchmark set with one release binary and writes docs/performance.md: per command its
# wall time, CPU time and peak memory, with the machine, the UTC date, the commit and the command.
# Usage: scripts/performance.sh [BIN] [OUT.md]
#   BIN     the release binary (default: target/release/superlube; build it with
#           `cargo build --release`)
#   OUT.md  the page to write (default: docs/performance.md)
# Environment: PERF_COMMIT  the commit BIN was built from, when not this checkout's HEAD.
# About 800 s of CPU in all (the default design with its DEM runs, with and without the yield, is
# half of it): some 14 min on an idle 2-core machine.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
invocation="scripts/performance.sh${*:+ $*}"
[ -n "${PERF_COMMIT:-}" ] && invocation="PERF_COMMIT=$PERF_COMMIT $invocation"
bin=$(realpath "${1:-$root/target/release/superlube}")
page=${2:-$root/docs/performance.md}
[ -x "$bin" ] || { echo "no binary at $bin: run cargo build --release" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "needs /usr/bin/time (GNU time)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rows=$work/rows.md

commit=${PERF_COMMIT:-$(git -C "$root" rev-parse --short HEAD)}
if [ -z "${PERF_COMMIT:-}" ] && [ -n "$(git -C "$root" status --porcelain --untracked-files=no)" ]; then
    commit="$commit (with uncommitted changes)"
fi
model=$(lscpu | sed -n 's/^Model name: *//p' | head -1)
cpus=$(nproc)
load=$(cut -d' ' -f1-3 /proc/loadavg)
date=$(date -u '+%Y-%m-%d %H:%M')
version=$("$bin" --version)

# measure WHAT -- ARGS...: runs `superlube ARGS` in a fresh folder, appends a table row
measure() {
    local what=$1; shift 2
    local dir l1; dir=$(mktemp -d "$work/run.XXXX")
    l1=$(cut -d' ' -f1 /proc/loadavg)
    echo "performance: $what" >&2
    (cd "$dir" && /usr/bin/time -f '%e %U %S %M' -o "$dir/time.txt" "$bin" "$@" >stdout.txt 2>stderr.txt) ||
        { echo "FAILED: superlube $*" >&2; tail -5 "$dir/stderr.txt" >&2; exit 1; }
    read -r wall user sys rss <"$dir/time.txt"
    printf '| %s | `superlube %s` | %.2f | %.2f | %d | %s |\n' "$what" "$*" "$wall" \
        "$(echo "$user + $sys" | bc -l)" "$((rss / 1024))" "$l1" >>"$rows"
}

measure "Tier 1 screen: the study's sweep, 301 θ × 4 loads, square-tri (3505 spheres)" -- \
    screen --pattern square-tri --out s.csv
measure "Tier 1 screen: the same, tri-tri" -- \
    screen --pattern tri-tri --out s.csv
measure "Tier 2 landscape: 51 × 51 placements over the repeat cell" -- \
    landscape --pattern square-tri --theta-deg 0 --load-mn 1.4 --grid 51 --out dz.csv
measure "Tier 2 friction estimate: one (θ, α, W)" -- \
    friction --pattern square-tri --theta-deg 10.2 --alpha-deg 90 --load-mn 1.4 --out f.csv
measure "Tier 2 friction estimate: 3 loads of one (θ, α)" -- \
    friction --pattern tri-tri --theta-deg 10.6 --alpha-deg 6.5 --load-mn 0.35,1.4,2.1 --out f.csv
measure "tolerance map: 41 θ × 21 pull directions × 11 loads (the default)" -- \
    tolerance --pattern square-tri --theta-deg 0 --alpha-deg 90 --out-dir tol
measure "yield of one answer, the estimate's part: 59 devices (square-tri θ = 7.3°, pull 82.53°, σ_h 0.002 µm)" -- \
    yield --pattern square-tri --sigma-h-um 0.002 --theta-deg 7.3 --direction-deg 82.53 --no-dem --out-dir y
measure "yield of one answer with its DEM: the same, the DEM locating the devices that set the quote and its bound, and 10 fresh devices as a check pooled in (2 + 2 + 60 µs runs, 2 side by side, at most 40)" -- \
    yield --pattern square-tri --sigma-h-um 0.002 --theta-deg 7.3 --direction-deg 82.53 --out-dir y
for m in reduced full; do
    measure "Tier 3 DEM, the study's protocol 10 + 10 + 300 µs, --model $m: superlubric scene (square-tri 0°, α = 90°, 1.4 mN)" -- \
        slide --pattern square-tri --theta-deg 0 --alpha-deg 90 --load-mn 1.4 --model "$m" --out s.csv --json s.json
    measure "Tier 3 DEM, the same, --model $m: stick-slip scene (square-tri 0°, α = 0°, 1.4 mN)" -- \
        slide --pattern square-tri --theta-deg 0 --alpha-deg 0 --load-mn 1.4 --model "$m" --out s.csv --json s.json
    measure "Tier 3 DEM, the same, --model $m: coating-failure scene (tri-tri 30°, α = 0°, 2.45 mN)" -- \
        slide --pattern tri-tri --theta-deg 30 --alpha-deg 0 --load-mn 2.45 --model "$m" --out s.csv --json s.json
done
measure "design, the default, surrogate tiers only (2 patterns, tolerance ±0.1° × ±0.5°), each answer's yield by the estimate" -- \
    design --no-dem --out-dir d
measure "design, the default, nominal (no tolerance), no yield" -- \
    design --no-dem --no-yield --theta-tol-deg 0 --direction-tol-deg 0 --out-dir d
measure "design, the default with its DEM confirmation, no yield (fresh folder)" -- \
    design --no-yield --out-dir d
measure "design, the default with its DEM confirmation and each answer's yield with its DEM (fresh folder)" -- \
    design --out-dir d

lammps="\`lmp\` was not found on this machine: no LAMMPS figure."
if command -v lmp >/dev/null; then
    dir=$work/lammps; mkdir -p "$dir"
    flags="--pattern square-tri --theta-deg 0 --alpha-deg 90 --load-mn 1.4 --equilibrate-us 0.2 --relax-us 0.2 --slide-us 1"
    # shellcheck disable=SC2086
    if (cd "$dir" && "$bin" export-lammps $flags --out-dir run >/dev/null 2>&1) &&
        (cd "$dir/run" && /usr/bin/time -f '%e %U %S %M' -o ../time.txt lmp -in in.superlube.lmp >lmp.log 2>&1); then
        steps=$(python3 -c 'import json,sys; s=json.load(open(sys.argv[1]))["steps"]; print(s["equilibrate"] + s["relax"] + s["slide"])' "$dir/run/export.json")
        read -r wall user sys rss <"$dir/time.txt"
        lammps=$(printf 'LAMMPS (`%s`, one process) on the exported superlubric scene (`superlube export-lammps %s`, then `lmp -in in.superlube.lmp`): %d steps in %.1f s wall, %.2f ms per step.' \
            "$(command -v lmp)" "$flags" "$steps" "$wall" "$(echo "1000 * $wall / $steps" | bc -l)")
    else
        lammps="LAMMPS (\`$(command -v lmp)\`) did not complete the exported scene on this machine: no LAMMPS figure ($(tail -1 "$dir/run/lmp.log" 2>/dev/null))."
    fi
fi

load_end=$(cut -d' ' -f1-3 /proc/loadavg)
tmp=$(mktemp "$(dirname "$page")/.performance.XXXX")
cat >"$tmp" <<EOF
# Performance

What each tier and the design cost, measured by \`scripts/performance.sh\` (this page is its
output: rerun it rather than editing). Every figure is one run of the release binary from the
shell, in a fresh folder (no reused stages), process start and file writing included: wall time,
CPU time (user + system, all threads) and peak resident memory.

- Machine: $model, $cpus CPUs; load average (1, 5, 15 min) $load at the start, $load_end at the
  end, and the 1-minute load when each command started in the last column.
- Date: $date UTC.
- Commit: $commit; binary: $version.
- Command: \`$invocation\`.

The machine may be shared: where the load exceeds its CPUs other work ran beside the command, so
its wall time is an upper bound; its CPU time is less affected. Compare two builds only in the same sitting on the same machine
(CONTRIBUTING.md, "Benchmarks").

| what | command | wall (s) | CPU (s) | peak memory (MB) | load |
|---|---|---|---|---|---|
$(cat "$rows")

$lammps

The scenes: the study's presets (3 µm spheres, 364 × 270 µm triangular substrate, square and
triangular sliders of 3505 spheres). The design's DEM confirmation runs its short protocol
(2 + 2 + 60 µs, \`--dem-model reduced\`) side by side on every core, plus one run of the study's
protocol on the best design (the protocol check). The per-call costs inside the tiers
(one equilibrium, one path) are in the criterion benchmarks: \`cargo bench --bench screen\`,
\`landscape\`, \`friction\`, \`dem\`.
EOF
mv "$tmp" "$page"
echo "wrote $page" >&2
