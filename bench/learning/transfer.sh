#!/bin/sh
# Transfer benchmark: models trained with the product's defaults on the training recipe, scored on
# wall-following runs in scenes the training never saw (docs/BENCHMARKS.md#transfer).
#
#   bench/learning/transfer.sh TACTILE OUTDIR [FIT_SEEDS]
#
#   TACTILE    the tactile program (build/app/tactile)
#   OUTDIR     working folder (runs, models, per-seed JSON, table.md)
#   FIT_SEEDS  fit seeds, default "1 2 3" (the table gives the median over them)
#
# Environment: RECIPE_RUNS (40), RECIPE_SEED (1), SCORE_RUNS (3), SCORE_STEPS (4000),
# SCORE_SEED (7001), ROOMS ("random:60:90001 random:60:90002"), THREADS (passed to nothing: the
# fits use the defaults, which run on every core).
#
# Held out in turn: each built-in scene (room1, room2, room3, chapter5): the recipe's runs in that
# scene are removed from training, and the wall-following runs scored are in it. Generated rooms
# (ROOMS, seeds no recipe or choice of a default ever used) are scored by models trained on the
# whole recipe. Prints, for every decision mode (step, online, offline), the balanced accuracy per
# group (median over fit seeds) in each scored scene and their mean, with training and scoring
# times.
set -eu
T=$1
OUT=$2
FIT_SEEDS=${3:-"1 2 3"}
RECIPE_RUNS=${RECIPE_RUNS:-40}
RECIPE_SEED=${RECIPE_SEED:-1}
SCORE_RUNS=${SCORE_RUNS:-3}
SCORE_STEPS=${SCORE_STEPS:-4000}
SCORE_SEED=${SCORE_SEED:-7001}
ROOMS=${ROOMS:-"random:60:90001 random:60:90002"}
SCENES="room1 room2 room3 chapter5"
mkdir -p "$OUT"

# The recipe, once.
if [ ! -d "$OUT/recipe" ]; then
  "$T" simulate --plan training --runs "$RECIPE_RUNS" --seed "$RECIPE_SEED" \
    --out-dir "$OUT/recipe" --quiet > /dev/null
fi
# Wall-following runs to score on, once per scene.
for S in $SCENES $ROOMS; do
  D="$OUT/score/$(echo "$S" | tr ':' '_')"
  if [ ! -d "$D" ]; then
    "$T" simulate --scene "$S" --driver wall-follow --runs "$SCORE_RUNS" --steps "$SCORE_STEPS" \
      --seed "$SCORE_SEED" --out-dir "$D" --quiet > /dev/null
  fi
done

now() { date +%s.%N; }
for SEED in $FIT_SEEDS; do
  for S in $SCENES $ROOMS; do
    TAG=$(echo "$S" | tr ':' '_')
    # Training runs: the recipe without the runs recorded in the held-out scene.
    LIST="$OUT/train_$TAG.txt"
    : > "$LIST"
    for f in "$OUT"/recipe/*.csv; do
      if ! head -5 "$f" | grep -qx "# scene: $S"; then echo "$f" >> "$LIST"; fi
    done
    t0=$(now)
    # shellcheck disable=SC2046
    "$T" train --runs $(paste -sd, "$LIST") --test-runs $(ls "$OUT/score/$TAG"/*.csv | paste -sd,) \
      --seed "$SEED" --out "$OUT/model_${TAG}_$SEED.json" --json > "$OUT/train_${TAG}_$SEED.json" \
      2> /dev/null
    t1=$(now)
    # Scoring alone: classify every scored run with the model's default (online) decision.
    for r in "$OUT/score/$TAG"/*.csv; do
      "$T" classify --model "$OUT/model_${TAG}_$SEED.json" --run "$r" --out /dev/null 2> /dev/null
    done
    t2=$(now)
    echo "{\"scene\": \"$S\", \"seed\": $SEED, \"train_s\": $(echo "$t1 - $t0" | bc), \"score_s\": $(echo "$t2 - $t1" | bc), \"train_runs\": $(wc -l < "$LIST")}" \
      > "$OUT/time_${TAG}_$SEED.json"
  done
done

python3 - "$OUT" "$FIT_SEEDS" "$SCENES $ROOMS" <<'PY'
import json, statistics, sys
out, seeds, scenes = sys.argv[1], sys.argv[2].split(), sys.argv[3].split()
groups = ["F", "FLC", "L", "RLC", "B", "RRC", "R", "FRC"]
modes = ["step", "online", "offline"]
score = {}   # (mode, scene, group) -> [per seed]
tests = {}   # (scene, group) -> test steps
times = {}
for s in scenes:
    tag = s.replace(":", "_")
    for seed in seeds:
        doc = json.load(open(f"{out}/train_{tag}_{seed}.json"))
        t = json.load(open(f"{out}/time_{tag}_{seed}.json"))
        times.setdefault(s, []).append((t["train_s"], t["score_s"], t["train_runs"]))
        for g in doc["groups"]:
            if not g.get("trained"):
                continue
            tests[(s, g["group"])] = g.get("samples_test", 0)
            for m in modes:
                v = g["balanced_accuracy_by_decision"][m]
                if v is not None:
                    score.setdefault((m, s, g["group"]), []).append(v)
def med(v):
    return statistics.median(v) if v else None
def cell(v, n=None):
    if v is None:
        return "no test data"
    return f"{v:.2f}" + (f" ({n})" if n is not None else "")
lines = []
for m in modes:
    lines.append(f"\n### decision: {m}\n")
    lines.append("| scored on (held out) | " + " | ".join(groups) + " |")
    lines.append("|---|" + "---|" * len(groups))
    for s in scenes:
        row = [cell(med(score.get((m, s, g), [])), tests.get((s, g))) for g in groups]
        lines.append(f"| {s} | " + " | ".join(row) + " |")
    means = []
    for g in groups:
        per = [med(score.get((m, s, g), [])) for s in scenes]
        per = [p for p in per if p is not None]
        means.append(cell(statistics.mean(per) if per else None))
    lines.append("| **mean over scenes** | " + " | ".join(means) + " |")
lines.append("\n| scored on | training runs | train + score in-process s (median) | classify the scored runs s (median) |")
lines.append("|---|---|---|---|")
for s in scenes:
    ts = times[s]
    lines.append(f"| {s} | {ts[0][2]} | {statistics.median(t[0] for t in ts):.1f} | {statistics.median(t[1] for t in ts):.2f} |")
text = "\n".join(lines) + "\n"
open(f"{out}/table.md", "w").write(text)
print(text)
PY
