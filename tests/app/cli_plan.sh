#!/bin/sh
# `tactile simulate --plan training`: the recipe's runs, their class table, determinism, and the
# generated scenes travelling with the runs into a database.
. "$(dirname "$0")/cli_test_lib.sh"

"$T" simulate --plan training --runs 14 --seed 3 --out-dir "$W/a" --prefix p --json --quiet \
  >"$W/a.json" || fail "plan run failed"
python3 - "$W/a.json" <<'PY' || fail "plan JSON"
import json, sys
j = json.load(open(sys.argv[1]))
assert len(j["runs"]) == 14, j["runs"]
kinds = [r["kind"] for r in j["runs"]]
# Every second run is an extra (two office drives, left and right, then a pocket); the others are
# the recipe's numbered kinds in their order.
assert kinds[1::2] == ["office drive left", "office drive right", "extra pocket",
                      "office drive left", "office drive right", "extra pocket",
                      "office drive left"], kinds
assert kinds[0::2] == ["wall-follow", "cluttered", "wall-end", "inside-corner", "tips",
                       "reverse", "pocket"], kinds
assert all(r["scene"].startswith("random:office:") for r in j["runs"][1::2]
           if r["kind"].startswith("office drive")), j["runs"]
groups = j["class_steps"]
assert sorted(groups) == sorted(["F", "FLC", "L", "RLC", "B", "RRC", "R", "FRC"]), groups
assert sum(groups["F"].values()) == j["steps"], (groups["F"], j["steps"])
assert groups["F"]["DeadPath"] > 0 and groups["B"]["DeadPath"] == 0, groups
assert j["truth"]["blocked_without_readings"] == 0, j["truth"]
PY
# The same seed gives the same files, byte for byte.
"$T" simulate --plan training --runs 14 --seed 3 --out-dir "$W/b" --prefix p --quiet >/dev/null ||
  fail "second plan run failed"
for f in "$W"/a/*; do
  cmp -s "$f" "$W/b/$(basename "$f")" || fail "$(basename "$f") differs between two runs"
done
# Generated scenes are written beside their runs and stored with them on import.
[ -f "$W/a/p_0004.scene.json" ] || fail "no scene file for a generated scene"
"$T" import --db "$W/p.db" "$W/a" >/dev/null || fail "import failed"
stored=$(sqlite3 "$W/p.db" "SELECT count(*) FROM runs WHERE scene_id IS NOT NULL")
[ "$stored" = 14 ] || fail "scenes stored for $stored of 14 runs"
# Usage errors.
usage() {
  st=0
  "$T" simulate "$@" >/dev/null 2>&1 || st=$?
  [ "$st" -eq 2 ] || fail "simulate $* exited $st, not 2"
}
usage --plan other --out-dir "$W/c"
usage --plan training --runs 2
# Without --runs the recipe has its documented size (run files only; the scenes are small).
"$T" simulate --plan training --seed 3 --out-dir "$W/d" --quiet --json >"$W/d.json" ||
  fail "plan without --runs failed"
python3 -c 'import json,sys; n=len(json.load(open(sys.argv[1]))["runs"]); assert n == 80, n' \
  "$W/d.json" || fail "plan without --runs: not the documented 80 runs"
usage --plan training --scene room1 --out-dir "$W/c"
echo "ok: plan"
