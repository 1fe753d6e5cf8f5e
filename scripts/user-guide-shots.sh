#!/usr/bin/env bash
# Makes the user guide's screenshots (docs/images/guide-*.png) with the workbench's --screenshot
# option on the offscreen platform, from a database this script builds with the CLI: simulated
# runs in three built-in scenes, their truth as the label set "truth", half a run labelled by hand
# as "annotations", a stored model and a small sweep; for the simulator window's three modes a
# navigator model by the standard recipe and runs driven in the window. Settings go to a temporary
# home, so the pictures do not depend on the user's.
# Usage: scripts/user-guide-shots.sh [BUILD_DIR]     (default build/)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
T=$build/app/tactile
W=$build/app/tactile-workbench
out=$root/docs/images
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_CONFIG_HOME=$work/config QT_QPA_PLATFORM=offscreen

for scene in room1 room3 chapter5; do
  "$T" simulate --scene "$scene" --runs 2 --steps 2000 --seed 7 --out-dir "$work/runs" \
    --prefix "$scene" --quiet >/dev/null
done
db=$work/guide.db
"$T" import --db "$db" "$work/runs" >/dev/null
"$T" autolabel --db "$db" --all --set truth >/dev/null
# "annotations": an annotator part way through chapter5_0000 (the truth's segments up to step 900)
# who has finished the test run chapter5_0001 (all of its truth), to review predictions against.
"$T" labels export --db "$db" --set truth "$work/truth.csv" >/dev/null
awk -F, '/^# run chapter5_000[01] / || /^run,/ || ($1 == "chapter5_0000" && $4 <= 900) ||
         $1 == "chapter5_0001" { print }' \
  "$work/truth.csv" >"$work/annotations.csv"
"$T" labels import --db "$db" --set annotations "$work/annotations.csv" >/dev/null
train_runs=(room1_0000 room3_0000 chapter5_0000)
test_runs=(room1_0001 room3_0001 chapter5_0001)
"$T" train --db "$db" --set truth --train-runs "${train_runs[@]}" --test-runs "${test_runs[@]}" \
  >/dev/null
"$T" sweep --db "$db" --set truth --train-runs "${train_runs[@]}" --test-runs "${test_runs[@]}" \
  --orders 1 2 4 --covs nodal-diag grand-diag --floors 0.03 0.1 >/dev/null
model=$("$T" models list --db "$db" --json | sed -n 's/.*"name":"\([^"]*\)".*/\1/p' | head -1)

# shot LOCALE FILE ARGS...: the workbench under LOCALE (its language and numbers) to FILE.
shot() {
  local locale=$1 file=$2
  shift 2
  env LANG="$locale" LC_ALL="$locale" LANGUAGE= "$W" --db "$db" "$@" --screenshot "$out/$file"
  echo "wrote docs/images/$file"
}
shot C.UTF-8 guide-workbench.png --run chapter5_0000 --step 700
shot C.UTF-8 guide-sweep.png --sweep 1
shot C.UTF-8 guide-predictions.png --run chapter5_0001 --step 900 --model "$model"
shot de_DE.UTF-8 guide-de.png --run chapter5_0000 --step 700
shot zh_CN.UTF-8 guide-zh_CN.png --run chapter5_0000 --step 700

# The simulator window, one picture per mode. Each picture is made on a copy of the database, so
# the runs left part way by a screenshot do not end up in the guide's database.
# simshot FILE ARGS...: the simulator window (with --simulate ... in ARGS) to FILE.
simshot() {
  local file=$1
  shift
  cp "$db" "$work/shot.db"
  env LANG=C.UTF-8 LC_ALL=C.UTF-8 LANGUAGE= "$W" --db "$work/shot.db" "$@" --screenshot "$out/$file"
  rm -f "$work/shot.db"
  echo "wrote docs/images/$file"
}
# Practice: a wall-following explorer's commands replayed as if typed, the whole scene shown.
"$T" simulate --scene practice --driver wall-follow --steps 700 --seed 3 --out "$work/practice.csv" \
  --quiet >/dev/null
simshot guide-sim-practice.png --simulate practice --commands "$work/practice.csv" --rate 0 \
  --whole-scene --data
# Experiment: start and goal from seed 5 in room2, the scene hidden, a subject driving.
"$T" simulate --scene room2 --driver wall-follow --steps 520 --seed 5 --out "$work/experiment.csv" \
  --quiet >/dev/null
simshot guide-sim-experiment.png --simulate room2 --mode experiment --subject "Ada Lovelace" \
  --seed 5 --commands "$work/experiment.csv" --rate 0
# Autonomous: the navigator with a model by the standard recipe (docs/navigation-bench.md) on the
# chapter-5 scene, from the first start (seed) it reaches the goal from after following a wall.
"$T" simulate --plan training --runs 80 --seed 1 --out-dir "$work/train" --quiet >/dev/null
"$T" train --runs "$work"/train/*.csv --out "$work/navigator.json" --threads 2 >/dev/null
"$T" models import --db "$db" --name navigator "$work/navigator.json" >/dev/null
nav_seed=$("$T" navigate --scene chapter5 --model "$work/navigator.json" --seeds 1-40 --threads 2 \
  --quiet --json | jq -r '[.runs[] | select(.outcome == "success" and .steps > 500)][0].seed')
[ "$nav_seed" != null ] || { echo "no seed of 1-40 reaches the goal after a wall" >&2; exit 1; }
simshot guide-sim-autonomous.png --simulate chapter5 --mode autonomous --model navigator \
  --seed "$nav_seed" --step 400 --data
# The navigator: its whole run, recorded in the window, opened in the workbench with its strips.
env LANG=C.UTF-8 LC_ALL=C.UTF-8 LANGUAGE= "$W" --db "$db" --simulate chapter5 --mode autonomous \
  --model navigator --seed "$nav_seed" --step 6000 --screenshot "$work/whole-run.png"
shot C.UTF-8 guide-navigator.png --run autonomous_chapter5 --step 400
