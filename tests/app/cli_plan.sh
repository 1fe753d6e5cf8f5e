#!/bin/sh
# `tactile simulate --plan training`: the recipe's runs, their class table, determinism, and the
# generated scenes travelling with the runs into a database.
. "$(dirname "$0")/cli_test_lib.sh"

"$T" simulate --plan training --runs 12 --seed 3 --out-dir "$W/a" --prefix p --json --quiet \
  >"$W/a.json" || fail "plan run failed"
python3 - "$W/a.json" <<'PY' || fail "plan JSON"
import json, sys
j = json.load(open(sys.argv[1]))
assert len(j["runs"]) == 12, j["runs"]
kinds = [r["kind"] for r in j["runs"]]
assert kinds[:3] == ["wall-follow", "cluttered", "wall-end"], kinds
assert kinds[10:] == ["office bug", "office wall-follow"], kinds
groups = j["class_steps"]
assert sorted(groups) == sorted(["F", "FLC", "L", "RLC", "B", "RRC", "R", "FRC"]), groups
assert sum(groups["F"].values()) == j["steps"], (groups["F"], j["steps"])
assert groups["F"]["DeadPath"] > 0 and groups["B"]["DeadPath"] == 0, groups
assert j["truth"]["blocked_without_readings"] == 0, j["truth"]
PY
# The same seed gives the same files, byte for byte.
"$T" simulate --plan training --runs 12 --seed 3 --out-dir "$W/b" --prefix p --quiet >/dev/null ||
  fail "second plan run failed"
for f in "$W"/a/*; do
  cmp -s "$f" "$W/b/$(basename "$f")" || fail "$(basename "$f") differs between two runs"
done
# Generated scenes are written beside their runs and stored with them on import.
[ -f "$W/a/p_0002.scene.json" ] || fail "no scene file for a generated scene"
"$T" import --db "$W/p.db" "$W/a" >/dev/null || fail "import failed"
stored=$(sqlite3 "$W/p.db" "SELECT count(*) FROM runs WHERE scene_id IS NOT NULL")
[ "$stored" = 12 ] || fail "scenes stored for $stored of 12 runs"
# Usage errors.
usage() {
  st=0
  "$T" simulate "$@" >/dev/null 2>&1 || st=$?
  [ "$st" -eq 2 ] || fail "simulate $* exited $st, not 2"
}
usage --plan other --out-dir "$W/c"
usage --plan training --runs 2
usage --plan training --scene room1 --out-dir "$W/c"
echo "ok: plan"
