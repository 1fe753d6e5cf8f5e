#!/usr/bin/env python3
"""Scores of bench/learning/extras_choice.sh: per group, score (recipe folds, office folds).

    bench/learning/extras_choice.py [--decision online|offline|step] OUT NAME ...

The two recipe folds' confusions are summed; the office runs are one test set. Each side's balanced accuracy is taken over the classes with at least 30 test steps (a
side with fewer than two such classes is left out); the score is the mean of the two sides. Per
NAME, the median over the fit seeds found in OUT (its recipe and office figures are the median
fit's).
"""
import glob
import json
import sys

GROUPS = ["F", "FLC", "L", "RLC", "B", "RRC", "R", "FRC"]


def confusion(path, group, decision):
    for m in json.load(open(path))["models"]:
        if m["group"] == group and "by_decision" in m["metrics"]:
            c = m["metrics"]["by_decision"][decision]["confusion"]
            return c["classes"], c["counts"]
    return None


def summed(a, b):
    if a is None or b is None:
        return a or b
    return a[0], [[x + y for x, y in zip(r, s)] for r, s in zip(a[1], b[1])]


def balanced(c, min_steps=30):
    if c is None:
        return None
    _, n = c
    recalls = [n[i][i] / sum(n[i]) for i in range(len(n)) if sum(n[i]) >= min_steps]
    return sum(recalls) / len(recalls) if len(recalls) >= 2 else None


def main():
    args = sys.argv[1:]
    decision = "online"
    if args[:1] == ["--decision"]:
        decision, args = args[1], args[2:]
    if len(args) < 2:
        sys.exit(__doc__)
    out, names = args[0], args[1:]
    print("| set (fit seeds) | " + " | ".join(GROUPS) + " |")
    print("|---" * (len(GROUPS) + 1) + "|")
    for name in names:
        seeds = sorted(p.split("_")[-1].split(".")[0] for p in glob.glob(f"{out}/{name}_*.of.json"))
        cells = []
        for g in GROUPS:
            fits = []
            for s in seeds:
                base = f"{out}/{name}_{s}"
                recipe = balanced(summed(confusion(base + ".r1.json", g, decision),
                                         confusion(base + ".r2.json", g, decision)))
                office = balanced(confusion(base + ".of.json", g, decision))
                sides = [x for x in (recipe, office) if x is not None]
                if sides:
                    fits.append((sum(sides) / len(sides), recipe, office))
            if not fits:
                cells.append("no test data")
                continue
            fits.sort(key=lambda f: f[0])
            score, recipe, office = fits[len(fits) // 2]
            side = lambda x: "-" if x is None else f"{x:.3f}"
            cells.append(f"{score:.3f} ({side(recipe)}, {side(office)})")
        print(f"| {name} ({len(seeds)}) | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
