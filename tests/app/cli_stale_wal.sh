#!/bin/sh
# A write-ahead log left beside a database it does not belong to is never applied
# (docs/storage.md#a-leftover-write-ahead-log):
#  1. a log left by a killed reader holds a commit; a backup taken one commit earlier is restored
#     over the database: every verb, reading or writing, refuses it naming the log, and the file
#     and the log keep their SHA-256;
#  2. with the log moved away, as the message says, the backup opens as it was;
#  3. the same log beside the very file it was written on is recovered (a crash loses nothing);
#  4. a backup identical to the state the log started from cannot be told from that file: the log
#     is applied and the result is whole (db check passes);
#  5. output files: --out to a FIFO streams, --out equal to an input is refused, a 0600 file
#     keeps its mode, a database cut short is refused.
#   tests/app/cli_stale_wal.sh TACTILE WORKDIR
. "$(dirname "$0")/cli_test_lib.sh"

"$T" simulate --scene room1 --driver wall-follow --steps 120 --runs 4 --out-dir runs --quiet > /dev/null

# Runs `import` of $2 into $1 while another process holds a read transaction, then kills that
# process with SIGKILL, so the import's commit stays in $1-wal.
import_under_reader() {
  rm -f hold.fifo
  mkfifo hold.fifo
  sqlite3 "$1" < hold.fifo > /dev/null 2>&1 &
  holder=$!
  exec 3> hold.fifo
  echo "BEGIN; SELECT count(*) FROM runs;" >&3
  sleep 1
  "$T" import --db "$1" "$2" > /dev/null
  kill -9 "$holder"
  wait "$holder" 2> /dev/null || true
  exec 3>&-
  [ -s "$1-wal" ] || fail "the log of $1 holds nothing: the reader did not hold it"
}

sums() {
  sha256sum "$@" | awk '{print $1}' | tr '\n' ' '
}

# Runs a verb that must be refused because of the log: exit 1, the log named, nothing changed.
expect_refused() {
  label=$1
  shift
  before=$(sums X.db X.db-wal)
  set +e
  "$@" > refused.out 2> refused.err
  rc=$?
  set -e
  [ "$rc" -eq 1 ] || fail "$label exited $rc: $(cat refused.err)"
  grep -q "X.db-wal does not belong to this database" refused.err ||
    fail "$label: stderr '$(cat refused.err)'"
  [ "$(sums X.db X.db-wal)" = "$before" ] || fail "$label changed the database or its log"
}

# ---- 1. a backup restored beside a newer log ----------------------------------------------------
"$T" import --db X.db runs/run_0000.csv > /dev/null
cp X.db backup.db
"$T" import --db X.db runs/run_0001.csv > /dev/null
import_under_reader X.db runs/run_0002.csv
cp X.db-wal crashed.db-wal
cp X.db crashed.db
cp backup.db X.db
expect_refused "runs list" "$T" runs list --db X.db
expect_refused "db check" "$T" db check --db X.db
expect_refused "import" "$T" import --db X.db runs/run_0003.csv
expect_refused "runs rename" "$T" runs rename --db X.db run_0000 renamed
expect_refused "autolabel" "$T" autolabel --db X.db --set truth --all
expect_refused "db create" "$T" db create --db X.db
expect_refused "export-run" "$T" export-run --db X.db --run run_0000 --out out.csv
[ ! -e out.csv ] || fail "export-run wrote from a refused database"

# ---- 2. the log moved away: the backup as it was -----------------------------------------------
mkdir aside
mv X.db-wal aside/
rm -f X.db-shm
"$T" runs list --db X.db --json > list.json
grep -q '"run_0000"' list.json || fail "the restored backup lost its run: $(cat list.json)"
grep -q '"run_0001"' list.json && fail "the restored backup shows a later run: $(cat list.json)"
"$T" db check --db X.db > /dev/null || fail "the restored backup is not whole"

# ---- 3. the log beside its own file: recovered -------------------------------------------------
"$T" runs list --db crashed.db --json > crashed.json
for r in run_0000 run_0001 run_0002; do
  grep -q "\"$r\"" crashed.json || fail "recovery lost $r: $(cat crashed.json)"
done
"$T" db check --db crashed.db > /dev/null || fail "the recovered database is not whole"

# ---- 4. a backup identical to the log's starting state ----------------------------------------
"$T" import --db Y.db runs/run_0000.csv > /dev/null
cp Y.db ybackup.db
import_under_reader Y.db runs/run_0001.csv
cp ybackup.db Y.db
"$T" db check --db Y.db > /dev/null || fail "applying the log to an identical backup damaged it"
"$T" runs list --db Y.db --json | grep -q '"run_0001"' || fail "the log's commit was lost"

# ---- 5. output files -----------------------------------------------------------------------------
"$T" export-run --db crashed.db --run run_0000 --out run0.csv > /dev/null
mkfifo out.fifo
cat out.fifo > streamed.csv &
reader=$!
"$T" export-run --db crashed.db --run run_0000 --out out.fifo > /dev/null
wait "$reader"
[ -p out.fifo ] || fail "--out replaced the FIFO"
cmp -s streamed.csv run0.csv || fail "the FIFO did not receive the run"

set +e
"$T" export-run --db crashed.db --run run_0000 --out crashed.db > same.out 2> same.err
rc=$?
set -e
[ "$rc" -eq 1 ] || fail "--out equal to --db exited $rc"
grep -q "input" same.err || fail "--out equal to --db: '$(cat same.err)'"
"$T" runs list --db crashed.db > /dev/null || fail "--out destroyed the database"

cp run0.csv private.csv
chmod 600 private.csv
"$T" export-run --db crashed.db --run run_0001 --out private.csv > /dev/null
[ "$(stat -c %a private.csv)" = 600 ] || fail "a 0600 output became $(stat -c %a private.csv)"
ls ./*.tmp-* > /dev/null 2>&1 && fail "temporary files left: $(ls ./*.tmp-*)"

"$T" export-run --db crashed.db --run run_0000 --out /dev/stdout > stdout.csv
cmp -s stdout.csv run0.csv || fail "--out /dev/stdout did not stream the run"
[ -L /dev/stdout ] || [ -c /dev/stdout ] || fail "/dev/stdout was replaced"

# A file-size limit: the write fails, the old file stays, no temporary file is left.
cp run0.csv limited.csv
set +e
(ulimit -f 100 && "$T" simulate --scene room1 --driver wall-follow --steps 3000 --out limited.csv \
  --quiet) > /dev/null 2> limit.err
rc=$?
set -e
[ "$rc" -eq 1 ] || fail "a write past ulimit -f exited $rc: $(cat limit.err)"
cmp -s limited.csv run0.csv || fail "a failed write changed the old file"
ls ./*.tmp-* > /dev/null 2>&1 && fail "temporary files left after ulimit -f: $(ls ./*.tmp-*)"

# Reading verbs leave no -wal or -shm behind.
for verb in "runs list" "db check" "labels list"; do
  # shellcheck disable=SC2086
  "$T" $verb --db crashed.db > /dev/null
  [ ! -e crashed.db-wal ] && [ ! -e crashed.db-shm ] || fail "$verb left -wal or -shm behind"
done

cp crashed.db cut.db
"$T" db check --db cut.db > /dev/null
truncate -s -5000 cut.db
set +e
"$T" db check --db cut.db > cut.out 2> cut.err
rc=$?
set -e
[ "$rc" -eq 1 ] || fail "db check of a database cut short exited $rc"
grep -q "cut short" cut.err || fail "db check of a database cut short: '$(cat cut.err)'"

echo "ok: stale wal"
