#!/usr/bin/env bash
# Export a study scene with `superlube export-lammps`, run LAMMPS on it (equilibrate phase only,
# STEPS steps) and print the throughput (particle-steps/s).
#
#   dem/lammps/run_peer.sh                               # defaults below
#   STEPS=5000 REPEAT=3 RANKS="1 2" MOUNT=springs dem/lammps/run_peer.sh
#
# Needs: lmp (Debian package `lammps`), mpirun (openmpi-bin) for RANKS > 1, and the superlube binary:
# $SUPERLUBE, else `superlube` on the PATH, else `cargo run --release` in this repository.
# Prints one CSV row per run on stdout:
#   engine,mount,ranks,atoms,model_particles,steps,loop_s,particle_steps_per_s,contacts,p_max_GPa,z_um
# particle_steps_per_s = LAMMPS atoms x steps / LAMMPS "Loop time" (atoms = every LAMMPS atom: the
# control layer has two sub-layers, so atoms = model_particles + slider spheres).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
STEPS="${STEPS:-2000}"          # 2000 x 1e-5 us = 0.02 us
REPEAT="${REPEAT:-1}"
RANKS="${RANKS:-1 2}"
MOUNT="${MOUNT:-locked}"        # locked | free | springs
PATTERN="${PATTERN:-square-tri}"
THETA="${THETA:-0}"
LOAD="${LOAD:-1.4}"             # mN
DT="${DT:-1e-5}"                # us
WORK="${WORK:-$(mktemp -d)}"
if [ -n "${SUPERLUBE:-}" ]; then sl=("$SUPERLUBE")
elif command -v superlube >/dev/null; then sl=(superlube)
else sl=(cargo run --release --quiet --manifest-path "$root/Cargo.toml" --); fi

"${sl[@]}" export-lammps --pattern "$PATTERN" --theta "$THETA" --load-mn "$LOAD" --tilt "$MOUNT" \
  --dt-us "$DT" --dump-us 0 --out "$WORK/export" >&2
model=$(python3 -c "import json,sys; m=json.load(open(sys.argv[1])); i=m['ids']; \
print(i['substrate']['count'] + i['slider']['count'] * 2 + 1)" "$WORK/export/export.json")
echo "engine,mount,ranks,atoms,model_particles,steps,loop_s,particle_steps_per_s,contacts,p_max_GPa,z_um"
for rep in $(seq "$REPEAT"); do
  for np in $RANKS; do
    if [ "$np" = 1 ]; then launch=(lmp); else launch=(mpirun --allow-run-as-root -np "$np" lmp); fi
    log="$WORK/log_${np}_${rep}.lammps"
    (cd "$WORK/export" && "${launch[@]}" -in in.superlube.lmp -var nsteps "$STEPS" -var every "$STEPS" \
      -var csv "ts_${np}_${rep}.csv" -log "$log" -screen none)
    # the first run is the equilibrate phase: "Loop time of 1.23 on 2 procs for 2000 steps with 23031 atoms"
    read -r loop steps atoms < <(awk '/^Loop time of/ {print $4, $9, $12; exit}' "$log")
    res=$(grep '^RESULT phase=equilibrate' "$log" | tail -1)
    c=$(sed -E 's/.*contacts=([^ ]+).*/\1/' <<<"$res")
    p=$(sed -E 's/.*p_max_GPa=([^ ]+).*/\1/' <<<"$res")
    z=$(sed -E 's/.*z_um=([^ ]+).*/\1/' <<<"$res")
    pss=$(python3 -c "print(f'{$atoms*$steps/$loop:.4g}')")
    echo "lammps,$MOUNT,$np,$atoms,$model,$steps,$loop,$pss,$c,$p,$z"
  done
done
echo "# work dir: $WORK" >&2
