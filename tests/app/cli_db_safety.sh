#!/bin/sh
# Database safety through the CLI (docs/storage.md#opening, #errors, #check, #concurrency):
#  1. only creating verbs make a database; any other verb on a missing path fails with
#     "tactile: error: DB: no such database" and creates nothing;
#  2. read-only verbs work on a read-only database in a read-only folder (as an unprivileged user);
#  3. a file that is not a Tactile database is refused and left byte for byte unchanged, with no
#     -wal/-shm beside it; an empty file only becomes a database through a creating verb;
#  4. SQLite errors name the database file;
#  6. db check summarises (count, first 10 cases, "and N more"; --json keeps every count);
#  5. eight processes importing into one new database at once, five rounds: all succeed, every run
#     stored once, the rest reported as skipped.
#   tests/app/cli_db_safety.sh TACTILE WORKDIR
. "$(dirname "$0")/cli_test_lib.sh"
# No journal or shared-memory files beside $1.
no_companions() {
  for s in -wal -shm -journal; do
    [ ! -e "$1$s" ] || fail "$1$s was left behind"
  done
}

"$T" simulate --scene room1 --driver wall-follow --steps 200 --runs 6 --out-dir runs --quiet > /dev/null

# ---- 1. missing database: only creating verbs create -------------------------------------------
expect_missing() {
  # $1: label; the command follows.
  label=$1
  shift
  set +e
  "$@" > missing.out 2> missing.err
  rc=$?
  set -e
  [ "$rc" -eq 1 ] || fail "$label on a missing database exited $rc: $(cat missing.err)"
  [ "$(cat missing.err)" = "tactile: error: nodb/x.db: no such database" ] ||
    fail "$label: stderr '$(cat missing.err)'"
  [ -z "$(ls -A nodb)" ] || fail "$label created files: $(ls -A nodb)"
}
mkdir nodb
expect_missing "db check" "$T" db check --db nodb/x.db
expect_missing "db check --json" "$T" db check --db nodb/x.db --json
expect_missing "export-run" "$T" export-run --db nodb/x.db --run run_0000 --out out.csv
[ ! -e out.csv ] || fail "export-run wrote its output for a missing database"
expect_missing "runs list" "$T" runs list --db nodb/x.db
expect_missing "labels list" "$T" labels list --db nodb/x.db
expect_missing "labels export" "$T" labels export --db nodb/x.db --set s labels.csv
expect_missing "models list" "$T" models list --db nodb/x.db
expect_missing "sweeps list" "$T" sweeps list --db nodb/x.db

"$T" db create --db nodb/new.db > create.out || fail "db create exited $?"
grep -q "created nodb/new.db (schema version" create.out || fail "db create: $(cat create.out)"
"$T" db check --db nodb/new.db > check.out || fail "db check of a created database failed"
grep -q "ok, schema version" check.out || fail "check of new: $(cat check.out)"
"$T" db create --db nodb/new.db > create2.out || fail "db create of an existing database failed"
grep -q "already a Tactile database" create2.out || fail "db create again: $(cat create2.out)"

"$T" import --db c.db runs > import.out || fail "import exited $?"
grep -q "6 imported, 0 skipped, 0 failed" import.out || fail "import: $(cat import.out)"

# ---- 3. files that are not Tactile databases are refused unchanged ------------------------------
refused() {
  # $1: file; the command follows. Exit 1, an error naming the file, the bytes unchanged.
  file=$1
  shift
  cp "$file" "$file.orig"
  set +e
  "$@" > refused.out 2> refused.err
  rc=$?
  set -e
  [ "$rc" -eq 1 ] || fail "$* on $file exited $rc"
  grep -q "^tactile: error: $file: .*not a Tactile database" refused.err ||
    fail "$* on $file: $(cat refused.err)"
  cmp -s "$file" "$file.orig" || fail "$* changed $file"
  no_companions "$file"
  rm -f "$file.orig"
}
sqlite3 foreign.db "CREATE TABLE notes(id INTEGER PRIMARY KEY, text TEXT); INSERT INTO notes(text) VALUES('keep me');"
sqlite3 foreign-wal.db "PRAGMA journal_mode = WAL; CREATE TABLE t(x); INSERT INTO t VALUES(1);" > /dev/null
sqlite3 other-app.db "PRAGMA application_id = 1234; PRAGMA user_version = 7;"
printf 'step,x,y\n0,1,2\n' > text.db
for f in foreign.db foreign-wal.db other-app.db text.db; do
  refused "$f" "$T" import --db "$f" runs
  refused "$f" "$T" db check --db "$f"
  refused "$f" "$T" db create --db "$f"
  refused "$f" "$T" export-run --db "$f" --run run_0000 --out out.csv
done
# A user_version without the Tactile application id is another program's file, whatever the verb:
# one line on stderr, the bytes unchanged, no backup and no WAL switch.
sqlite3 versioned.db "PRAGMA user_version = 2; CREATE TABLE notes(x); INSERT INTO notes VALUES('keep');"
sqlite3 versioned-bare.db "PRAGMA user_version = 4;"
for f in versioned.db versioned-bare.db; do
  sum=$(sha256sum < "$f")
  for verb in "import --db $f runs" "db check --db $f" "db create --db $f" \
              "runs rename --db $f a b" "runs delete --db $f a" "runs list --db $f" \
              "labels list --db $f" "autolabel --db $f --all --set s" \
              "export-run --db $f --run a --out out.csv"; do
    # shellcheck disable=SC2086
    refused "$f" "$T" $verb
    [ "$(wc -l < refused.err)" -eq 1 ] || fail "$verb on $f: not one line: $(cat refused.err)"
    [ "$(sha256sum < "$f")" = "$sum" ] || fail "$verb changed $f"
  done
  ! ls "$f".*bak > /dev/null 2>&1 || fail "a backup of $f was made"
done
# An empty file: refused unless a creating verb is given it.
: > empty.db
refused empty.db "$T" db check --db empty.db
refused empty.db "$T" export-run --db empty.db --run run_0000 --out out.csv
[ ! -s empty.db ] || fail "empty.db grew"
"$T" db create --db empty.db > /dev/null || fail "db create on an empty file failed"
"$T" db check --db empty.db > /dev/null || fail "empty file made into a database is not ok"

# ---- 4. SQLite errors name the database ---------------------------------------------------------
cp c.db broken.db
sqlite3 broken.db "DROP TABLE step_blocks; DROP VIEW step_truth; DROP TABLE steps;"
set +e
"$T" export-run --db broken.db --run run_0000 --out broken.csv 2> broken.err
rc=$?
set -e
[ "$rc" -eq 1 ] || fail "export-run from a database without steps exited $rc"
grep -q "^tactile: error: broken.db: .*no such table: steps" broken.err ||
  fail "SQLite error without the database: $(cat broken.err)"
! grep -q "broken.db: broken.db" broken.err || fail "database named twice: $(cat broken.err)"
set +e
"$T" export-run --db c.db --run no_such_run --out broken.csv 2> broken.err
set -e
[ "$(cat broken.err)" = "tactile: error: c.db: no run named 'no_such_run'" ] ||
  fail "unknown run: $(cat broken.err)"

# ---- 6. db check summarises --------------------------------------------------------------------
cp c.db orphan.db
sqlite3 orphan.db "DELETE FROM runs WHERE name = 'run_0000';"  # foreign keys off: orphaned rows
set +e
"$T" db check --db orphan.db > check.out 2> check.err
rc=$?
set -e
[ "$rc" -eq 1 ] || fail "db check of a damaged database exited $rc"
grep -q "DAMAGED" check.out || fail "check: $(cat check.out)"
grep -q "^tactile: error: orphan.db: 200 problems of kind 'foreign key steps -> runs'" check.err ||
  fail "no count per kind: $(head -3 check.err)"
grep -q "^tactile: error: orphan.db:   and 190 more" check.err || fail "no 'and N more'"
[ "$(grep -c 'refers to a missing runs row' check.err)" -le 20 ] ||
  fail "db check printed every case ($(grep -c refers check.err) lines)"
[ "$(wc -l < check.err)" -le 40 ] || fail "db check printed $(wc -l < check.err) lines"
set +e
"$T" db check --db orphan.db --json > check.json
set -e
python3 - check.json << 'EOF' || fail "db check --json: $(cat check.json)"
import json, sys
doc = json.load(open(sys.argv[1]))
kinds = {k["kind"]: k for k in doc["problem_kinds"]}
steps = kinds["foreign key steps -> runs"]
assert steps["count"] == 200 and len(steps["cases"]) == 10 and steps["more"] == 190, steps
assert "step count" in kinds and not doc["ok"], doc
EOF

# ---- 2. read-only database in a read-only folder, as an unprivileged user ----------------------
# Root ignores file modes, so as root the read-only verbs run as user nobody (65534).
if [ "$(id -u)" -ne 0 ]; then
  DROP=self
elif command -v setpriv > /dev/null 2>&1; then
  DROP=setpriv
elif command -v su > /dev/null 2>&1; then
  DROP=su
else
  DROP=none
fi
nobody() {
  case $DROP in
    self) "$@" ;;
    setpriv) setpriv --reuid=65534 --regid=65534 --clear-groups "$@" ;;
    *)
      cmd=""
      for a in "$@"; do cmd="$cmd '$a'"; done
      su nobody -s /bin/sh -c "$cmd"
      ;;
  esac
}
if [ "$DROP" = none ]; then
  echo "note: neither setpriv nor su: the read-only case was not run"
else
  # The unprivileged user needs a path it may walk from / (the work folder may sit inside a
  # private 0700 folder, as under mktemp): the read-only case runs in a folder of its own under
  # /tmp with the program, the runs and the database copied in, removed on exit.
  RO=$(mktemp -d "${TMPDIR:-/tmp}/tactile-ro.XXXXXX")
  trap 'chmod -R u+w "$RO" 2> /dev/null; rm -rf "$RO"' EXIT
  chmod 755 "$RO"
  cp "$T" "$RO/tactile"
  cp -r runs "$RO/runs"
  chmod -R a+rX "$RO/runs"
  cp c.db r-source.db
  cd "$RO"
  T_MAIN=$T
  T="$RO/tactile"
  mkdir ro out
  cp "$W/r-source.db" ro/r.db
  "$T" autolabel --db ro/r.db --all --set truth > /dev/null || fail "autolabel exited $?"
  cp ro/r.db r-before.db
  no_companions ro/r.db
  chmod 444 ro/r.db
  chmod 555 ro
  chmod 777 out
  # The unprivileged user must reach the folder and the program; otherwise the check is void.
  nobody test -r ro/r.db || fail "nobody cannot read ro/r.db (check the folder permissions)"
  ! nobody sh -c ": > ro/probe" 2> /dev/null || fail "ro/ is writable by nobody"
  nobody "$T" db check --db ro/r.db > ro.out 2> ro.err || fail "read-only db check: $(cat ro.err)"
  grep -q "ro/r.db: ok, schema version" ro.out || fail "read-only check: $(cat ro.out)"
  nobody "$T" db check --db ro/r.db --json > ro.json 2> ro.err || fail "read-only check --json"
  grep -q '"ok":true' ro.json || fail "read-only check json: $(cat ro.json)"
  nobody "$T" export-run --db ro/r.db --run run_0003 --out out/run_0003.csv 2> ro.err ||
    fail "read-only export-run: $(cat ro.err)"
  cmp -s out/run_0003.csv runs/run_0003.csv || fail "read-only export differs from the file"
  nobody "$T" runs list --db ro/r.db > ro-list.out 2> ro.err || fail "read-only runs list: $(cat ro.err)"
  grep -q run_0005 ro-list.out || fail "read-only runs list: $(cat ro-list.out)"
  nobody "$T" labels export --db ro/r.db --set truth out/truth.csv > /dev/null 2> ro.err ||
    fail "read-only labels export: $(cat ro.err)"
  [ "$(grep -c '^# run ' out/truth.csv)" -eq 6 ] || fail "read-only labels export: $(head -3 out/truth.csv)"
  nobody "$T" labels list --db ro/r.db > /dev/null 2> ro.err || fail "read-only labels list: $(cat ro.err)"
  cmp -s ro/r.db r-before.db || fail "read-only verbs changed the database"
  no_companions ro/r.db
  # A writing verb is refused (the file and folder are read-only), naming the database.
  set +e
  nobody "$T" import --db ro/r.db runs > /dev/null 2> ro.err
  rc=$?
  set -e
  [ "$rc" -eq 1 ] || fail "import into a read-only database exited $rc"
  grep -q "^tactile: error: ro/r.db: " ro.err || fail "read-only import error: $(cat ro.err)"
  chmod 755 ro
  chmod 644 ro/r.db
  T=$T_MAIN
  cd "$W"
fi

# ---- 5. eight importers at once into one new database, five rounds -----------------------------
files=$(ls runs | wc -l)
round=1
while [ "$round" -le 5 ]; do
  db="cc$round.db"
  pids=""
  i=1
  while [ "$i" -le 8 ]; do
    "$T" import --db "$db" runs --threads 1 --json > "imp$round.$i.json" 2> "imp$round.$i.err" &
    pids="$pids $!"
    i=$((i + 1))
  done
  i=1
  for pid in $pids; do
    wait "$pid" || fail "round $round importer $i exited $?: $(cat "imp$round.$i.err")"
    i=$((i + 1))
  done
  python3 - "$files" imp$round.*.json << 'EOF' || fail "round $round: $(cat imp$round.*.err)"
import json, sys
files = int(sys.argv[1])
imported = {}
for name in sys.argv[2:]:
    doc = json.load(open(name))
    assert not doc["failed"], (name, doc["failed"])
    assert len(doc["runs"]) + len(doc["skipped"]) == files, (name, doc)
    for r in doc["runs"]:
        assert r["name"] not in imported, ("stored twice", r["name"])
        imported[r["name"]] = name
    for s in doc["skipped"]:
        assert "already imported" in s["message"], s
assert len(imported) == files, imported
EOF
  if grep -l "UNIQUE\|already exists" imp$round.*.err > /dev/null 2>&1; then
    fail "round $round: $(cat imp$round.*.err)"
  fi
  "$T" db check --db "$db" > "check$round.out" || fail "round $round check: $(cat "check$round.out")"
  grep -q "ok, schema version 7, $files runs, $((files * 200)) steps" "check$round.out" ||
    fail "round $round: $(cat "check$round.out")"
  round=$((round + 1))
done

echo "ok: database safety"
