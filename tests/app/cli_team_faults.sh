#!/bin/sh
# The server stops at once (pg_ctl stop -m immediate) while an import streams its steps to it, on a
# server of this test's own: the import ends with one line saying the connection was lost and exit
# 1; after the restart no part of the run is stored, `db check` is ok, and the same import stores
# the run once with all its steps. An edit while the server is down is reported as not stored.
#   tests/app/cli_team_faults.sh TACTILE WORKDIR SOURCE_DIR
. "$(dirname "$0")/cli_test_lib.sh"
SRC=$3
cluster="$SRC/tests/support/pg_cluster.sh"
state="$W/pg.state"
trap 'bash "$cluster" stop "$state" > /dev/null 2>&1 || true' EXIT
bash "$cluster" start "$state" > /dev/null
db=$(sed -n 1p "$state")

"$T" db create --db "$db" > /dev/null
"$T" bench storage --steps 1000 --files 1 --big-steps 400000 --repeats 1 --no-compare --dir gen \
  --keep > /dev/null
mv gen/big.csv big.csv
"$T" simulate --scene room1 --driver wall-follow --steps 100 --runs 1 --out-dir small --quiet > /dev/null
"$T" import --db "$db" small > /dev/null

"$T" import --db "$db" big.csv > import.out 2> import.err &
writer=$!
tries=0
until psql -tA "$db" -c "SELECT count(*) FROM pg_stat_activity WHERE query LIKE 'COPY steps%'" \
  2> /dev/null | grep -q '^1$'; do
  tries=$((tries + 1))
  [ "$tries" -lt 400 ] || fail "the import never reached its steps"
  kill -0 "$writer" 2> /dev/null || fail "the import ended before the server stopped"
  sleep 0.05
done
bash "$cluster" crash "$state"
if wait "$writer"; then fail "the import said it stored a run on a stopped server"; fi
grep -q "big.csv" import.err || grep -q "big.csv" import.out || fail "the import did not name the file: $(cat import.out import.err)"
grep -qi "connection\|server" import.err import.out || fail "the import did not say the server went: $(cat import.err)"

# An edit while the server is down: refused, said so, exit 1.
if "$T" labels set --db "$db" --set team --run run_0000 --groups F --steps 1-5 --class Wall \
  2> edit.err; then
  fail "an edit was reported stored on a stopped server"
fi
grep -q "cannot connect to the server" edit.err || fail "edit while down: $(cat edit.err)"

bash "$cluster" restart "$state"
if "$T" runs list --db "$db" | grep -q '^big '; then fail "the cut import left a run"; fi
"$T" db check --db "$db" | grep -q ": ok, schema version" || fail "db check after the crash: $("$T" db check --db "$db")"
[ "$("$T" labels history --db "$db" --set team --run run_0000 --json 2> /dev/null | grep -c Wall)" = 0 ] ||
  fail "the refused edit is in the history"
"$T" import --db "$db" big.csv > /dev/null
steps=$("$T" runs list --db "$db" --json | sed 's/.*"name":"big"[^}]*"steps":\([0-9]*\).*/\1/')
[ "$steps" = 400000 ] || fail "the run after the restart holds $steps steps"
[ "$("$T" runs list --db "$db" | grep -c '^big ')" = 1 ] || fail "the run is stored twice"
"$T" db check --db "$db" | grep -q ": ok, schema version" || fail "db check at the end"
echo "ok"
