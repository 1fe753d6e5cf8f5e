#!/bin/sh
# Sweep workers side by side (docs/cluster.md): on one database, a sweep of 240 fits is planned
# and filled by 1 worker process of one thread, then by 2 such processes at once, REPEAT times
# alternately. Each worker reports the time it spent claiming jobs and storing their cells
# (`sweep work --json`: claim_store_s); divided by its jobs, that is what claiming and storing one
# job (here one cell) costs. Prints one JSON line:
# {"db","fits","one_s":[...],"two_s":[...],"median_one_s","median_two_s","speedup",
#  "claim_store_ms":[...],"median_claim_store_ms"}.
#   bench/team/sweep_workers.sh TACTILE DB WORKDIR [REPEAT]
# DB is a file or a PostgreSQL address (an empty database: the script imports its runs).
set -eu
T=$1 DB=$2 W=$3
REPEAT=${4:-3}
mkdir -p "$W"
cd "$W"
# 40 runs of the training recipe (about 77,000 steps): 30 to train on, 10 to test on.
if [ ! -d runs ]; then
  "$T" simulate --plan training --runs 40 --out-dir runs --quiet > /dev/null
fi
"$T" import --db "$DB" runs > /dev/null
"$T" autolabel --db "$DB" --all --set truth > /dev/null
names() { ls runs/*.csv | sed 's|runs/||; s|\.csv$||' | "$@" | paste -sd, -; }
DATA="--set truth --train-runs $(names head -n 30) --test-runs $(names tail -n 10)"
# 4 groups x 5 orders x 2 forms x 3 floors x 2 seeds = 240 fits of normal+shear features (one
# worker takes about 20 s on the machine of docs/BENCHMARKS.md; the longest fit 0.6 s).
GRID="--groups F,R,L,B --orders 2,4,8,16,32 --covs nodal-diag,nodal-full --floors 0.01,0.03,0.1
  --seeds 1,2 --features normal+shear"

plan() {
  # shellcheck disable=SC2086
  "$T" sweep plan --db "$DB" $DATA "$@" --json |
    python3 -c "import json,sys; print(json.load(sys.stdin)['sweep'])"
}
now() { date +%s.%N; }
# Milliseconds of claiming and storing per job in a worker's --json summary.
perJob() {
  python3 -c "
import json, sys
d = json.load(open(sys.argv[1]))
print(1000 * d['claim_store_s'] / max(d['jobs'], 1))" "$1"
}

one="" two="" store=""
r=0
while [ "$r" -lt "$REPEAT" ]; do
  # shellcheck disable=SC2086
  id=$(plan $GRID)
  start=$(now)
  "$T" sweep work --db "$DB" --sweep "$id" --threads 1 --json > w0.json
  one="$one $(echo "$(now) - $start" | bc)"
  store="$store $(perJob w0.json)"
  # shellcheck disable=SC2086
  id=$(plan $GRID)
  start=$(now)
  "$T" sweep work --db "$DB" --sweep "$id" --threads 1 --json > w1.json &
  a=$!
  "$T" sweep work --db "$DB" --sweep "$id" --threads 1 --json > w2.json &
  b=$!
  wait $a
  wait $b
  two="$two $(echo "$(now) - $start" | bc)"
  store="$store $(perJob w1.json) $(perJob w2.json)"
  r=$((r + 1))
done
python3 - "$DB" "$one" "$two" "$store" << 'EOF'
import json, statistics, sys, re
db = re.sub(r"password=[^&\s]*", "password=***", sys.argv[1])
one = [float(x) for x in sys.argv[2].split()]
two = [float(x) for x in sys.argv[3].split()]
store = [round(float(x), 3) for x in sys.argv[4].split()]
print(json.dumps({"db": db, "fits": 240, "one_s": one, "two_s": two,
                  "median_one_s": statistics.median(one), "median_two_s": statistics.median(two),
                  "speedup": statistics.median(one) / statistics.median(two),
                  "claim_store_ms": store, "median_claim_store_ms": statistics.median(store)}))
EOF
