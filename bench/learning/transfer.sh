#!/bin/sh
# Transfer benchmark: models trained with the product's defaults on the training recipe, scored on
# wall-following runs in scenes the training never saw (docs/bench-learning.md#transfer).
#
#   bench/learning/transfer.sh TACTILE OUTDIR [FIT_SEEDS]
#
#   TACTILE    the tactile program (build/app/tactile)
#   OUTDIR     working folder (runs, models, per-seed JSON, table.md); runs already there are reused
#   FIT_SEEDS  fit seeds, default "1 2 3" (the tables give the median over them)
#
# Environment: RECIPE_RUNS (80, the recipe's documented size), RECIPE_SEED (1), SCORE_RUNS (3), SCORE_STEPS (4000),
# SCORE_SEED (7001), ROOMS (four generated office rooms with benchmark seeds, >= 900000, which
# neither the training recipe nor any choice of a default uses), MIN_STEPS (30), TRAIN_ARGS
# (extra `tactile train` options, empty: the product's defaults), REPORT_ONLY (1: only print the
# tables of a finished OUTDIR), IN_SCENE_RUNS (0) and IN_SCENE_SEED (8001): see below.
#
# Held out in turn: each built-in scene (room1, room2, room3, chapter5): the recipe's runs in that
# scene are removed from training, and the wall-following runs scored are in it. The office rooms
# (ROOMS) are scored by models trained on the whole recipe. Prints, for every decision mode (step,
# online, offline), the balanced accuracy per group and scored scene with its test-step count, the
# same pooled over every scored scene (one confusion summed over them) with the count of the
# rarest class, and the training and scoring times. A cell is marked "too few" when fewer than two
# of its classes have MIN_STEPS test steps; "no test data" when it has none.
#
# IN_SCENE_RUNS > 0 is a ceiling check, not the benchmark: each scored scene's model is also
# trained on IN_SCENE_RUNS wall-following runs recorded in that very scene (seeds IN_SCENE_SEED,
# IN_SCENE_SEED + 1, ...; other start poses than the scored runs'). What the models reach then,
# the scene's own driving seen in training, bounds what any training recipe can give them.
set -eu
T=$1
OUT=$2
FIT_SEEDS=${3:-"1 2 3"}
RECIPE_RUNS=${RECIPE_RUNS:-80}
RECIPE_SEED=${RECIPE_SEED:-1}
SCORE_RUNS=${SCORE_RUNS:-3}
SCORE_STEPS=${SCORE_STEPS:-4000}
SCORE_SEED=${SCORE_SEED:-7001}
ROOMS=${ROOMS:-"random:office:900001 random:office:900002 random:office:900003 random:office:900004"}
MIN_STEPS=${MIN_STEPS:-30}
TRAIN_ARGS=${TRAIN_ARGS:-}
IN_SCENE_RUNS=${IN_SCENE_RUNS:-0}
IN_SCENE_SEED=${IN_SCENE_SEED:-8001}
SCENES="room1 room2 room3 chapter5"
mkdir -p "$OUT"

for S in $ROOMS; do
  seed=${S##*:}
  if [ "$seed" -lt 900000 ]; then
    echo "transfer.sh: $S: benchmark rooms use seeds >= 900000 (the training recipe uses the rest)" >&2
    exit 2
  fi
done

if [ "$IN_SCENE_RUNS" -gt 0 ] && [ "$IN_SCENE_SEED" -lt $((SCORE_SEED + SCORE_RUNS)) ] &&
  [ "$SCORE_SEED" -lt $((IN_SCENE_SEED + IN_SCENE_RUNS)) ]; then
  echo "transfer.sh: the in-scene runs' seeds ($IN_SCENE_SEED + $IN_SCENE_RUNS) overlap the scored runs' ($SCORE_SEED + $SCORE_RUNS)" >&2
  exit 2
fi

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
  D="$OUT/inscene/$(echo "$S" | tr ':' '_')"
  if [ "$IN_SCENE_RUNS" -gt 0 ] && [ ! -d "$D" ]; then
    "$T" simulate --scene "$S" --driver wall-follow --runs "$IN_SCENE_RUNS" --steps "$SCORE_STEPS" \
      --seed "$IN_SCENE_SEED" --out-dir "$D" --quiet > /dev/null
  fi
done

now() { date +%s.%N; }
# REPORT_ONLY=1: only print the tables of a finished OUTDIR.
[ "${REPORT_ONLY:-0}" = 1 ] && FIT_LOOP="" || FIT_LOOP=$FIT_SEEDS
for SEED in $FIT_LOOP; do
  for S in $SCENES $ROOMS; do
    TAG=$(echo "$S" | tr ':' '_')
    # Training runs: the recipe without the runs recorded in the held-out scene.
    LIST="$OUT/train_$TAG.txt"
    : > "$LIST"
    for f in "$OUT"/recipe/*.csv; do
      if ! head -8 "$f" | grep -qx "# scene: $S"; then echo "$f" >> "$LIST"; fi
    done
    if [ "$IN_SCENE_RUNS" -gt 0 ]; then ls "$OUT/inscene/$TAG"/*.csv >> "$LIST"; fi
    t0=$(now)
    # shellcheck disable=SC2046,SC2086
    "$T" train --runs $(cat "$LIST") --test-runs "$OUT/score/$TAG"/*.csv --seed "$SEED" $TRAIN_ARGS \
      --out "$OUT/model_${TAG}_$SEED.json" --json > "$OUT/train_${TAG}_$SEED.json" 2> /dev/null
    t1=$(now)
    # Scoring alone: classify every scored run with the model's default (online) decision.
    for r in "$OUT/score/$TAG"/*.csv; do
      "$T" classify --model "$OUT/model_${TAG}_$SEED.json" --run "$r" \
        --out "$OUT/classified_${TAG}.csv" 2> /dev/null
    done
    t2=$(now)
    awk -v s="$S" -v seed="$SEED" -v a="$t0" -v b="$t1" -v c="$t2" -v n="$(wc -l < "$LIST")" \
      -v k="$IN_SCENE_RUNS" \
      'BEGIN { printf "{\"scene\": \"%s\", \"seed\": %s, \"train_s\": %.3f, \"score_s\": %.3f, \"train_runs\": %d, \"in_scene_runs\": %d}\n", s, seed, b - a, c - b, n, k }' \
      > "$OUT/time_${TAG}_$SEED.json"
  done
done

python3 - "$OUT" "$FIT_SEEDS" "$SCENES $ROOMS" "$MIN_STEPS" <<'PY'
import json, statistics, sys
out, seeds, scenes, min_steps = sys.argv[1], sys.argv[2].split(), sys.argv[3].split(), int(sys.argv[4])
groups = ["F", "FLC", "L", "RLC", "B", "RRC", "R", "FRC"]
modes = ["step", "online", "offline"]

def confusion(model, mode):
    c = model["metrics"]["by_decision"][mode]["confusion"]
    return c["classes"], c["counts"]

def add(acc, classes, counts):
    for i, t in enumerate(classes):
        for j, p in enumerate(classes):
            acc[(t, p)] = acc.get((t, p), 0) + counts[i][j]

def balanced(acc):
    truths = sorted({t for (t, _) in acc})
    support = {t: sum(n for (tt, _), n in acc.items() if tt == t) for t in truths}
    recalls = [acc.get((t, t), 0) / support[t] for t in truths if support[t] > 0]
    if not recalls:
        return None, 0, 0, 0
    enough = sum(1 for t in truths if support[t] >= min_steps)
    return statistics.mean(recalls), sum(support.values()), min(s for s in support.values() if s > 0), enough

per = {}     # (mode, scene, group) -> [balanced accuracy per seed]
count = {}   # (scene, group) -> (test steps, rarest class, classes with >= min_steps)
pooled = {}  # (mode, group, seed) -> summed confusion over scenes
times = {}
in_scene = set()  # IN_SCENE_RUNS of the trainings found
for s in scenes:
    tag = s.replace(":", "_")
    for seed in seeds:
        bundle = json.load(open(f"{out}/model_{tag}_{seed}.json"))
        t = json.load(open(f"{out}/time_{tag}_{seed}.json"))
        times.setdefault(s, []).append((t["train_s"], t["score_s"], t["train_runs"]))
        in_scene.add(t.get("in_scene_runs", 0))
        for m in bundle["models"]:
            g = m["group"]
            for mode in modes:
                classes, counts = confusion(m, mode)
                acc = {}
                add(acc, classes, counts)
                add(pooled.setdefault((mode, g, seed), {}), classes, counts)
                b, n, rare, enough = balanced(acc)
                count[(s, g)] = (n, rare, enough)
                if b is not None:
                    per.setdefault((mode, s, g), []).append(b)

def med(v):
    return statistics.median(v) if v else None

def cell(v, n, rare, enough):
    if v is None or n == 0:
        return "no test data"
    text = f"{v:.2f} ({n})"
    return text + " too few" if enough < 2 else text

# The in-scene runs each model was trained with, as recorded when it was trained (REPORT_ONLY
# prints a ceiling check's tables as such whatever IN_SCENE_RUNS is now).
seen = "unseen" if in_scene == {0} else f"seen: {'/'.join(map(str, sorted(in_scene)))} runs of it in training"
lines = [f"Median over fit seeds {' '.join(seeds)}. "
         f"Cells: balanced accuracy (test steps); 'too few': fewer than two classes with {min_steps} test steps."]
for mode in modes:
    lines.append(f"\n### decision: {mode}\n")
    lines.append(f"| scored on ({seen}) | " + " | ".join(groups) + " |")
    lines.append("|---|" + "---|" * len(groups))
    for s in scenes:
        row = [cell(med(per.get((mode, s, g), [])), *count.get((s, g), (0, 0, 0))) for g in groups]
        lines.append(f"| {s} | " + " | ".join(row) + " |")
    row = []
    for g in groups:
        vals, info = [], None
        for seed in seeds:
            b, n, rare, enough = balanced(pooled.get((mode, g, seed), {}))
            if b is not None:
                vals.append(b)
                info = (n, rare, enough)
        if not vals:
            row.append("no test data")
        else:
            n, rare, enough = info
            row.append(f"**{med(vals):.3f}** ({n}; rarest {rare})" + (" too few" if enough < 2 else ""))
    lines.append("| **pooled over the scenes** | " + " | ".join(row) + " |")

lines.append("\n### confusion pooled over the scenes, online decision, fit seed " + seeds[0] + " (rows truth, columns decided)\n")
for g in groups:
    acc = pooled.get(("online", g, seeds[0]), {})
    if not acc:
        continue
    cls = sorted({t for (t, _) in acc} | {p for (_, p) in acc})
    cells = "; ".join(f"{t}: " + ", ".join(f"{p} {acc.get((t, p), 0)}" for p in cls)
                      for t in cls if sum(acc.get((t, p), 0) for p in cls) > 0)
    lines.append(f"- {g}: {cells}")

lines.append("\n| scored on | training runs | train + score in process, s (median) | classify the scored runs, s (median) |")
lines.append("|---|---|---|---|")
for s in scenes:
    ts = times[s]
    lines.append(f"| {s} | {ts[0][2]} | {statistics.median(t[0] for t in ts):.1f} | {statistics.median(t[1] for t in ts):.2f} |")
total = sum(t[0] + t[1] for s in scenes for t in times[s])
lines.append(f"\nTotal training and scoring time: {total:.0f} s.")
text = "\n".join(lines) + "\n"
open(f"{out}/table.md", "w").write(text)
print(text)
PY
