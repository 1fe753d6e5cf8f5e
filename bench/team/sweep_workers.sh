#!/bin/sh
# Sweep workers side by side (docs/cluster.md): on one database, a sweep of 240 fits is planned
# and filled by 1 worker process of one thread, then by 2 such processes at once, REPEAT times
# alternately; and a sweep of 400 cheap jobs (Gaussian fits on little data) filled by one worker,
# whose time per job bounds what claiming and storing a job costs. Prints one JSON line:
# {"db","fits","one_s":[...],"two_s":[...],"median_one_s","median_two_s","speedup",
#  "cheap_jobs","claim_store_ms":[...],"median_claim_store_ms"}.
#   bench/team/sweep_workers.sh TACTILE DB WORKDIR [REPEAT]
# DB is a file or a PostgreSQL address (an empty database: the script imports its runs).
set -eu
T=$1 DB=$2 W=$3
REPEAT=${4:-3}
mkdir -p "$W"
cd "$W"
if [ ! -d b1 ]; then
  "$T" simulate --scene room1 --runs 4 --steps 1500 --out-dir b1 --prefix room1 --quiet > /dev/null
  "$T" simulate --scene chapter5 --runs 4 --steps 1500 --out-dir b2 --prefix ch5 --quiet > /dev/null
fi
"$T" import --db "$DB" b1 b2 > /dev/null
"$T" autolabel --db "$DB" --all --set truth > /dev/null
DATA="--set truth --train-runs room1_0000,room1_0001,ch5_0000,ch5_0001,ch5_0002
  --test-runs room1_0002,ch5_0003"
# 4 groups x 5 orders x 2 forms x 3 floors x 2 seeds = 240 fits.
GRID="--groups F,R,L,B --orders 1,2,4,8,16 --covs nodal-diag,nodal-full --floors 0.01,0.03,0.1
  --seeds 1,2"
# 8 groups x 50 floors = 400 cheap jobs.
CHEAP="--groups F,FLC,L,RLC,B,RRC,R,FRC --methods gaussian --floors $(seq -s, 0.01 0.01 0.5)"

plan() {
  # shellcheck disable=SC2086
  "$T" sweep plan --db "$DB" $DATA "$@" --json |
    python3 -c "import json,sys; print(json.load(sys.stdin)['sweep'])"
}
now() { date +%s.%N; }

one="" two="" cheap=""
r=0
while [ "$r" -lt "$REPEAT" ]; do
  # shellcheck disable=SC2086
  id=$(plan $GRID)
  start=$(now)
  "$T" sweep work --db "$DB" --sweep "$id" --threads 1 > /dev/null
  one="$one $(echo "$(now) - $start" | bc)"
  # shellcheck disable=SC2086
  id=$(plan $GRID)
  start=$(now)
  "$T" sweep work --db "$DB" --sweep "$id" --threads 1 > /dev/null &
  a=$!
  "$T" sweep work --db "$DB" --sweep "$id" --threads 1 > /dev/null &
  b=$!
  wait $a
  wait $b
  two="$two $(echo "$(now) - $start" | bc)"
  # shellcheck disable=SC2086
  id=$(plan $CHEAP)
  "$T" sweep work --db "$DB" --sweep "$id" --threads 1 --json > cheap.json
  cheap="$cheap $(python3 -c "
import json
d = json.load(open('cheap.json'))
print(1000 * (d['wall_s'] - d['extract_s']) / d['jobs'])")"
  r=$((r + 1))
done
python3 - "$DB" "$one" "$two" "$cheap" << 'EOF'
import json, statistics, sys, re
db = re.sub(r"password=[^&\s]*", "password=***", sys.argv[1])
one = [float(x) for x in sys.argv[2].split()]
two = [float(x) for x in sys.argv[3].split()]
cheap = [float(x) for x in sys.argv[4].split()]
print(json.dumps({"db": db, "fits": 240, "one_s": one, "two_s": two,
                  "median_one_s": statistics.median(one), "median_two_s": statistics.median(two),
                  "speedup": statistics.median(one) / statistics.median(two),
                  "cheap_jobs": 400, "claim_store_ms": cheap,
                  "median_claim_store_ms": statistics.median(cheap)}))
EOF
