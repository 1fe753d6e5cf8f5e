#!/bin/sh
# End to end through the CLI: simulate a folder of runs (built-in and procedural scenes), import
# it, import it again (all skipped), autolabel every run, export the labels and a run, check the
# database, and import a broken file (named by file and line, nothing stored).
#   tests/app/cli_storage_chain.sh TACTILE WORKDIR
. "$(dirname "$0")/cli_test_lib.sh"

"$T" simulate --scene room1 --driver wall-follow --steps 600 --runs 3 --out-dir runs --quiet > /dev/null
"$T" simulate --scene random:30:5 --driver random --steps 300 --out runs/proc.csv --quiet > /dev/null

"$T" import --db c.db runs > import.out 2> import.err || fail "import exited $?"
grep -q "4 imported, 0 skipped, 0 failed" import.out || fail "import summary: $(cat import.out)"
# The procedural scene is stored too: no "stored without its scene" warning.
if grep -q "without its scene" import.err; then fail "scene not stored: $(cat import.err)"; fi
steps=$(sed -n 's/.* \([0-9]*\) steps in .*/\1/p' import.out)
[ "$steps" -gt 600 ] || fail "steps: $steps"

"$T" import --db c.db runs --json > again.json || fail "re-import exited $?"
grep -q '"runs":\[\]' again.json || fail "re-import stored runs: $(cat again.json)"
[ "$(grep -o 'already imported' again.json | wc -l)" -eq 4 ] || fail "re-import: $(cat again.json)"

"$T" autolabel --db c.db --all --set truth > autolabel.out || fail "autolabel exited $?"
[ "$(grep -c "labelled run" autolabel.out)" -eq 4 ] || fail "autolabel: $(cat autolabel.out)"
"$T" labels export --db c.db --set truth labels.csv || fail "labels export exited $?"
# Provenance lines (one per run), then the header.
[ "$(grep -c '^# run [a-z_0-9]* steps [0-9]* checksum [0-9a-f]*$' labels.csv)" -eq 4 ] ||
  fail "label provenance: $(head -5 labels.csv)"
grep -v '^#' labels.csv | head -1 | grep -q '^run,group,first_step,last_step,class' ||
  fail "label header"
# Every run has segments for all eight groups, and each group's segments start at step 0.
for run in proc run_0000 run_0001 run_0002; do
  groups=$(grep "^$run,[A-Z]*,0," labels.csv | cut -d, -f2 | sort -u | wc -l)
  [ "$groups" -eq 8 ] || fail "run $run: $groups groups start at step 0"
done

"$T" export-run --db c.db --run run_0001 --out back.csv || fail "export-run exited $?"
cmp -s back.csv runs/run_0001.csv || fail "exported run differs from the imported file"

"$T" db check --db c.db > check.out || fail "db check exited $?"
grep -q "ok, schema version 7, 4 runs, $steps steps" check.out || fail "check: $(cat check.out)"

# A file broken in its 100th row: named by file and line, nothing of it stored.
awk 'NR == 1, /^step,/ { print; next } { n++; if (n == 100) sub(/^[0-9]+,[^,]*/, "99,abc"); print }' \
  runs/run_0000.csv > broken.csv
if "$T" import --db c.db broken.csv > broken.out 2> broken.err; then fail "broken file imported"; fi
line=$(awk '/^step,/ { print NR + 100; exit }' runs/run_0000.csv)
grep -q "broken.csv:$line:" broken.err || fail "broken file message: $(cat broken.err)"
"$T" db check --db c.db | grep -q "4 runs, $steps steps" || fail "the broken file left steps behind"
echo "ok"
