#!/bin/sh
# The learning verbs report what the engine did: components dropped for lack of mass, held-out rows
# whose log-likelihood is -inf (one definition of mean_loglik for fit, train and sweep), warnings
# for a variance floor that hides a feature, and no settings the Gaussian method does not use.
#   tests/app/cli_learning.sh TACTILE WORKDIR
. "$(dirname "$0")/cli_test_lib.sh"
has() {  # has FILE TEXT: the file contains TEXT literally
  grep -qF -- "$2" "$1" || fail "$1 lacks $2: $(cat "$1")"
}
lacks() {
  if grep -qF -- "$2" "$1"; then fail "$1 has $2: $(cat "$1")"; fi
}

# Two classes; class a has exactly 4 distinct points.
{
  echo "f0,f1,label"
  for i in 0 1 2 3 4 5 6 7 8 9; do
    echo "0,0,a"
    echo "1,0,a"
    echo "0,1,a"
    echo "1,1,a"
    echo "5.$i,5.$i,b"
    echo "6.$i,4.$i,b"
  done
} > train.csv

# Order 64 on 4 distinct points keeps 4 components: 60 dropped, and said so.
"$T" fit --train train.csv --order 64 --floor 0.01 --json > fit64.json || fail "fit exited $?"
has fit64.json '"components_per_class":[4,'
has fit64.json '"dropped_components_per_class":[60,'
has fit64.json '"dropped_components":'
for key in '"fit_s":' '"mean_loglik":' '"iterations":' '"accuracy":' '"neg_inf_rows":0'; do
  has fit64.json "$key"
done
"$T" fit --train train.csv --order 64 --floor 0.01 > fit64.txt || fail "fit (text) exited $?"
has fit64.txt "dropped for lack of mass"

# A test row with zero density (-inf log-likelihood) is counted, not averaged.
{
  echo "f0,f1,label"
  echo "0.5,0.5,a"
  echo "1e200,0,a"
  echo "5.5,5.5,b"
} > test.csv
"$T" fit --train train.csv --test test.csv --order 2 --json > neginf.json || fail "fit exited $?"
has neginf.json '"neg_inf_rows":1'
lacks neginf.json '"mean_loglik":null'
"$T" fit --train train.csv --test test.csv --order 2 > neginf.txt || fail "fit (text) exited $?"
has neginf.txt "1 test rows with log-likelihood -inf left out"

# The Gaussian method: no order, covariance form or initialisation; no one-vs-rest models fitted;
# --reg add accepted.
"$T" fit --train train.csv --method gaussian --reg add --json > gauss.json || fail "fit exited $?"
lacks gauss.json '"order":'
lacks gauss.json '"covariance":'
lacks gauss.json '"init":'
has gauss.json '"regularization":"add"'
has gauss.json '"models_fitted":2'

# A feature on the 1e-6 scale with the default floor: a warning naming it, on stderr and in JSON.
{
  echo "f0,f1,label"
  for i in 0 1 2 3 4 5 6 7 8 9; do
    echo "$i,0.00000$i,a"
    echo "$i,0.00001$i,b"
  done
} > tiny.csv
"$T" fit --train tiny.csv --order 1 --json > tiny.json 2> tiny.err || fail "fit exited $?"
has tiny.err "tactile: warning: variance floor 0.01 is"
has tiny.err "feature 1 (f1)"
has tiny.json '"warnings":["variance floor'
"$T" fit --train train.csv --order 2 --json > clean.json 2> clean.err || fail "fit exited $?"
has clean.json '"warnings":[]'
lacks clean.err "warning"

# train and sweep report the same quantities.
"$T" simulate --scene room1 --driver wall-follow --steps 800 --runs 2 --out-dir runs --quiet \
  > /dev/null
"$T" train --runs runs/run_0000.csv runs/run_0001.csv --groups R --order 64 --out m.json \
  --json > train.json 2> /dev/null || fail "train exited $?"
for key in '"dropped_components":' '"neg_inf_rows":' '"mean_loglik":' '"warnings":'; do
  has train.json "$key"
done
lacks train.json '"dropped_components":0'
# when_trained REPORT GROUP REGEX WHAT: a group that trained on these short runs (some need more
# rows per class than they have) has a report line matching REGEX.
when_trained() {
  if grep -q "^$2 " "$1"; then
    grep -Eq "$3" "$1" || fail "$4: $(cat "$1")"
  fi
}
# Unset train options keep each group's own default; a given one applies to every group.
# (RRC and FRC, not F: a group needs two classes with enough rows, and F only touches walls here;
# --min-rows 1: these short runs give RRC fewer rows than the default minimum of 20.)
"$T" train --runs runs/run_0000.csv runs/run_0001.csv --groups R,RRC,FRC --order 4 --min-rows 1 \
  --out d.json > /dev/null 2>&1 || fail "train --order 4 exited $?"
"$T" report d.json > d.txt || fail "report exited $?"
grep -Eq '^R +normal\+shear\+touch\+context\+neighbours +gmm +nodal-full +4 +0\.01 .*online \(evidence x 0\.1\)$' d.txt ||
  fail "R defaults: $(cat d.txt)"
# RRC's and FRC's defaults may need more rows per class than these short runs have; when they
# train, they keep their own feature kind, floor and evidence weight (RRC's kind,
# normal+shear+touch+context, differs from R's neighbours features; FRC's weight, 1, from R's 0.1).
# FRC's default family is trees: --order 4 makes it mixtures, with the mixtures' own features.
when_trained d.txt RRC '^RRC +normal\+shear\+touch\+context +gmm +nodal-full +4 +0\.01 .*online \(evidence x 0\.3\)$' "RRC defaults"
when_trained d.txt FRC '^FRC +normal\+shear\+touch\+context\+neighbours +gmm +nodal-full +4 +0\.01 .*online$' "FRC defaults"
"$T" train --runs runs/run_0000.csv runs/run_0001.csv --groups R,RRC --floor 0.5 --cov nodal-diag \
  --features normal --min-rows 1 --out e.json > /dev/null 2>&1 || fail "train --floor exited $?"
"$T" report e.json > e.txt || fail "report exited $?"
grep -Eq '^R +normal +gmm +nodal-diag +8 +0\.5 ' e.txt || fail "R overridden: $(cat e.txt)"
grep -Eq '^RRC +normal +gmm +nodal-diag +8 +0\.5 ' e.txt || fail "RRC overridden: $(cat e.txt)"
# Boosted trees: each group's own features, rounds, depth and evidence weight unless given; a given
# setting applies to every group and leaves the others per group (R: 200 rounds of depth 6; RRC:
# 100 of depth 4 and the context features; FRC: the motion features, not its mixtures'
# neighbours; as docs/learning.md#training-defaults lists them).
"$T" train --runs runs/run_0000.csv runs/run_0001.csv --groups R,RRC,FRC --method gbt --min-rows 1 \
  --out t.json > /dev/null 2>&1 || fail "train --method gbt exited $?"
"$T" report t.json > t.txt || fail "report exited $?"
grep -Eq '^R +normal\+shear\+touch\+context\+neighbours +gbt +trees 200, depth 6, learning rate 0\.1, min child weight 1 .*online \(evidence x 2\)$' t.txt ||
  fail "R trees defaults: $(cat t.txt)"
when_trained t.txt RRC '^RRC +normal\+shear\+touch\+context +gbt +trees 100, depth 4, .*online \(evidence x 2\)$' "RRC trees defaults"
when_trained t.txt FRC '^FRC +normal\+shear\+touch\+motion +gbt +trees 100, depth 6, .*online \(evidence x 4\)$' "FRC trees defaults"
"$T" train --runs runs/run_0000.csv runs/run_0001.csv --groups R,RRC --trees 7 --min-rows 1 \
  --out t7.json > /dev/null 2>&1 || fail "train --trees 7 exited $?"
"$T" report t7.json > t7.txt || fail "report exited $?"
grep -Eq '^R +.* gbt +trees 7, depth 6, ' t7.txt || fail "R --trees 7: $(cat t7.txt)"
when_trained t7.txt RRC '^RRC +.* gbt +trees 7, depth 4, ' "RRC --trees 7"
# --emission-weight: every group's chain weighs each step's evidence by it; the model file and
# the report say so; a weight that is not > 0 is a usage error (exit 2).
"$T" train --runs runs/run_0000.csv runs/run_0001.csv --groups R --emission-weight 0.25 \
  --min-rows 1 --out w.json > /dev/null 2>&1 || fail "train --emission-weight exited $?"
has w.json '"emission_weight": 0.25'
"$T" report w.json > w.txt || fail "report exited $?"
grep -Eq '^R .* online \(evidence x 0\.25\)' w.txt || fail "R weight: $(cat w.txt)"
for bad in 0 -1 nan; do
  code=0
  "$T" train --runs runs/run_0000.csv --groups R --emission-weight "$bad" --out bad.json \
    > /dev/null 2> bad.err || code=$?
  [ "$code" -eq 2 ] || fail "--emission-weight $bad exited $code"
  grep -q "emission-weight" bad.err || fail "--emission-weight $bad: $(cat bad.err)"
done
# Options of the database form are refused with run files, not ignored; no file is written.
for opt in "--name m" "--set truth" "--train-runs a"; do
  code=0
  # shellcheck disable=SC2086
  "$T" train --runs runs/run_0000.csv --groups R $opt --out db-only.json > /dev/null \
    2> db-only.err || code=$?
  [ "$code" -eq 2 ] || fail "train --runs with $opt exited $code"
  grep -q "need --db" db-only.err || fail "train --runs with $opt: $(cat db-only.err)"
  [ ! -e db-only.json ] || fail "train --runs with $opt wrote a model"
done
for opt in "--name s" "--set truth" "--train-runs a"; do
  code=0
  # shellcheck disable=SC2086
  "$T" sweep --runs runs/run_0000.csv --groups R --orders 2 $opt --out db-only.json > /dev/null \
    2> db-only.err || code=$?
  [ "$code" -eq 2 ] || fail "sweep --runs with $opt exited $code"
  grep -q "need --db" db-only.err || fail "sweep --runs with $opt: $(cat db-only.err)"
  [ ! -e db-only.json ] || fail "sweep --runs with $opt wrote a sweep"
done
"$T" sweep --runs runs/run_0000.csv runs/run_0001.csv --groups R --orders 1,64 \
  --covs nodal-diag --floors 0.03 --out s.json --json > sweep.json || fail "sweep exited $?"
has sweep.json '"warnings":'
[ "$(grep -o '"dropped_components":' s.json | wc -l)" -eq 2 ] || fail "sweep cells: $(cat s.json)"
[ "$(grep -o '"neg_inf_rows":' s.json | wc -l)" -eq 2 ] || fail "sweep cells: $(cat s.json)"
"$T" report s.json > report.txt || fail "report exited $?"
has report.txt "dropped"
# The report of a sweep file: its training runs, each cell's contact patterns kept in the file and
# shown for the best cell; Markdown to a file writes its figures beside it and links them.
has s.json '"patterns":'
has report.txt "runs/run_0000.csv, runs/run_0001.csv"
has report.txt "Contact patterns of group R"
"$T" report s.json --format md --out "sweep report.md" || fail "report md exited $?"
for f in rate_floor rate_order time_error; do
  has "sweep report.md" "](sweep%20report_files/$f.svg)"
  has "sweep report_files/$f.svg" "</svg>"
  lacks "sweep report_files/$f.svg" "nan"
done
"$T" report m.json > model.txt || fail "report exited $?"
has model.txt "dropped"
echo "ok"
