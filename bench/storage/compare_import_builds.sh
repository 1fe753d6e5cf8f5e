#!/bin/sh
# Import speed of two builds side by side, alternating, on the same files:
#   bench/storage/compare_import_builds.sh BASE_TACTILE NEW_TACTILE [ROUNDS] [DIR]
# Data sets (made once with NEW_TACTILE in DIR, default a new temporary folder):
#   synthetic  8 files, 1,000,000 steps (`tactile bench storage --keep`: full-precision values,
#              about 7 of 88 sensor values non-zero, truth columns)
#   big        one file of 1,000,000 steps of the same kind
#   wallfollow 400 simulated wall-following runs in room3, up to 4,000 steps each (~976,000 steps)
#   random     500 simulated random-walk runs in room1, up to 2,000 steps each (~997,000 steps)
#   tiny       20,000 simulated random-walk runs in room1 of 50 steps each (1,000,000 steps)
# Each round imports every data set into a new database with each build (order alternating) and
# prints one line: build, data set, steps, wall seconds, user+sys CPU seconds.
set -eu
BASE=$1
NEW=$2
ROUNDS=${3:-3}
DIR=${4:-$(mktemp -d)}
mkdir -p "$DIR"
if [ ! -d "$DIR/tiny" ]; then
  "$NEW" simulate --scene room1 --driver random --steps 50 --runs 20000 --seed 1 \
    --out-dir "$DIR/tiny" --quiet > /dev/null
fi
if [ ! -f "$DIR/synthetic/bench-7.csv" ]; then
  "$NEW" bench storage --steps 1000000 --files 8 --big-steps 1000000 --repeats 1 --no-compare \
    --dir "$DIR/synthetic" --keep > /dev/null
  mkdir -p "$DIR/big"
  mv "$DIR/synthetic/big.csv" "$DIR/big/big.csv"
  rm -f "$DIR"/synthetic/*.db*
  "$NEW" simulate --scene room3 --driver wall-follow --steps 4000 --runs 400 --seed 1 \
    --out-dir "$DIR/wallfollow" --quiet > /dev/null
  "$NEW" simulate --scene room1 --driver random --steps 2000 --runs 500 --seed 1 \
    --out-dir "$DIR/random" --quiet > /dev/null
fi
measure() {  # build-label tactile data-set
  rm -f "$DIR"/t.db*
  /usr/bin/time -f "%e %U %S" -o "$DIR/time.txt" "$2" import --db "$DIR/t.db" --json \
    "$DIR/$3" > "$DIR/out.json"
  steps=$(sed -n 's/.*"steps":\([0-9]*\)}$/\1/p' "$DIR/out.json")
  awk -v b="$1" -v s="$3" -v n="$steps" '{ print b, s, n, $1, $2 + $3 }' "$DIR/time.txt"
}
i=1
while [ "$i" -le "$ROUNDS" ]; do
  echo "# round $i, $(uptime)" >&2
  for set in synthetic big wallfollow random tiny; do
    if [ $((i % 2)) -eq 1 ]; then
      measure base "$BASE" "$set"
      measure new "$NEW" "$set"
    else
      measure new "$NEW" "$set"
      measure base "$BASE" "$set"
    fi
  done
  i=$((i + 1))
done
rm -f "$DIR"/t.db* "$DIR/time.txt" "$DIR/out.json"
