#!/bin/sh
# The catalog verbs end to end (docs/storage.md#catalog): two simulated batches with prefixes
# imported in one call, a name clash between batches without prefixes, runs list/rename/delete,
# labels list/rename/delete, label export with provenance lines, a label file refused for another
# run of the same name, and file-form train refusing an ambiguous or mismatching run file.
#   tests/app/cli_catalog.sh TACTILE WORKDIR
. "$(dirname "$0")/cli_test_lib.sh"
# Data rows of a run file (its step count).
steps() { awk 'f { n++ } /^step,/ { f = 1 } END { print n + 0 }' "$1"; }

"$T" simulate --scene room1 --driver random --steps 300 --runs 2 --out-dir room1 --prefix room1 \
  --quiet > /dev/null
"$T" simulate --scene room1 --driver random --steps 200 --runs 2 --seed 7 --out-dir ch5 \
  --prefix ch5 --quiet > /dev/null
[ -f room1/room1_0000.csv ] && [ -f ch5/ch5_0001.csv ] || fail "prefixed batch files: $(ls room1 ch5)"
if "$T" simulate --scene room1 --steps 10 --out one.csv --prefix p --quiet 2> prefix.err; then
  fail "--prefix without --out-dir accepted"
fi

# Both batches in one call.
"$T" import --db c.db room1 ch5 --json > import.json || fail "import exited $?"
for name in room1_0000 room1_0001 ch5_0000 ch5_0001; do
  grep -q "\"name\":\"$name\"" import.json || fail "run $name not imported: $(cat import.json)"
done
grep -q '"failed":\[\]' import.json || fail "import failures: $(cat import.json)"

# runs list --json: one object, each run with id, steps, scene and label sets.
"$T" runs list --db c.db --json > list.json || fail "runs list exited $?"
[ "$(wc -l < list.json)" -eq 1 ] || fail "runs list --json is not one line"
s=$(steps ch5/ch5_0000.csv)
grep -q "{\"id\":3,\"label_sets\":\[\],\"name\":\"ch5_0000\",\"scene\":\"room1\",\"steps\":$s}" \
  list.json || fail "runs list entry for ch5_0000 ($s steps): $(cat list.json)"
[ "$(grep -o '"name":' list.json | wc -l)" -eq 4 ] || fail "runs list: $(cat list.json)"
"$T" runs list --db c.db > list.txt
grep -q "^room1_0001 .* room1 " list.txt || fail "runs list table: $(cat list.txt)"

# Read-only verbs do not create a database.
if "$T" runs list --db missing.db 2> missing.err; then fail "runs list on a missing database"; fi
grep -q "missing.db: no such database" missing.err || fail "missing db: $(cat missing.err)"
[ ! -e missing.db ] || fail "runs list created missing.db"

# Rename; a taken name is refused.
"$T" runs rename --db c.db room1_0000 first --json > rename.json || fail "runs rename exited $?"
grep -q '"from":"room1_0000"' rename.json || fail "rename: $(cat rename.json)"
if "$T" runs rename --db c.db first ch5_0000 2> taken.err; then fail "rename to a taken name"; fi
grep -q "a run named 'ch5_0000' already exists" taken.err || fail "taken: $(cat taken.err)"
"$T" runs list --db c.db --json | grep -q '"name":"first"' || fail "renamed run not listed"

# Labels: autolabel, list, export with provenance lines.
"$T" autolabel --db c.db --all --set truth > /dev/null || fail "autolabel exited $?"
"$T" runs list --db c.db --json | grep -q '"label_sets":\["truth"\],"name":"first"' ||
  fail "label set not listed on the run"
"$T" labels list --db c.db --json > labels.json || fail "labels list exited $?"
grep -q '"name":"truth","runs":\["ch5_0000","ch5_0001","first","room1_0001"\],"segments":[1-9]' \
  labels.json || fail "labels list: $(cat labels.json)"
"$T" labels export --db c.db --set truth l.csv --json > export.json || fail "export exited $?"
grep -q '"file":"l.csv"' export.json || fail "labels export --json: $(cat export.json)"
[ "$(grep -c '^# run ' l.csv)" -eq 4 ] || fail "provenance lines: $(head -5 l.csv)"
grep -q "^# run first steps $(steps room1/room1_0000.csv) checksum [0-9a-f]\{16\}\$" l.csv ||
  fail "provenance of 'first': $(head -5 l.csv)"
sed -n 5p l.csv | grep -q '^run,group,first_step,last_step,class' || fail "header after provenance"
"$T" labels import --db c.db --set again l.csv > /dev/null || fail "own export not importable"

# labels rename/delete; an unknown name deletes nothing; both list forms (A B and A,B).
"$T" labels rename --db c.db truth t2 > /dev/null || fail "labels rename exited $?"
if "$T" labels delete --db c.db t2 ghost 2> ghost.err; then fail "deleted with an unknown set"; fi
grep -q "no label set named 'ghost'; nothing deleted" ghost.err || fail "ghost: $(cat ghost.err)"
"$T" labels list --db c.db --json | grep -q '"name":"t2"' || fail "t2 deleted by a failed delete"
"$T" labels delete --db c.db t2,again --json > ldel.json || fail "labels delete exited $?"
grep -q '"deleted":\["t2","again"\]' ldel.json || fail "labels delete: $(cat ldel.json)"
"$T" labels list --db c.db --json | grep -q '"label_sets":\[\]' || fail "sets left after delete"

# runs delete: unknown name deletes nothing; then a real delete cascades.
if "$T" runs delete --db c.db ch5_0000 ghost 2> rghost.err; then fail "deleted with a ghost"; fi
grep -q "c.db: no run named 'ghost'; nothing deleted" rghost.err || fail "$(cat rghost.err)"
"$T" runs delete --db c.db ch5_0000 ch5_0001 > /dev/null || fail "runs delete exited $?"
"$T" runs list --db c.db --json | grep -q 'ch5' && fail "ch5 runs still listed"
"$T" db check --db c.db --json | grep -q '"ok":true,.*"runs":2' || fail "db check after delete"

# Two batches without prefixes in one call: the second run_0000 fails, naming both files.
"$T" simulate --scene room1 --driver random --steps 120 --runs 1 --out-dir a --quiet > /dev/null
"$T" simulate --scene room1 --driver random --steps 150 --runs 1 --seed 9 --out-dir b \
  --quiet > /dev/null
if "$T" import --db d.db a b > clash.out 2> clash.err; then fail "clashing batch imported"; fi
grep -q "b/run_0000.csv: a run named 'run_0000' already exists (imported from a/run_0000.csv" \
  clash.err || fail "clash message: $(cat clash.err)"
grep -q -- "--prefix" clash.err || fail "clash message does not suggest --prefix"

# Labels made on d.db's run_0000 refused by a database whose run_0000 is another recording.
"$T" autolabel --db d.db --all --set t > /dev/null
"$T" labels export --db d.db --set t d.csv > /dev/null
"$T" import --db e.db b/run_0000.csv > /dev/null
"$T" autolabel --db e.db --all --set t > /dev/null
"$T" labels export --db e.db --set t e.csv > /dev/null
ours=$(sed -n 's/^# run run_0000 steps \([0-9]*\) checksum \([0-9a-f]*\)$/\1 steps, checksum \2/p' d.csv)
theirs=$(sed -n 's/^# run run_0000 steps \([0-9]*\) checksum \([0-9a-f]*\)$/\1 steps, checksum \2/p' e.csv)
[ -n "$ours" ] && [ -n "$theirs" ] && [ "$ours" != "$theirs" ] || fail "checksums: $ours / $theirs"
if "$T" labels import --db e.db --set other d.csv 2> wrong.err; then fail "foreign labels imported"; fi
grep -q "d.csv:1: run 'run_0000': the label file was made for $ours, but the database's run 'run_0000' has $theirs" \
  wrong.err || fail "mismatch message: $(cat wrong.err)"

# File-form train: a stem in two folders is ambiguous without provenance; with it, the wrong file
# is refused naming both values.
grep -v '^#' d.csv > plain.csv
if "$T" train --runs a/run_0000.csv b/run_0000.csv --labels plain.csv --out m.json \
  2> ambiguous.err; then fail "ambiguous stem trained"; fi
grep -q "label run 'run_0000' matches a/run_0000.csv and b/run_0000.csv" ambiguous.err ||
  fail "ambiguous message: $(cat ambiguous.err)"
if "$T" train --runs b/run_0000.csv --labels d.csv --out m.json 2> mismatch.err; then
  fail "labels of another run trained"
fi
grep -q "label run 'run_0000' was made for $ours, but b/run_0000.csv has $theirs" mismatch.err ||
  fail "train mismatch message: $(cat mismatch.err)"
[ ! -e m.json ] || fail "a model was written"
echo "ok"
