#!/bin/sh
# Judge training runs added to the recipe on the selection corpus (docs/learning.md, sixth
# selection): every group at its default setting, online decision, fit seeds 1-3.
#
#   bench/learning/extras_choice.sh TACTILE SEL OUT NAME [EXTRA_RUN.csv ...]
#
#   TACTILE  the tactile program (build/app/tactile)
#   SEL      the selection corpus: SEL/recipe/s1_*.csv and s2_*.csv (the recipe's numbered runs of
#            plan seeds 1 and 2 without the built-in scenes) and SEL/office_K/*.csv
#   OUT      working folder; NAME_S.r1.json, NAME_S.r2.json, NAME_S.of.json per fit seed S
#   NAME     the tag of this set of extra runs (none: the corpus alone)
#
# Environment: FIT_SEEDS ("1 2 3"), TRAIN_ARGS (extra `tactile train` options, for example
# "--groups R --features normal+shear+touch+context --order 16 --emission-weight 1").
#
# Three trainings per fit seed: seed-1 recipe runs and the extras scored on the seed-2 recipe runs,
# the other way round, and all recipe runs and the extras scored on the office runs (rooms no
# training run is in). Then: bench/learning/extras_choice.py OUT NAME...
# shellcheck disable=SC2086 # TRAIN_ARGS is a list of options
set -eu
T=$1
SEL=$2
OUT=$3
NAME=$4
shift 4
mkdir -p "$OUT"
TRAIN_ARGS=${TRAIN_ARGS:-}
for S in ${FIT_SEEDS:-1 2 3}; do
  "$T" train --runs "$SEL"/recipe/s1_*.csv "$@" --test-runs "$SEL"/recipe/s2_*.csv \
    --seed "$S" $TRAIN_ARGS --threads 2 --out "$OUT/${NAME}_$S.r2.json" > /dev/null 2>&1
  "$T" train --runs "$SEL"/recipe/s2_*.csv "$@" --test-runs "$SEL"/recipe/s1_*.csv \
    --seed "$S" $TRAIN_ARGS --threads 2 --out "$OUT/${NAME}_$S.r1.json" > /dev/null 2>&1
  "$T" train --runs "$SEL"/recipe/*.csv "$@" --test-runs "$SEL"/office_*/*.csv \
    --seed "$S" $TRAIN_ARGS --threads 2 --out "$OUT/${NAME}_$S.of.json" > /dev/null 2>&1
done
