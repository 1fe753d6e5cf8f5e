#!/bin/sh
# Hostile sizes and numbers through the command line (docs/cli.md#contract): work on two threads
# that runs out of memory fails like work on one (exit 1, "out of memory", never an abort); every
# numeric option refuses NaN and infinity and the documented out-of-range values; a 10 MB line
# with an error in it gives one short error line; messages about JSON content are plain words with
# the file and line.
#   tests/app/cli_limits.sh TACTILE WORKDIR
. "$(dirname "$0")/cli_test_lib.sh"

command -v python3 > /dev/null || fail "python3 is needed to write the test files"
"$T" simulate --scene room1 --runs 2 --steps 3000 --out-dir sim --quiet > /dev/null

# ---- worker threads: out of memory is reported, never an abort ----
# A run of 1,500 steps in which every dome of every group is pressed, alternating Wall and Corner.
python3 - << 'EOF'
import random
random.seed(1)
groups = ["F", "FLC", "L", "RLC", "B", "RRC", "R", "FRC"]
cols = ["step", "x", "y", "theta", "v", "omega", "blocked"]
for s in range(44):
    cols += ["n%d" % s, "s%d" % s]
cols += ["truth_" + g for g in groups]
with open("pressed.csv", "w") as f:
    f.write("# format: tactile-run 1\n# scene: room1\n# dt: 0.1\n" + ",".join(cols) + "\n")
    for i in range(1500):
        row = [str(i), "500", "500", "0", "0", "0", "0"]
        for s in range(44):
            row += ["%.3f" % random.uniform(0.1, 5), "%.3f" % random.uniform(-1, 1)]
        row += ["Wall" if (i // 100) % 2 == 0 else "Corner"] * 8
        f.write(",".join(row) + "\n")
EOF
# `expect_oom WHAT COMMAND...` runs COMMAND with at most 500 MB of address space.
expect_oom() {
  what=$1
  shift
  status=0
  (ulimit -v 500000 && exec "$@") > oom.out 2> oom.err || status=$?
  [ "$status" -eq 1 ] || fail "$what: expected exit 1, got $status (134 is an abort): $(cat oom.err)"
  grep -q "tactile: error: out of memory" oom.err || fail "$what: no 'out of memory': $(cat oom.err)"
}
# Models of the largest order (4096) with full covariances of the widest features: each fit's
# statistics need far more than 500 MB, and on two threads the fits run on worker threads.
F=normal+shear+touch+context+neighbours
expect_oom "train on 2 threads" "$T" train --runs pressed.csv --groups R --order 4096 \
  --cov nodal-full --init random-from-data --features $F --threads 2 --max-iter 1 --out m.json
expect_oom "sweep on 2 threads" "$T" sweep --runs pressed.csv --groups R --orders 4096 \
  --covs nodal-full grand-full --init random-from-data --features $F --floors 0.01 --threads 2 \
  --max-iter 1 --out s.json
[ ! -e m.json ] && [ ! -e s.json ] || fail "a failed train or sweep left a file"

# ---- numeric options: one rule, NaN and infinity never pass ----
expect_usage() {
  what=$1
  pattern=$2
  shift 2
  status=0
  "$@" > usage.out 2> usage.err || status=$?
  [ "$status" -eq 2 ] || fail "$what: expected exit 2, got $status: $(cat usage.err)"
  grep -q -- "$pattern" usage.err || fail "$what: expected '$pattern': $(cat usage.err)"
}
R="--runs sim/run_0000.csv sim/run_0001.csv"
# shellcheck disable=SC2086
{
  expect_usage "sweep --floors nan" "tactile: error: variance floor nan is out of range" \
    "$T" sweep $R --groups R --floors nan --out s.json
  expect_usage "sweep --floors inf" "variance floor inf is out of range" \
    "$T" sweep $R --groups R --floors inf --out s.json
  expect_usage "sweep --floors 1e-320" "a floor is 0 (none) or a finite number of at least" \
    "$T" sweep $R --groups R --floors 1e-320 --out s.json
  expect_usage "sweep --holdout nan" "the held-out share must be between 0 and 1" \
    "$T" sweep $R --groups R --holdout nan --out s.json
  expect_usage "sweep --orders 1000000000" "model order 1000000000 is out of range: an order is a whole number from 1 to 4096" \
    "$T" sweep $R --groups R --orders 1000000000 --out s.json
  expect_usage "sweep --tol nan" "the tolerance must be a finite number of at least 0" \
    "$T" sweep $R --groups R --tol nan --out s.json
  expect_usage "train --holdout nan" "--holdout must be a number in \[0, 1), got nan" \
    "$T" train $R --groups R --holdout nan --out m.json
  expect_usage "train --floor nan" "--floor must be a finite number >= 0, got nan" \
    "$T" train $R --groups R --floor nan --out m.json
  expect_usage "train --floor 1e-320" "--floor must be 0 (no floor) or at least 2.2250738585072014e-308" \
    "$T" train $R --groups R --floor 1e-320 --out m.json
  expect_usage "train --tol inf" "--tol must be a finite number >= 0, got inf" \
    "$T" train $R --groups R --tol inf --out m.json
  expect_usage "train --order 5000" "--order must be between 1 and 4096, got 5000" \
    "$T" train $R --groups R --order 5000 --out m.json
  expect_usage "train --emission-weight nan" "--emission-weight must be a finite number > 0, got nan" \
    "$T" train $R --groups R --emission-weight nan --out m.json
  expect_usage "fit --floor nan" "--floor must be a finite number >= 0, got nan" \
    "$T" fit --train t.csv --floor nan
  expect_usage "simulate --dt nan" "--dt must be a number in (0, 1\], got nan" \
    "$T" simulate --scene room1 --dt nan --out x.csv
  expect_usage "classify --stay nan" "--stay must be a number in \[0, 1\], got nan" \
    "$T" classify --model m.json --run sim/run_0000.csv --stay nan
  expect_usage "classify --threshold nan" "--threshold must be a finite number >= 0, got nan" \
    "$T" classify --model m.json --run sim/run_0000.csv --threshold nan
}

# ---- one 10 MB line: one short error line ----
python3 -c "import sys; sys.stdout.write('a' * 10000000)" > big.txt
short_error() {
  what=$1
  shift
  status=0
  "$@" > big.out 2> big.err || status=$?
  [ "$status" -ne 0 ] || fail "$what: accepted a 10 MB line"
  size=$(wc -c < big.err)
  [ "$size" -lt 2000 ] || fail "$what: a $size-byte error message: $(head -c 400 big.err)"
  grep -q "tactile: error: " big.err || fail "$what: $(head -c 400 big.err)"
}
cp big.txt big.csv
short_error "run file" "$T" import --db big.db big.csv
(printf 'f0,label\n'; cat big.txt; printf ',a\n') > feat.csv
short_error "feature table" "$T" fit --train feat.csv
(printf 'run,group,first_step,last_step,class\nr,F,0,'; cat big.txt; printf ',Wall\n') > lab.csv
short_error "label file" "$T" labels import --db big.db --set s lab.csv
(printf '{"format": "'; cat big.txt; printf '"}\n') > rep.json
short_error "report" "$T" report rep.json
(printf '['; cat big.txt) > syn.json
short_error "JSON syntax" "$T" report syn.json

# ---- JSON content in plain words, with the file ----
printf '{"format": "tactile-sweep", "cells": "none"}\n' > sw.json
status=0
"$T" report sw.json > rep.out 2> rep.err || status=$?
[ "$status" -eq 1 ] || fail "report of a malformed sweep: exit $status: $(cat rep.err)"
grep -q "json.exception" rep.err && fail "the JSON library's own text leaked: $(cat rep.err)"
grep -q "tactile: error: sw.json" rep.err || fail "report should name the file: $(cat rep.err)"
printf '{"format": 3}\n' > f3.json
status=0
"$T" report f3.json > rep.out 2> rep.err || status=$?
[ "$status" -eq 1 ] || fail "report of a numeric format: exit $status"
grep -q "json.exception" rep.err && fail "the JSON library's own text leaked: $(cat rep.err)"
printf '{\n "segments": [\n  {"run": "r", "group": "F", "first_step": "3", "last_step": 5, "class": "Wall"}]}\n' > l.json
status=0
"$T" labels import --db lab.db --set s l.json > lab.out 2> lab.err || status=$?
[ "$status" -eq 1 ] || fail "labels import of a string step: exit $status: $(cat lab.err)"
grep -q 'l.json:3: segment 1: "first_step" holds a string where an integer is needed' lab.err ||
  fail "labels import of a string step: $(cat lab.err)"

echo "ok: limits"
