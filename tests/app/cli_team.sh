#!/bin/sh
# The team database from the command line (docs/team.md), on the private test server:
#  1. `db create` makes the schema in an empty server database, says so once, and refuses a
#     database holding another application's tables, leaving it as it was;
#  2. a file's runs and labels copied to the server and back export byte for byte as the file's
#     own, and a second copy adds nothing;
#  3. TACTILE_DB stands for --db;
#  4. a password in an address never shows: not in errors, not in --json;
#  5. an import killed (SIGKILL) while it streams its steps to the server stores nothing, and the
#     same import again stores the run once, with all its steps.
#   tests/app/cli_team.sh TACTILE WORKDIR   (TACTILE_TEST_PG_FILE names the server's state file)
. "$(dirname "$0")/cli_test_lib.sh"

[ -n "${TACTILE_TEST_PG_FILE:-}" ] && [ -f "$TACTILE_TEST_PG_FILE" ] ||
  fail "no test server (TACTILE_TEST_PG_FILE)"
server=$(sed -n 1p "$TACTILE_TEST_PG_FILE")
socket=$(sed -n 2p "$TACTILE_TEST_PG_FILE")
schema="cli$$"
psql -q -v ON_ERROR_STOP=1 "$server" -c "CREATE SCHEMA $schema; CREATE SCHEMA ${schema}_other;
  CREATE TABLE ${schema}_other.invoices(id int);" > /dev/null
db="$server&options=-csearch_path%3D$schema"
other="$server&options=-csearch_path%3D${schema}_other"

# 1.
"$T" db create --db "$db" | grep -q "^created " || fail "db create did not say it created"
"$T" db create --db "$db" | grep -q "already a Tactile database" || fail "second db create"
if "$T" db create --db "$other" 2> err.txt; then fail "a foreign database was taken"; fi
grep -q "not a Tactile database" err.txt || fail "foreign database: $(cat err.txt)"
[ "$(psql -tA "$server" -c "SELECT count(*) FROM pg_tables WHERE schemaname = '${schema}_other'")" = 1 ] ||
  fail "the foreign database was changed"

# 2.
"$T" simulate --scene room1 --driver wall-follow --steps 150 --runs 3 --out-dir runs --quiet > /dev/null
"$T" import --db local.db runs > /dev/null
"$T" autolabel --db local.db --all --set truth > /dev/null
"$T" db copy --from local.db --to "$db" > /dev/null
"$T" db copy --from "$db" --to back.db > /dev/null
for run in run_0000 run_0001 run_0002; do
  "$T" export-run --db "$db" --run "$run" --out server.csv
  "$T" export-run --db back.db --run "$run" --out back.csv
  cmp -s server.csv "runs/$run.csv" || fail "$run from the server differs from its file"
  cmp -s back.csv "runs/$run.csv" || fail "$run after the round trip differs from its file"
done
"$T" labels export --db local.db --set truth local-labels.csv > /dev/null
"$T" labels export --db back.db --set truth back-labels.csv > /dev/null
cmp -s local-labels.csv back-labels.csv || fail "labels changed on the round trip"
again=$("$T" db copy --from local.db --to "$db" --json)
echo "$again" | grep -q '"runs_copied":0' || fail "a second copy copied runs: $again"
echo "$again" | grep -q '"segments_copied":0' || fail "a second copy copied labels: $again"

# 3.
TACTILE_DB="$db" "$T" runs list | grep -q run_0002 || fail "TACTILE_DB was not used"
TACTILE_DB="$db" "$T" db check | grep -q "ok, schema version" || fail "db check on the server"

# 4.
secret="pw$$secret"
bad="postgresql://nobody:$secret@/no_such_db?host=$socket"
for verb in "runs list --db" "db check --db" "db create --db"; do
  # shellcheck disable=SC2086
  if "$T" $verb "$bad" > out.txt 2> err.txt; then fail "$verb on a missing database succeeded"; fi
  if grep -q "$secret" out.txt err.txt; then fail "$verb printed the password"; fi
  grep -q '\*\*\*' err.txt || fail "$verb: the address is not shown masked: $(cat err.txt)"
done
with_password=$(echo "$db" | sed "s#postgresql://#postgresql://postgres:$secret@#")
"$T" db create --db "$with_password" --json > out.json
if grep -q "$secret" out.json; then fail "--json printed the password"; fi

# 5.
# A 400,000-step run file (the storage benchmark's synthetic run, kept in its folder).
"$T" bench storage --steps 1000 --files 1 --big-steps 400000 --repeats 1 --no-compare --dir gen \
  --keep > /dev/null
mv gen/big.csv big.csv
"$T" import --db "$db" big.csv > /dev/null 2>&1 &
writer=$!
# Until the server is receiving its steps (COPY), then the writer dies mid-transaction.
tries=0
until psql -tA "$server" -c "SELECT count(*) FROM pg_stat_activity WHERE query LIKE 'COPY steps%'" |
  grep -q '^1$'; do
  tries=$((tries + 1))
  [ "$tries" -lt 400 ] || fail "the import never reached its steps"
  kill -0 "$writer" 2> /dev/null || fail "the import ended before it could be killed"
  sleep 0.05
done
kill -9 "$writer"
wait "$writer" 2> /dev/null || true
if "$T" runs list --db "$db" | grep -q '^big '; then fail "a killed import left a run"; fi
"$T" db check --db "$db" | grep -q "ok, schema version" || fail "db check after the kill"
"$T" import --db "$db" big.csv > /dev/null
steps=$("$T" runs list --db "$db" --json | sed 's/.*"name":"big"[^}]*"steps":\([0-9]*\).*/\1/')
[ "$steps" = 400000 ] || fail "the run after the kill holds $steps steps"
[ "$("$T" runs list --db "$db" | grep -c '^big ')" = 1 ] || fail "the run is stored twice"
echo "ok"
