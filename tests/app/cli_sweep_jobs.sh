#!/bin/sh
# Sweeps planned for workers (docs/cluster.md), on an SQLite file and on the test server: one
# check of the request (order 5000 refused in the same words by every form), plan, status, work by
# 1, 2 and 4 worker processes at once with every cell stored once and equal to the one-process
# sweep's, a worker killed with SIGKILL mid-job whose claim another worker takes over when its
# lease runs out, and export.
#   tests/app/cli_sweep_jobs.sh TACTILE WORKDIR   (TACTILE_TEST_PG_FILE: the server, optional)
. "$(dirname "$0")/cli_test_lib.sh"
command -v python3 > /dev/null || fail "python3 is needed to read the JSON output"

"$T" simulate --scene room1 --runs 3 --steps 300 --out-dir b1 --prefix room1 --quiet > /dev/null
"$T" simulate --scene chapter5 --runs 3 --steps 300 --out-dir b2 --prefix ch5 --quiet > /dev/null

json() { python3 -c "import json,sys; d=json.load(sys.stdin); print($1)"; }

# The one check: the same words from every form of the request.
"$T" import --db order.db b1 > /dev/null
for form in "sweep --runs b1/room1_0000.csv --out x.json" \
  "sweep --db order.db --set truth --train-runs room1_0000 --test-runs room1_0001" \
  "sweep plan --db order.db --set truth --train-runs room1_0000 --test-runs room1_0001"; do
  code=0
  # shellcheck disable=SC2086
  "$T" $form --orders 1,5000 2> order.err > /dev/null || code=$?
  [ "$code" -eq 2 ] || fail "$form --orders 5000 exited $code"
  [ "$(cat order.err)" = "tactile: error: model order 5000 is out of range: an order is a whole number from 1 to 4096" ] ||
    fail "$form --orders 5000 said: $(cat order.err)"
done

# Same cells whatever computed them: every field but the times.
same_cells() {
  python3 - "$1" "$2" << 'EOF' || fail "cells of $2 differ from $1"
import json, sys
def cells(path):
    d = json.load(open(path))
    out = []
    for c in d["cells"]:
        c = {k: v for k, v in c.items() if k not in ("fit_s", "predict_s")}
        out.append(json.dumps(c, sort_keys=True))
    return out
a, b = cells(sys.argv[1]), cells(sys.argv[2])
assert len(a) == len(b), (len(a), len(b))
assert len(set(b)) == len(b), "a cell is stored twice"
assert a == b, "cells differ"
EOF
}

GRID="--set truth --train-runs room1_0000,ch5_0000,ch5_0002 --test-runs room1_0002,ch5_0001
  --groups F,R,L --orders 2,8 --covs nodal-diag,nodal-full --floors 0.01,0.1
  --decisions step,online --max-iter 60"
# Long jobs for the lease test (no convergence: every fit runs all its iterations).
SLOW="--set truth --train-runs room1_0000,ch5_0000 --test-runs room1_0002
  --groups F,R --orders 16 --covs nodal-full --floors 0.01,0.03 --max-iter 6000 --tol 0"

databases="local.db"
if [ -n "${TACTILE_TEST_PG_FILE:-}" ] && [ -f "$TACTILE_TEST_PG_FILE" ]; then
  server=$(sed -n 1p "$TACTILE_TEST_PG_FILE")
  schema="sw$$"
  psql -q -v ON_ERROR_STOP=1 "$server" -c "CREATE SCHEMA $schema" > /dev/null
  databases="$databases $server&options=-csearch_path%3D$schema"
fi

n=0
for db in $databases; do
  n=$((n + 1))
  "$T" import --db "$db" b1 b2 > /dev/null
  "$T" autolabel --db "$db" --all --set truth > /dev/null
  # shellcheck disable=SC2086
  "$T" sweep --db "$db" $GRID --threads 2 --out ref$n.json > /dev/null || fail "one-process sweep"
  cells=$(json 'len(d["cells"])' < ref$n.json)
  [ "$cells" -eq 48 ] || fail "reference sweep: $cells cells"

  for workers in 1 2 4; do
    # shellcheck disable=SC2086
    "$T" sweep plan --db "$db" $GRID --name "w$workers" --json > plan.json || fail "plan exited $?"
    [ "$(json 'd["cells"]' < plan.json)" -eq 48 ] || fail "plan: $(cat plan.json)"
    id=$(json 'd["sweep"]' < plan.json)
    "$T" sweep status --db "$db" --sweep "$id" --json > status.json
    [ "$(json 'd["pending"], d["done"], d["state"]' < status.json)" = "48 0 planned" ] ||
      fail "status of a planned sweep: $(cat status.json)"
    pids=""
    i=0
    while [ $i -lt $workers ]; do
      "$T" sweep work --db "$db" --sweep "$id" --worker "w$i" --json > work$i.json &
      pids="$pids $!"
      i=$((i + 1))
    done
    for p in $pids; do wait "$p" || fail "a worker of $workers exited $?"; done
    stored=$(cat work*.json | python3 -c "import sys,json; print(sum(json.loads(l)['cells'] for l in sys.stdin))")
    [ "$stored" -eq 48 ] || fail "$workers workers stored $stored cells"
    rm -f work*.json
    "$T" sweep status --db "$db" --sweep "$id" --json > status.json
    [ "$(json 'd["done"], d["pending"], d["running"], d["failed"], d["state"]' < status.json)" = "48 0 0 0 finished" ] ||
      fail "status after $workers workers: $(cat status.json)"
    "$T" sweeps export --db "$db" --sweep "$id" --out w$workers.json || fail "export exited $?"
    same_cells ref$n.json w$workers.json
  done

  # A worker killed mid-job: its claim stays running until the lease runs out, then another
  # worker takes it over; every cell is stored once.
  # shellcheck disable=SC2086
  "$T" sweep --db "$db" $SLOW --out slowref.json > /dev/null || fail "slow reference sweep"
  # shellcheck disable=SC2086
  id=$("$T" sweep plan --db "$db" $SLOW --name slow --json | json 'd["sweep"]')
  "$T" sweep work --db "$db" --sweep "$id" --worker doomed --lease 2 > /dev/null 2>&1 &
  doomed=$!
  tries=0
  until "$T" sweep status --db "$db" --sweep "$id" --json | json 'd["running"]' | grep -q '^[1-9]'; do
    tries=$((tries + 1))
    [ $tries -lt 400 ] || fail "the worker never claimed a job"
    sleep 0.02
  done
  kill -9 "$doomed"
  wait "$doomed" 2> /dev/null || true
  "$T" sweep status --db "$db" --sweep "$id" --json > killed.json
  [ "$(json 'd["running_jobs"][0]["worker"]' < killed.json)" = doomed ] ||
    fail "status after the kill: $(cat killed.json)"
  "$T" sweep status --db "$db" --sweep "$id" | grep -q "doomed, lease" || fail "status text"
  "$T" sweep work --db "$db" --sweep "$id" --worker rescuer --lease 2 --json > rescue.json ||
    fail "rescuer exited $?"
  "$T" sweep status --db "$db" --sweep "$id" --json > status.json
  [ "$(json 'd["done"], d["running"], d["failed"]' < status.json)" = "4 0 0" ] ||
    fail "status after the rescue: $(cat status.json)"
  "$T" sweeps export --db "$db" --sweep "$id" --out slow.json
  same_cells slowref.json slow.json
done
echo "ok: sweep jobs on $n databases"
