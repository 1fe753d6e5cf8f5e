#!/bin/sh
# Choose each group's model family (Gaussian mixtures or boosted trees) on the selection corpus
# (docs/learning.md#boosted-trees), by the rule of the sixth selection: every group at its default
# setting of each family, online decision, median of fit seeds 1-3 (bench/learning/extras_choice.sh
# and extras_choice.py). The scenes the transfer benchmark scores on are never used.
#
#   bench/learning/family_choice.sh TACTILE SEL OUT
#
#   TACTILE  the tactile program (build/app/tactile)
#   SEL      the selection corpus, made here when SEL/recipe is missing: the training recipe of
#            plan seeds 1 and 2 (80 runs each) without the runs in the built-in scenes, and two
#            wall-following runs in each office room 1-8 (driver seed 11 follows the left wall,
#            14 the right)
#   OUT      working folder; gmm_S.*.json and gbt_S.*.json per fit seed S, then the table
#
# Environment: FIT_SEEDS ("1 2 3"), GBT_ARGS (the trees' options, "--method gbt").
set -eu
T=$1
SEL=$2
OUT=$3
HERE=$(dirname "$0")
if [ ! -d "$SEL/recipe" ]; then
  mkdir -p "$SEL/recipe"
  for P in 1 2; do
    "$T" simulate --plan training --runs 80 --seed "$P" --out-dir "$SEL/plan$P" --quiet > /dev/null
    for F in "$SEL/plan$P"/*.csv; do
      SCENE=$(sed -n 's/^# scene: //p;/^step,/q' "$F")
      case "$SCENE" in room1 | room2 | room3 | chapter5) continue ;; esac
      # Training reads the steps only: the generated scene files stay behind.
      cp "$F" "$SEL/recipe/s${P}_$(basename "$F")"
    done
  done
  for K in 1 2 3 4 5 6 7 8; do
    mkdir -p "$SEL/office_$K"
    "$T" simulate --scene "random:office:$K" --driver wall-follow --steps 4000 --seed 11 \
      --out "$SEL/office_$K/left.csv" --quiet > /dev/null
    "$T" simulate --scene "random:office:$K" --driver wall-follow --steps 4000 --seed 14 \
      --out "$SEL/office_$K/right.csv" --quiet > /dev/null
  done
fi
"$HERE/extras_choice.sh" "$T" "$SEL" "$OUT" gmm
TRAIN_ARGS=${GBT_ARGS:-"--method gbt"} "$HERE/extras_choice.sh" "$T" "$SEL" "$OUT" gbt
for D in online offline step; do
  echo "### decision: $D"
  echo
  "$HERE/extras_choice.py" --decision "$D" "$OUT" gmm gbt
  echo
done
