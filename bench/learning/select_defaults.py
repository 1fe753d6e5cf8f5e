#!/usr/bin/env python3
"""Choose each group's training defaults from a leave-scene-out sweep (docs/learning.md#training-defaults).

    bench/learning/select_defaults.py SWEEP.json|MODEL.json[=TAG] ... [--min-steps 30] [--median-over-fits] [--top 3]

The sweeps are `tactile sweep --split by-scene` over the selection corpus (docs/learning.md), the
model bundles `tactile train --split by-scene` over it (for settings a sweep does not cover, such
as `--priors`; TAG names them in the table). Each held-out scene's confusion is in the cell's (the
model's) "scenes". Scenes named "recipe-*" are folds of the
training recipe; the others are wall-following runs in generated office rooms. Per cell and fold
kind the confusions are pooled (summed over the folds of that kind) and the balanced accuracy is
taken over the classes with at least --min-steps test steps; a fold kind with fewer than two such
classes is left out. A cell's score is the mean of the two fold kinds' balanced accuracies (or
the one that has data). Only causal decisions (step, online) can be a default; within 0.002 of the
best, the fewer features, then the lower order, then the larger floor, then the larger emission
weight (the class chain's weight of each step's evidence, `tactile train --emission-weight`; 1 =
the plain HMM; sweeps have 1) win (the simpler model). Prints the table of every group's best
cells (--top of them) and the chosen one.

--median-over-fits: the inputs are fits of the same cells with different fit seeds (for example
model bundles `tactile train --split by-scene --seed S` for S = 1, 2, 3, or one sweep per seed);
a setting's score is the median of its fits' scores (its recipe and office figures too), so a
setting that won by one lucky EM start does not win.
"""
import statistics
import json
import sys

FEATURE_SIZE = {"normal": 0, "normal+shear": 1, "normal+shear+touch": 2, "normal+shear+touch+context": 3,
                "normal+shear+touch+context+neighbours": 4, "normal+shear+touch+motion": 3,
                "normal+shear+touch+motion+neighbours": 4}


def pooled(cell, recipe):
    acc = {}
    for s in cell.get("scenes", []):
        if s["scene"].startswith("recipe-") != recipe:
            continue
        cls = s["confusion"]["classes"]
        for i, t in enumerate(cls):
            for j, p in enumerate(cls):
                acc[(t, p)] = acc.get((t, p), 0) + s["confusion"]["counts"][i][j]
    return acc


def balanced(acc, min_steps):
    truths = sorted({t for (t, _) in acc})
    support = {t: sum(n for (tt, _), n in acc.items() if tt == t) for t in truths}
    enough = [t for t in truths if support[t] >= min_steps]
    if len(enough) < 2:
        return None, sum(support.values())
    return sum(acc.get((t, t), 0) / support[t] for t in enough) / len(enough), sum(support.values())


def main():
    args = sys.argv[1:]
    min_steps = 30
    median_over_fits = "--median-over-fits" in args
    if median_over_fits:
        args.remove("--median-over-fits")
    top = 3
    if "--top" in args:
        i = args.index("--top")
        top = int(args[i + 1])
        del args[i:i + 2]
    if "--min-steps" in args:
        i = args.index("--min-steps")
        min_steps = int(args[i + 1])
        del args[i:i + 2]
    cells = []
    for arg in args:
        path, _, tag = arg.partition("=")
        doc = json.load(open(path))
        if "cells" in doc:
            cells += doc["cells"]
            continue
        for m in doc["models"]:  # a model bundle trained with --split by-scene
            for mode, _ in m["metrics"]["balanced_accuracy_by_decision"].items():
                scenes = [{"scene": sc["scene"], "confusion": sc["by_decision"][mode]["confusion"]}
                          for sc in m["metrics"].get("scenes", []) if mode in sc.get("by_decision", {})]
                cells.append({"ok": True, "group": m["group"], "features": m["features"] + (f" [{tag}]" if tag else ""),
                              "order": max(len(c["weights"]) for c in m["components"].values()), "floor": m["variance_floor"],
                              "decision": mode, "scenes": scenes,
                              "emission_weight": m.get("transitions", {}).get("emission_weight", 1.0)})
    by_group = {}
    for c in cells:
        if not c.get("ok"):
            continue
        r, nr = balanced(pooled(c, True), min_steps)
        o, no = balanced(pooled(c, False), min_steps)
        parts = [v for v in (r, o) if v is not None]
        if not parts:
            continue
        score = sum(parts) / len(parts)
        by_group.setdefault(c["group"], []).append((score, r, o, nr, no, c))
    if median_over_fits:
        for g, rows in by_group.items():
            fits = {}
            for x in rows:
                c = x[5]
                key = (c["features"].split(" [")[0], c["order"], c["floor"], c["decision"],
                       c.get("emission_weight", 1.0))
                fits.setdefault(key, []).append(x)
            merged = []
            for (features, order, floor, decision, weight), xs in fits.items():
                med = lambda i: None if any(x[i] is None for x in xs) else statistics.median(x[i] for x in xs)
                cell = {"features": f"{features} [median of {len(xs)} fits]", "order": order, "floor": floor,
                        "decision": decision, "emission_weight": weight}
                merged.append((statistics.median(x[0] for x in xs), med(1), med(2), xs[0][3], xs[0][4], cell))
            by_group[g] = merged
    print("| group | features | order | floor | emission weight | decision | recipe folds (steps) | office folds (steps) | score |")
    print("|---|---|---|---|---|---|---|---|---|")
    fmt = lambda v: "-" if v is None else f"{v:.3f}"
    for g in ["F", "FLC", "L", "RLC", "B", "RRC", "R", "FRC"]:
        rows = sorted(by_group.get(g, []), key=lambda x: -x[0])
        causal = [x for x in rows if x[5]["decision"] in ("step", "online")]
        if not causal:
            continue
        best = causal[0][0]
        near = [x for x in causal if x[0] >= best - 0.002]
        near.sort(key=lambda x: (FEATURE_SIZE.get(x[5]["features"].split(" [")[0], 9), x[5]["order"], -x[5]["floor"],
                                 -x[5].get("emission_weight", 1.0), -x[0]))
        chosen = near[0]
        for x in rows[:top] + ([chosen] if chosen not in rows[:top] else []):
            c = x[5]
            mark = " **chosen**" if x is chosen else ""
            w = c.get("emission_weight", 1.0)
            print(f"| {g} | {c['features']} | {c['order']} | {c['floor']:g} | {w:g} | {c['decision']} | "
                  f"{fmt(x[1])} ({x[3]}) | {fmt(x[2])} ({x[4]}) | {x[0]:.3f}{mark} |")


if __name__ == "__main__":
    main()
