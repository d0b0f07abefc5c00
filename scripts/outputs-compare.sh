#!/usr/bin/env bash
# Compares two folders written by scripts/outputs-run.sh: every file with cmp; where cmp differs,
# compares again with the wall-time fields blanked (JSON `wall_s`, `particle_steps_per_s`,
# `elapsed*`, the logs' times and ETAs, the numbers of the report's stage-time rows `| 1. …`).
# Prints IDENTICAL / SAME-BUT-TIME / DIFFERENT per file and exits 1 if any file differs.
# Usage: scripts/outputs-compare.sh BEFORE AFTER
set -uo pipefail
a=$1; b=$2; bad=0; same=0; timed=0
blank() {
    sed -E -e 's/"(wall_s|particle_steps_per_s|elapsed_s|seconds)": *[-0-9.eE+]+/"\1": T/g' \
        -e 's/[0-9]+(\.[0-9]+)? ?(s|ms|min)\b/T/g' -e 's/ETA [^ ]+/ETA T/g' \
        -e '/^\| [0-9]+\. /s/[0-9]+\.[0-9]+/T/g' -e 's/^Made by superlube .*/STAMP/' "$1"
}
while IFS= read -r f; do
    rel=${f#"$a"/}
    if [ ! -e "$b/$rel" ]; then echo "MISSING in after: $rel"; bad=1; continue; fi
    if cmp -s "$f" "$b/$rel"; then same=$((same+1)); continue; fi
    if diff -q <(blank "$f") <(blank "$b/$rel") >/dev/null; then timed=$((timed+1)); echo "SAME-BUT-TIME: $rel"; continue; fi
    echo "DIFFERENT: $rel"; bad=1
done < <(find "$a" -type f | sort)
while IFS= read -r f; do rel=${f#"$b"/}; [ -e "$a/$rel" ] || { echo "NEW in after: $rel"; bad=1; }; done < <(find "$b" -type f | sort)
echo "identical: $same, same but wall time: $timed"
exit $bad
