#!/bin/sh
# A planned sweep filled by a Slurm job array on a single-node cluster of the test's own
# (tests/support/slurm_cluster.sh): 4 tasks, one cancelled with scancel while it holds a claim,
# then one more `tactile sweep work`: every cell stored once and equal to a one-process sweep's.
#   tests/app/cli_sweep_slurm.sh TACTILE WORKDIR SOURCE_DIR   (as root)
. "$(dirname "$0")/cli_test_lib.sh"
SOURCE=$3
command -v python3 > /dev/null || fail "python3 is needed to read the JSON output"
cluster="$W/slurm.state"
trap '"$SOURCE/tests/support/slurm_cluster.sh" stop "$cluster"' EXIT
"$SOURCE/tests/support/slurm_cluster.sh" start "$cluster" > /dev/null || fail "no Slurm cluster"
. "$(cat "$cluster")/env"

json() { python3 -c "import json,sys; d=json.load(sys.stdin); print($1)"; }

"$T" simulate --plan training --runs 6 --seed 1 --out-dir recipe --quiet > /dev/null
"$T" import --db "$W/s.db" recipe > /dev/null
"$T" autolabel --db "$W/s.db" --all --set truth > /dev/null
# 48 cells in 24 jobs on runs of the training recipe (thousands of contact rows); no tolerance and
# three restarts, so that the first jobs handed out (the most expensive) take seconds and a task
# is reliably caught holding one. Runs of a few hundred steps gave jobs of milliseconds, and
# catching a claim then depended on luck.
GRID="--set truth --train-runs run_0001,run_0002,run_0004 --test-runs run_0003
  --groups F,R,L --orders 8,16 --covs nodal-diag,nodal-full --floors 0.01,0.1
  --decisions step,online --max-iter 3000 --tol 0 --restarts 3"
# shellcheck disable=SC2086
"$T" sweep --db "$W/s.db" $GRID --threads 2 --out ref.json > /dev/null || fail "one-process sweep"
# shellcheck disable=SC2086
id=$("$T" sweep plan --db "$W/s.db" $GRID --json | json 'd["sweep"]')
"$T" sweep submit --db "$W/s.db" --sweep "$id" --workers 4 --lease 3 --json > submit.json ||
  fail "submit exited $?: $(cat submit.json)"
job=$(json 'd["job"]' < submit.json)
[ "$(json 'd["array"]' < submit.json)" = "--array=0-3" ] || fail "submit: $(cat submit.json)"
grep -q "sweep work --db" "tactile-sweep-$id.sbatch" || fail "script: $(cat "tactile-sweep-$id.sbatch")"

# Cancel a task as soon as it holds a claim (its worker is JOB_TASK@HOST).
tries=0
task=""
while [ -z "$task" ]; do
  task=$("$T" sweep status --db "$W/s.db" --sweep "$id" --json |
    json '" ".join(r["worker"] for r in d["running_jobs"])' | sed -n 's/^[0-9]*_\([0-9]*\)@.*/\1/p')
  tries=$((tries + 1))
  [ $tries -lt 300 ] || fail "no task claimed a job: $(squeue)"
done
scancel "${job}_$task"
# The other tasks finish (they wait for the cancelled task's claim and take it over, or leave it).
tries=0
while [ -n "$(squeue -h -j "$job" 2> /dev/null)" ]; do
  tries=$((tries + 1))
  [ $tries -lt 600 ] || fail "the array never finished: $(squeue)"
  sleep 0.2
done
"$T" sweep work --db "$W/s.db" --sweep "$id" --json > after.json || fail "the last worker exited $?"
"$T" sweep status --db "$W/s.db" --sweep "$id" --json > status.json
[ "$(json 'd["done"], d["pending"], d["running"], d["failed"]' < status.json)" = "48 0 0 0" ] ||
  fail "status: $(cat status.json)"
"$T" sweeps export --db "$W/s.db" --sweep "$id" --out slurm.json || fail "export exited $?"
python3 - ref.json slurm.json << 'EOF' || fail "the array's cells differ from the one-process sweep's"
import json, sys
def cells(path):
    return [json.dumps({k: v for k, v in c.items() if k not in ("fit_s", "predict_s")},
                       sort_keys=True) for c in json.load(open(path))["cells"]]
a, b = cells(sys.argv[1]), cells(sys.argv[2])
assert len(b) == 48 and len(set(b)) == 48, len(b)
assert a == b
EOF
echo "ok: sweep on a Slurm array"
