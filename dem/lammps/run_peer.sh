#!/usr/bin/env bash
# Regenerate the study scene, run LAMMPS on it and print the throughput (particle-steps/s).
#
#   dem/lammps/run_peer.sh                       # defaults below
#   STEPS=5000 REPEAT=3 RANKS="1 2" TIES="bond var" dem/lammps/run_peer.sh
#
# Needs: python3, lmp (Debian package `lammps`), mpirun (openmpi) for RANKS > 1.
# Prints one CSV row per run on stdout:
#   engine,ties,ranks,atoms,model_particles,steps,loop_s,particle_steps_per_s,contacts,p_max_GPa,z_um
# particle_steps_per_s = atoms x steps / LAMMPS "Loop time" (atoms = every LAMMPS atom; bond mode
# has 3505 extra control-layer atoms, model_particles = 19526 = 12515 + 3505 + 3505 + 1 counts the
# SPEC's particles only).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
STEPS="${STEPS:-2000}"          # 2000 x 1e-5 us = 0.02 us
REPEAT="${REPEAT:-1}"
RANKS="${RANKS:-1 2}"
TIES="${TIES:-bond var}"
PATTERN="${PATTERN:-square-tri}"
THETA="${THETA:-0}"
LOAD="${LOAD:-1.4}"             # mN
DT="${DT:-1e-5}"                # us
WORK="${WORK:-$(mktemp -d)}"
MODEL_PARTICLES=19526

cp "$here"/in.*.lmp "$WORK"/
for t in $TIES; do
  python3 "$here/gen_scene.py" --pattern "$PATTERN" --theta-deg "$THETA" --load-mN "$LOAD" \
    --ties "$t" --out "$WORK/scene_$t.data" > "$WORK/scene_$t.json"
done
echo "engine,ties,ranks,atoms,model_particles,steps,loop_s,particle_steps_per_s,contacts,p_max_GPa,z_um"
for rep in $(seq "$REPEAT"); do
  for t in $TIES; do
    for np in $RANKS; do
      if [ "$np" = 1 ]; then launch=(lmp); else launch=(mpirun --allow-run-as-root -np "$np" lmp); fi
      log="$WORK/log_${t}_${np}_${rep}.lammps"
      (cd "$WORK" && "${launch[@]}" -in in.equilibrate.lmp -var ties "$t" -var data "scene_$t.data" \
        -var steps "$STEPS" -var every "$STEPS" -var dt "$DT" -var load_mN "$LOAD" \
        -var csv "eq_${t}_${np}.csv" -log "$log" -screen none)
      # "Loop time of 1.23 on 2 procs for 2000 steps with 19526 atoms"
      read -r loop steps atoms < <(awk '/^Loop time of/ {print $4, $9, $12}' "$log" | tail -1)
      res=$(grep '^RESULT' "$log" | tail -1)
      c=$(sed -E 's/.*contacts=([^ ]+).*/\1/' <<<"$res")
      p=$(sed -E 's/.*p_max_GPa=([^ ]+).*/\1/' <<<"$res")
      z=$(sed -E 's/.*z_um=([^ ]+).*/\1/' <<<"$res")
      pss=$(python3 -c "print(f'{$atoms*$steps/$loop:.4g}')")
      echo "lammps,$t,$np,$atoms,$MODEL_PARTICLES,$steps,$loop,$pss,$c,$p,$z"
    done
  done
done
echo "# work dir: $WORK" >&2
