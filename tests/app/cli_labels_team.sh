#!/bin/sh
# Label edits of a team from the command line, on an SQLite file and on the test server:
#  1. `labels set` makes one edit and says its revision; `labels history --json` shows who, when,
#     which steps and what they held;
#  2. an edit based on an older revision over steps someone changed since is refused (exit 1,
#     naming who changed them), stores nothing, and one over other steps stands;
#  3. assignments move from todo to reviewed and list per annotator;
#  4. `labels agreement` of two annotators' sets per group;
#  5. several annotator processes editing at once lose no edit (bench/team/annotators.sh);
#  6. roles on the server: each right allows what it says, and a refusal names the missing right.
#   tests/app/cli_labels_team.sh TACTILE WORKDIR SOURCE_DIR   (TACTILE_TEST_PG_FILE: the server)
. "$(dirname "$0")/cli_test_lib.sh"
SRC=$3

[ -n "${TACTILE_TEST_PG_FILE:-}" ] && [ -f "$TACTILE_TEST_PG_FILE" ] ||
  fail "no test server (TACTILE_TEST_PG_FILE)"
server=$(sed -n 1p "$TACTILE_TEST_PG_FILE")
schema="lt$$"
psql -q -v ON_ERROR_STOP=1 "$server" -c "CREATE SCHEMA $schema" > /dev/null

"$T" simulate --scene room1 --driver wall-follow --steps 800 --runs 2 --out-dir runs --quiet > /dev/null

json() { /usr/bin/python3 -c "import json,sys; d=json.load(sys.stdin); print($1)"; }

for db in local.db "$server&options=-csearch_path%3D$schema"; do
  "$T" import --db "$db" runs > /dev/null
  # 1.
  "$T" labels set --db "$db" --set team --run run_0000 --groups F,L --steps 10-40 --class Wall \
    --annotator anna > set.out || fail "labels set: $(cat set.out)"
  grep -q "^labelled steps 10-40 of run 'run_0000' as Wall in 'team': revision [0-9]" set.out ||
    fail "labels set said: $(cat set.out)"
  rev=$("$T" labels history --db "$db" --set team --run run_0000 --json | json 'd["revision"]')
  "$T" labels history --db "$db" --set team --run run_0000 --json > history.json
  [ "$(json 'len(d["revisions"])' < history.json)" = 2 ] || fail "history: $(cat history.json)"
  [ "$(json 'd["revisions"][0]["annotator"], d["revisions"][0]["group"], d["revisions"][1]["group"], d["revisions"][0]["class"]' < history.json)" = "anna F L Wall" ] ||
    fail "history entries: $(cat history.json)"
  # 2. Ben edits on top of anna (based on her revision); then anna, still at her old revision,
  # edits over Ben's steps: refused; over others: stands.
  "$T" labels set --db "$db" --set team --run run_0000 --groups F --steps 30-60 --class Corner \
    --annotator ben --expect-revision "$rev" --json > ben.json || fail "ben's edit was refused"
  benrev=$(json 'd["revision"]' < ben.json)
  [ "$benrev" -gt "$rev" ] || fail "ben's revision $benrev after $rev"
  if "$T" labels set --db "$db" --set team --run run_0000 --groups F --steps 50-55 --class Wall \
    --annotator anna --expect-revision "$rev" 2> err.txt; then
    fail "an edit over changed steps was stored"
  fi
  grep -q "not stored: steps 50-55 of F in run 'run_0000' were changed by ben at .* (revision $benrev)" err.txt ||
    fail "conflict message: $(cat err.txt)"
  [ "$("$T" labels history --db "$db" --set team --run run_0000 --json | json 'd["revision"]')" = "$benrev" ] ||
    fail "the refused edit left a revision"
  "$T" labels set --db "$db" --set team --run run_0000 --groups F --steps 100-110 --class Wall \
    --annotator anna --expect-revision "$rev" > /dev/null || fail "an edit over other steps was refused"
  if "$T" labels set --db "$db" --set team --run run_0000 --groups X --steps 1-2 --class Wall 2> err.txt; then
    fail "unknown group taken"
  else
    [ $? -eq 2 ] || fail "unknown group: exit $?"
  fi
  grep -q "unknown group 'X'" err.txt || fail "unknown group: $(cat err.txt)"
  # 3.
  "$T" labels assign --db "$db" --runs run_0000,run_0001 --to carl --set team > /dev/null
  "$T" labels assign --db "$db" --runs run_0001 --to carl --state reviewed > /dev/null
  "$T" labels assign --db "$db" --runs run_0000 --group L --to dora > /dev/null
  "$T" labels assignments --db "$db" --annotator carl --json > assigned.json
  [ "$(json '[(a["run"], a["state"], a["set"]) for a in d["assignments"]]' < assigned.json)" = \
    "[('run_0000', 'todo', 'team'), ('run_0001', 'reviewed', 'team')]" ] ||
    fail "assignments: $(cat assigned.json)"
  if "$T" labels assign --db "$db" --runs nope --to carl 2> err.txt; then fail "unknown run assigned"; fi
  # 4. Two annotators' sets: ben agrees with anna on F, not on L.
  "$T" labels set --db "$db" --set ben --run run_0000 --groups F --steps 10-40 --class Wall --annotator ben > /dev/null
  "$T" labels set --db "$db" --set ben --run run_0000 --groups L --steps 10-40 --class Corner --annotator ben > /dev/null
  "$T" labels set --db "$db" --set anna --run run_0000 --groups F,L --steps 10-40 --class Wall --annotator anna > /dev/null
  "$T" labels agreement --db "$db" --sets anna,ben --json > agree.json
  [ "$(json '[(g["group"], g["compared_steps"], g["percent"]) for g in d["groups"] if g["compared_steps"]]' < agree.json)" = \
    "[('F', 31, 100.0), ('L', 31, 0.0)]" ] || fail "agreement: $(cat agree.json)"
  # 5.
  THINK=0.02 sh "$SRC/bench/team/annotators.sh" "$T" "$db" 4 12 crowd > crowd.json ||
    fail "annotators lost edits: $(cat crowd.json)"
  [ "$(json 'd["lost"], d["failed"], d["stored"] + d["refused"]' < crowd.json)" = "0 0 48" ] ||
    fail "annotators: $(cat crowd.json)"
done
# 6. Roles on the server: an annotator edits labels but may not keep a model or delete a run, a
# researcher keeps models, an admin deletes runs; what is refused says which right is missing.
pg="$server&options=-csearch_path%3D$schema"
as_role() { echo "$pg" | sed "s/user=postgres/user=$1/"; }
for r in annotator researcher admin; do
  "$T" db grant --db "$pg" --role "${r}_$$" --as "$r" | grep -q "^${r}_$$ may now work as $r" ||
    fail "db grant $r"
done
if "$T" db grant --db local.db --role x --as admin 2> err.txt; then fail "grant on a file"; fi
grep -q "roles belong to a PostgreSQL server" err.txt || fail "grant on a file: $(cat err.txt)"
"$T" autolabel --db local.db --all --set truth > /dev/null
"$T" train --db local.db --set truth --name m1 > /dev/null 2>&1 || fail "train"
"$T" models export --db local.db m1 --out m1.json > /dev/null
# Labels from the model: marked model:m1 in the segments and the history.
"$T" labels from-model --db local.db --set auto --model m1 --runs run_0000 --json > auto.json 2> /dev/null ||
  fail "labels from-model"
[ "$(json 'd["annotator"], d["runs"]' < auto.json)" = "model:m1 1" ] || fail "from-model: $(cat auto.json)"
"$T" labels history --db local.db --set auto --run run_0000 --json > autoh.json
[ "$(json 'sorted({r["annotator"] + "/" + r["action"] for r in d["revisions"]})' < autoh.json)" = \
  "['model:m1/model']" ] || fail "from-model history: $(cat autoh.json)"
# TACTILE_DB names the database of a verb given neither --db nor files.
TACTILE_DB=local.db "$T" classify --model m1 --run run_0001 --decision step --json > env.json ||
  fail "classify with TACTILE_DB"
grep -q '"class"' env.json || fail "classify with TACTILE_DB printed: $(head -c 200 env.json)"
annotator=$(as_role "annotator_$$")
"$T" labels set --db "$annotator" --set team --run run_0001 --groups R --steps 5-9 --class Wall   > /dev/null || fail "an annotator could not edit labels"
if "$T" models import --db "$annotator" --name m1 m1.json 2> err.txt; then
  fail "an annotator stored a model"
fi
grep -q "lacks the researcher right" err.txt || fail "annotator's model: $(cat err.txt)"
[ "$(wc -l < err.txt)" = 1 ] || fail "more than one line: $(cat err.txt)"
if "$T" runs delete --db "$annotator" run_0001 2> err.txt; then fail "an annotator deleted a run"; fi
grep -q "lacks the admin right" err.txt || fail "annotator's delete: $(cat err.txt)"
"$T" runs list --db "$pg" --json | grep -q run_0001 || fail "the refused delete deleted"
"$T" models import --db "$(as_role "researcher_$$")" --name m1 m1.json > /dev/null ||
  fail "a researcher could not store a model"
if "$T" runs delete --db "$(as_role "researcher_$$")" run_0001 2> err.txt; then
  fail "a researcher deleted a run"
fi
"$T" runs delete --db "$(as_role "admin_$$")" run_0001 > /dev/null || fail "an admin could not delete"
# A role changed to annotator loses what it had.
"$T" db grant --db "$pg" --role "researcher_$$" --as annotator > /dev/null
if "$T" models delete --db "$(as_role "researcher_$$")" m1 2> err.txt; then
  fail "a demoted researcher deleted a model"
fi
psql -q "$server" -c "DROP SCHEMA $schema CASCADE" > /dev/null
for r in annotator researcher admin; do
  psql -q "$server" -c "DROP OWNED BY ${r}_$$; DROP ROLE ${r}_$$" > /dev/null
done
echo "ok"
