#!/usr/bin/env bash
# Labelling one 3,000-step run of the demo database by hand and from a model, in the real window
# (bench/gui/labelling_bench.cpp): the demo database as scripts/run.sh makes it (two wall-following
# runs of 3,000 steps in each built-in scene, truth as the label set "truth"), a model trained on
# the truth of every run but the one labelled, then both ways of working on that run.
# Usage: bench/gui/labelling.sh [BUILD_DIR] [RUN...]   (default build/; the demo runs of 3,000 steps:
#        room1_0001 room2_0000 room3_0000)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
shift $(($# > 0 ? 1 : 0))
runs=("$@")
[ ${#runs[@]} -gt 0 ] || runs=(room1_0001 room2_0000 room3_0000)
T=$build/app/tactile
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for scene in room1 room2 room3 chapter5; do
  "$T" simulate --scene "$scene" --runs 2 --steps 3000 --seed 1 --out-dir "$work/runs" \
    --prefix "$scene" --quiet >/dev/null
done
db=$work/demo.db
"$T" import --db "$db" "$work/runs" >/dev/null
"$T" autolabel --db "$db" --all --set truth >/dev/null
for run in "${runs[@]}"; do
  mapfile -t others < <("$T" runs list --db "$db" --json | python3 -c "
import json, sys
for r in json.load(sys.stdin)['runs']:
    if r['name'] != '$run': print(r['name'])")
  "$T" train --db "$db" --set truth --train-runs "${others[@]}" --test-runs "$run" \
    --name "model_$run" >/dev/null 2>&1
  echo "run $run: $("$T" runs list --db "$db" | awk -v r="$run" '$1 == r { print $3 }') steps" >&2
  QT_QPA_PLATFORM=offscreen "$build/bench/gui/tactile_labelling_bench" "$db" "$run" "model_$run" \
    2>"$work/stderr" || { grep -v "XDG_RUNTIME\|propagateSizeHints" "$work/stderr" >&2; exit 1; }
done
