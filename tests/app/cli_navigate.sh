#!/bin/sh
# `tactile navigate`: seeded runs on the chapter-5 scene (byte-identical for the same seeds, with
# any thread count), the JSON contract, run files that import with the navigator's columns, and
# usage errors.
. "$(dirname "$0")/cli_test_lib.sh"

"$T" navigate --scene chapter5 --status truth --seeds 1-3 --max-steps 3000 --out-dir "$W/a" \
  --threads 2 --json --quiet >"$W/a.json" || fail "navigate failed"
python3 - "$W/a.json" <<'PY' || fail "navigate JSON"
import json, sys
j = json.load(open(sys.argv[1]))
runs = j["runs"]
assert [r["seed"] for r in runs] == [1, 2, 3], runs
for r in runs:
    assert r["outcome"] in ("success", "unreachable", "timeout"), r
    assert r["steps"] >= 1 and r["path_length"] > 0 and r["blocked_steps"] >= 0, r
ok = sum(r["outcome"] == "success" for r in runs)
assert abs(j["success_rate"] - ok / 3) < 1e-12, j
PY
"$T" navigate --scene chapter5 --status truth --seeds 1-3 --max-steps 3000 --out-dir "$W/b" \
  --threads 1 --quiet >"$W/b.txt" || fail "second navigate failed"
for f in "$W"/a/*.csv; do
  cmp -s "$f" "$W/b/$(basename "$f")" || fail "$(basename "$f") differs between two runs"
done
grep -q "success rate" "$W/b.txt" || fail "no success rate line"
head -c 2000 "$W/a/navigate_truth_0001.csv" | grep -q "x_strategy" || fail "no x_strategy column"
"$T" import --db "$W/n.db" "$W/a" >/dev/null || fail "import failed"
cols=$(sqlite3 "$W/n.db" "SELECT count(*) FROM runs")
[ "$cols" = 3 ] || fail "imported $cols of 3 runs"

# The default navigator follows the touch map's plan (Head to Destination, Check Contact at a
# contact); --wall-follow runs the thesis strategies, which follow the wall across the scene.
"$T" navigate --scene chapter5 --status truth --seeds 1 --max-steps 3000 --out-dir "$W/pd" \
  --quiet >/dev/null || fail "plan drive failed"
"$T" navigate --scene chapter5 --status truth --seeds 1 --max-steps 3000 --out-dir "$W/wf" \
  --wall-follow --quiet >/dev/null || fail "--wall-follow failed"
python3 - "$W/pd/navigate_truth_0001.csv" "$W/wf/navigate_truth_0001.csv" <<'PY' || fail "modes"
import csv, sys
def strategies(path):
    rows = csv.DictReader(line for line in open(path) if not line.startswith("#"))
    return {r["x_strategy"] for r in rows}
plan, wall = strategies(sys.argv[1]), strategies(sys.argv[2])
assert plan <= {"HeadToDestination", "CheckContact"}, plan
assert "FollowWall" in wall, wall
PY

# The benchmark's JSON: one record a map per source, adding up to the summary; --out-dir writes
# every run (a small model trained on two short runs is enough for the model source to drive).
"$T" simulate --scene room1 --driver wall-follow --steps 800 --runs 2 --out-dir "$W/train" \
  --quiet >/dev/null || fail "simulate for the model failed"
"$T" train --runs "$W/train/run_0000.csv" "$W/train/run_0001.csv" --groups R --out "$W/m.json" \
  >/dev/null 2>&1 || fail "train failed"
"$T" navigate --benchmark 2 --model "$W/m.json" --threads 2 --out-dir "$W/bench" --json --quiet \
  >"$W/bench.json" 2>"$W/bench.err" || fail "navigate --benchmark failed"
python3 - "$W/bench.json" "$W/bench" <<'PY' || fail "benchmark JSON"
import json, os, sys
j = json.load(open(sys.argv[1]))
assert j["maps"] == 2, j
for source in ("model", "truth", "bumper"):
    s = j[source]
    runs = s["map_runs"]
    assert [r["map_seed"] for r in runs] == [900001, 900002], runs
    for key in ("success", "unreachable", "timeout"):
        assert s["outcomes"][key] == sum(r["outcome"] == key for r in runs), (source, key)
    for r in runs:
        assert sum(r["strategy_steps"].values()) == r["steps"] <= r["budget"], r
        assert set(r["strategy_steps"]) >= {"CheckContact", "FollowWall", "HeadToDestination"}, r
        assert 0 <= r["closest_goal_distance"] <= r["final_goal_distance"], r
        assert r["check_contact_starts"] >= 0 and r["path_ratio"] > 0, r
        f = os.path.join(sys.argv[2], "benchmark_%s_%d.csv" % (source, r["map_seed"]))
        rows = sum(1 for line in open(f) if line[0].isdigit())
        assert rows == r["steps"], (f, rows, r["steps"])
PY

# A model without some groups (this one has R alone) is named before the run, on stderr.
"$T" navigate --scene chapter5 --status model --model "$W/m.json" --seeds 1 --max-steps 20 \
  --out-dir "$W/partial" --quiet >/dev/null 2>"$W/partial.err" || fail "partial model run failed"
grep -q "^tactile: warning: model .*m.json has no model for F, FLC, L, RLC, B, RRC, FRC:" \
  "$W/partial.err" || fail "no warning of the missing groups: $(cat "$W/partial.err")"

# Seed 0 is the scene's own start, where the benchmark starts a map: with the map's budget the
# run is the benchmark's, for every source (so a benchmark map can be driven again and watched).
for source in model truth bumper; do
  budget=$(python3 -c "import json,sys; r=json.load(open(sys.argv[1]))['$source']['map_runs'][1]; print(r['budget'])" "$W/bench.json")
  "$T" navigate --scene random:office:900002 --status "$source" --model "$W/m.json" --seeds 0 \
    --max-steps "$budget" --out-dir "$W/again" --json --quiet >"$W/again.json" 2>"$W/again.err" ||
    fail "navigate --seeds 0 ($source) failed"
  # Every line but the seed's (0 here, the map's seed there).
  grep -v '^# seed:' "$W/again/navigate_${source}_0000.csv" >"$W/again.csv"
  grep -v '^# seed:' "$W/bench/benchmark_${source}_900002.csv" >"$W/bench.csv"
  [ "$(wc -l <"$W/again.csv")" -gt 20 ] || fail "seed 0 ($source): a short run"
  cmp -s "$W/again.csv" "$W/bench.csv" || fail "seed 0 ($source): the run differs from the benchmark's"
done

# Usage errors exit 2; a model source without a model too.
set +e
"$T" navigate --scene chapter5 --status truth --seeds 5-2 >/dev/null 2>&1
[ $? = 2 ] || fail "backwards --seeds is not a usage error"
"$T" navigate --scene chapter5 --status sideways >/dev/null 2>&1
[ $? = 2 ] || fail "unknown --status is not a usage error"
"$T" navigate --scene chapter5 >/dev/null 2>&1
[ $? = 2 ] || fail "model status without --model is not a usage error"
# Options the benchmark would ignore are refused; without --model it says what the model is for.
"$T" navigate --benchmark 2 --status truth --model "$W/m.json" >/dev/null 2>"$W/err.txt"
[ $? = 2 ] || fail "--benchmark with --status is not a usage error"
grep -q -- "--status excludes --benchmark" "$W/err.txt" || fail "--status: $(cat "$W/err.txt")"
"$T" navigate --scene chapter5 --status truth --seed 3 >/dev/null 2>"$W/err.txt"
[ $? = 2 ] || fail "--seed without --benchmark is not a usage error"
"$T" navigate --benchmark 2 >/dev/null 2>"$W/err.txt"
[ $? = 2 ] || fail "--benchmark without --model is not a usage error"
grep -q -- "--benchmark needs --model" "$W/err.txt" || fail "no model: $(cat "$W/err.txt")"
"$T" navigate --benchmark 0 --model "$W/m.json" >/dev/null 2>"$W/err.txt"
[ $? = 2 ] || fail "--benchmark 0 is not a usage error"
grep -q -- "--benchmark must be between" "$W/err.txt" || fail "--benchmark 0: $(cat "$W/err.txt")"
"$T" navigate --scene chapter5 --model "$W/missing.json" >/dev/null 2>"$W/err.txt"
[ $? = 1 ] || fail "a missing model file is not a failure"
grep -q "missing.json" "$W/err.txt" || fail "the error does not name the model file"

echo "ok: navigate"
