#!/bin/sh
# Hostile names and bytes through the command line (docs/file-formats.md#names-and-text): `--json`
# stays one valid JSON object whatever bytes reach it (file names, names stored by older versions,
# Latin-1 annotators), the one name rule at every entry, file paths never split at commas, integer
# literals in run files, JSON number overflow naming the file and line, a damaged user_version, and
# autolabel printing one error once.
#   tests/app/cli_hostile.sh TACTILE WORKDIR
. "$(dirname "$0")/cli_test_lib.sh"
command -v python3 > /dev/null || fail "python3 is needed to read the JSON output"

# One valid JSON object on one line, read by a strict reader (no NaN, valid UTF-8).
valid_json() {
  python3 - "$1" << 'EOF'
import json, sys
raw = open(sys.argv[1], "rb").read()
text = raw.decode("utf-8")  # raises on invalid UTF-8
assert text.endswith("\n") and text.count("\n") == 1, repr(text[:200])
def no_constants(c):
    raise ValueError(c)
doc = json.loads(text, parse_constant=no_constants)
assert isinstance(doc, dict), type(doc)
EOF
}

"$T" simulate --scene room1 --runs 3 --steps 250 --out-dir sim --quiet > /dev/null

# ---- file names that are not UTF-8, hold commas, or sit in a folder with a comma ----
mkdir -p "in" "dir,x"
cp sim/run_0000.csv "$(printf 'in/caf\351.csv')"
cp sim/run_0001.csv "in/run,one.csv"
cp sim/run_0002.csv "dir,x/third.csv"
status=0
"$T" import --db h.db --json in "dir,x" > import.json 2> import.err || status=$?
[ "$status" -eq 1 ] || fail "import with a non-UTF-8 file name should fail that file: exit $status"
valid_json import.json || fail "import --json: $(cat import.json)"
python3 - import.json << 'EOF' || fail "import --json content: $(cat import.json)"
import json, sys
d = json.load(open(sys.argv[1], encoding="utf-8"))
names = sorted(r["name"] for r in d["runs"])
assert names == ["run_one", "third"], names
assert len(d["failed"]) == 1, d["failed"]
f = d["failed"][0]
assert f["file"].endswith("caf\ufffd.csv"), f
assert "run name" in f["message"] and "--name" in f["message"], f
EOF
grep -q 'caf\\xE9' import.err || fail "the error should show the bad byte as \\xE9: $(cat import.err)"
# Given a name, the same file imports.
"$T" import --db h.db --name cafe "$(printf 'in/caf\351.csv')" > /dev/null ||
  fail "import --name of a non-UTF-8 file name"

# ---- the name rule at every entry ----
expect_usage() {
  what=$1
  shift
  status=0
  "$@" > usage.out 2> usage.err || status=$?
  [ "$status" -eq 2 ] || fail "$what: expected exit 2, got $status: $(cat usage.err)"
  grep -q "tactile: error: --" usage.err || fail "$what: message should name the option: $(cat usage.err)"
}
expect_usage "import --name a,b" "$T" import --db h.db --name "a,b" sim/run_0000.csv
expect_usage "import --name with a line break" "$T" import --db h.db --name "$(printf 'a\nb')" sim/run_0000.csv
expect_usage "import --prefix with a tab" "$T" import --db h.db --prefix "$(printf 'p\tq')" sim
expect_usage "autolabel --set a,b" "$T" autolabel --db h.db --all --set "a,b"
expect_usage "autolabel --set Latin-1" "$T" autolabel --db h.db --all --set "$(printf 'caf\351')"
expect_usage "labels import --set" "$T" labels import --db h.db --set "$(printf 'x\ny')" none.csv
expect_usage "train --name m,n" "$T" train --db h.db --set truth --name "m,n"
expect_usage "models import --name m,n" "$T" models import --db h.db --name "m,n" none.json
long=$(python3 -c 'print("n" * 201)')
expect_usage "import --name 201 bytes" "$T" import --db h.db --name "$long" sim/run_0000.csv
status=0
"$T" runs rename --db h.db third "$(printf 'caf\351')" 2> rename.err || status=$?
[ "$status" -eq 1 ] || fail "runs rename to invalid UTF-8: exit $status"
grep -q "UTF-8" rename.err || fail "runs rename message: $(cat rename.err)"

# A name starting with '-' is valid and can be renamed to and deleted after --.
"$T" runs rename --db h.db -- third -dash > /dev/null || fail "runs rename to -dash"
"$T" runs delete --db h.db -- -dash > /dev/null || fail "runs delete -dash"

# ---- autolabel: one error printed once ----
status=0
"$T" autolabel --db h.db --all --set "a,b" 2> once.err || status=$?
[ "$(grep -c 'tactile: error:' once.err)" -eq 1 ] || fail "autolabel printed: $(cat once.err)"
status=0
"$T" autolabel --db h.db --all --set "" 2> once.err || status=$?
[ "$status" -eq 2 ] || fail "autolabel --set '': exit $status"
[ "$(grep -c 'tactile: error:' once.err)" -eq 1 ] || fail "autolabel printed: $(cat once.err)"

# ---- bytes stored by an older version still print as valid JSON ----
"$T" autolabel --db h.db --all --set truth > /dev/null || fail "autolabel"
python3 - h.db << 'EOF' || fail "could not damage the names"
import sqlite3, sys
c = sqlite3.connect(sys.argv[1])
c.execute("UPDATE label_segments SET annotator = CAST(X'4A6F73E9' AS TEXT)")
c.execute("UPDATE label_sets SET annotator = CAST(X'4A6F73E9' AS TEXT)")
c.commit()
EOF
"$T" train --db h.db --set truth --name hostile --json > train.json 2> train.err ||
  fail "train --json exited $?: $(cat train.err)"
valid_json train.json || fail "train --json: $(cat train.json)"
# A run name edited outside the product breaks the run row's checksum: the database is then
# damaged for writing, but every reading verb still prints valid JSON.
cp h.db hr.db
python3 - hr.db << 'EOF' || fail "could not damage the run name"
import sqlite3, sys
c = sqlite3.connect(sys.argv[1])
c.execute("UPDATE runs SET name = CAST(X'6361666531E9' AS TEXT) WHERE name = 'cafe'")
c.commit()
EOF
"$T" runs list --db hr.db --json > list.json || fail "runs list --json exited $?"
valid_json list.json || fail "runs list --json: $(cat list.json)"
grep -q "cafe1" list.json || fail "runs list lost the run: $(cat list.json)"
"$T" labels list --db hr.db --json > labels.json || fail "labels list --json exited $?"
valid_json labels.json || fail "labels list --json: $(cat labels.json)"
"$T" labels export --db hr.db --set truth --json export.json > export.out ||
  fail "labels export exited $?"
valid_json export.out || fail "labels export --json: $(cat export.out)"
python3 -c 'import json,sys; json.loads(open(sys.argv[1],"rb").read().decode("utf-8"))' export.json ||
  fail "exported label JSON is not valid JSON"
"$T" models list --db hr.db --json > models.json || fail "models list --json exited $?"
valid_json models.json || fail "models list --json: $(cat models.json)"

# ---- integer fields in run files ----
python3 - sim/run_0000.csv bad_blocked.csv bad_step.csv << 'EOF'
import sys
lines = open(sys.argv[1]).read().split("\n")
header = next(i for i, l in enumerate(lines) if l.startswith("step,"))
cols = lines[header].split(",")
row = lines[header + 2].split(",")
row[cols.index("blocked")] = "01"
open(sys.argv[2], "w").write("\n".join(lines[:header + 2] + [",".join(row)] + lines[header + 3:]))
row = lines[header + 1].split(",")
row[cols.index("step")] = "-0"
open(sys.argv[3], "w").write("\n".join(lines[:header + 1] + [",".join(row)] + lines[header + 2:]))
EOF
for f in bad_blocked.csv bad_step.csv; do
  status=0
  "$T" import --db ints.db "$f" 2> ints.err > /dev/null || status=$?
  [ "$status" -eq 1 ] || fail "$f imported (exit $status)"
  grep -q "tactile: error: $f:[0-9]*: column '\(blocked\|step\)'" ints.err ||
    fail "$f: message should name file, line and column: $(cat ints.err)"
done

# ---- JSON number overflow names the file and line ----
"$T" models export --db h.db hostile --out m.json > /dev/null || fail "models export"
python3 - m.json << 'EOF'
import re, sys
text = open(sys.argv[1]).read()
text = re.sub(r'("variance_floor": )[^,\n]+', r'\g<1>1e400', text, count=1)
open(sys.argv[1], "w").write(text)
EOF
line=$(grep -n '1e400' m.json | cut -d: -f1)
status=0
"$T" models import --db h.db --name over m.json 2> over.err || status=$?
[ "$status" -eq 1 ] || fail "a model with 1e400 imported (exit $status)"
grep -q "tactile: error: m.json:$line: .*overflow" over.err || fail "model overflow: $(cat over.err)"
printf '{"name":"s","bounds":[0,0,1e400,100],"obstacles":[],"start":{"x":1,"y":1,"theta":0},"goal":{"x":2,"y":2}}\n' > s.json
status=0
"$T" simulate --scene s.json --steps 10 --out s.csv 2> scene.err > /dev/null || status=$?
[ "$status" -ne 0 ] || fail "a scene with 1e400 simulated"
grep -q "s.json:1: .*overflow" scene.err || fail "scene overflow: $(cat scene.err)"

# ---- running out of memory on a scene is an error naming the file, not "std::bad_alloc" ----
status=0
(ulimit -v 400000 && "$T" simulate --scene /dev/zero --steps 10 --out z.csv --quiet) 2> oom.err ||
  status=$?
[ "$status" -eq 1 ] || fail "scene /dev/zero: exit $status: $(cat oom.err)"
grep -q "tactile: error: /dev/zero: " oom.err || fail "scene /dev/zero: $(cat oom.err)"
if grep -q "bad_alloc" oom.err; then fail "scene /dev/zero: $(cat oom.err)"; fi

# ---- a damaged user_version: no advice to run a verb that then fails ----
"$T" import --db old.db sim/run_0000.csv > /dev/null
python3 -c 'import sqlite3,sys; c=sqlite3.connect(sys.argv[1]); c.execute("pragma user_version=3"); c.commit()' old.db
status=0
"$T" runs list --db old.db 2> old.err > /dev/null || status=$?
[ "$status" -eq 1 ] || fail "runs list on a damaged user_version: exit $status"
grep -q "damaged" old.err || fail "damaged user_version: $(cat old.err)"
if grep -q "db create" old.err; then fail "advises db create: $(cat old.err)"; fi
[ "$(wc -l < old.err)" -eq 1 ] || fail "damaged user_version: one line expected: $(cat old.err)"
before=$(cksum < old.db)
status=0
"$T" db create --db old.db 2> create.err > /dev/null || status=$?
[ "$status" -eq 1 ] || fail "db create on a damaged user_version: exit $status"
grep -q "damaged" create.err || fail "db create on a damaged user_version: $(cat create.err)"
[ "$(cksum < old.db)" = "$before" ] || fail "db create changed the damaged file"
if ls old.db.v3*.bak > /dev/null 2>&1; then fail "db create left a backup: $(ls old.db*)"; fi

echo "ok: hostile names and bytes"
