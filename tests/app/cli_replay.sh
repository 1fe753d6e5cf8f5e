#!/bin/sh
# `tactile simulate --commands RUN.csv`: replaying a run's commands from its start pose gives the
# same steps, row for row; usage errors exit 2.
. "$(dirname "$0")/cli_test_lib.sh"

"$T" simulate --scene room1 --steps 700 --seed 4 --out "$W/a.csv" --quiet >/dev/null ||
  fail "simulate failed"
"$T" simulate --scene room1 --commands "$W/a.csv" --out "$W/b.csv" --json >"$W/b.json" ||
  fail "replay failed"
python3 - "$W/b.json" "$W/a.csv" <<'PY' || fail "replay JSON"
import json, sys
j = json.load(open(sys.argv[1]))
rows = sum(1 for line in open(sys.argv[2]) if not line.startswith("#")) - 1
assert j["steps"] == rows and rows > 100, (j, rows)
PY
grep -v '^#' "$W/a.csv" >"$W/a.rows"
grep -v '^#' "$W/b.csv" >"$W/b.rows"
cmp -s "$W/a.rows" "$W/b.rows" || fail "replayed steps differ from the recorded ones"
# A start pose in the run file is where the replay starts, whatever the scene's.
sed 's/^# start: .*/# start: 600,200,1.5/' "$W/a.csv" >"$W/moved.csv"
"$T" simulate --scene room1 --commands "$W/moved.csv" --out "$W/c.csv" --quiet >/dev/null ||
  fail "replay from a moved start failed"
grep -q '^# start: 600,200,1.5$' "$W/c.csv" || fail "the replay did not start at the file's start"
grep -v '^#' "$W/c.csv" >"$W/c.rows"
if cmp -s "$W/a.rows" "$W/c.rows"; then fail "a different start gave the same steps"; fi
rc=0
"$T" simulate --scene room1 --commands "$W/a.csv" --out-dir "$W/d" >/dev/null 2>&1 || rc=$?
[ "$rc" -eq 2 ] || fail "--commands with --out-dir is not a usage error (exit $rc)"
rc=0
"$T" simulate --scene room1 --commands "$W/missing.csv" --out "$W/e.csv" 2>"$W/err" >/dev/null ||
  rc=$?
[ "$rc" -eq 1 ] || fail "a missing command file does not exit 1 (exit $rc)"
grep -q "missing.csv" "$W/err" || fail "the error does not name the file"
echo "ok: replay"
