#!/usr/bin/env python3
"""How often a corpus shows the situations driving shows most (docs/learning.md#what-stays-confused-and-why).

    bench/learning/recipe_gap.py RUN_DIR [RUN_DIR ...]

For the runs (tactile-run CSV files) in each folder: F's Corner and Wall steps while the commanded
turn is faster than 0.4 rad/s, and L's and R's LeavingWall and Corner steps at a commanded speed
of 25 units/s or more, as counts of the class's steps (the truth columns), per folder and, for
the training recipe's runs, per run (its `plan` metadata names the kind).
"""
import csv
import glob
import os
import sys

GROUPS = ["F", "FLC", "L", "RLC", "B", "RRC", "R", "FRC"]
CHECKS = [("F", "Corner", "turn", "|omega| > 0.4"), ("F", "Wall", "turn", "|omega| > 0.4"),
          ("L", "LeavingWall", "fast", "v >= 25"), ("R", "LeavingWall", "fast", "v >= 25"),
          ("L", "Corner", "fast", "v >= 25"), ("R", "Corner", "fast", "v >= 25")]


def rows(path):
    kind = ""
    body = []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                if line.startswith("# plan:"):
                    kind = " ".join(line.split()[2:])
                continue
            body.append(line)
    reader = csv.reader(body)
    header = next(reader)
    v, omega, truth = header.index("v"), header.index("omega"), len(header) - len(GROUPS)
    for r in reader:
        yield kind, abs(float(r[v])), abs(float(r[omega])), r[truth:]


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(sys.argv) > 1 else 2
    for folder in sys.argv[1:]:
        files = sorted(glob.glob(os.path.join(folder, "*.csv")))
        if not files:
            print(f"recipe_gap.py: {folder}: no run files", file=sys.stderr)
            return 1
        counts = {}
        for path in files:
            for kind, v, w, truth in rows(path):
                for g, cls, test, _ in CHECKS:
                    if truth[GROUPS.index(g)] != cls:
                        continue
                    hit = w > 0.4 if test == "turn" else v >= 25.0
                    for key in ((g, cls, ""), (g, cls, kind or os.path.basename(path))):
                        n, k = counts.get(key, (0, 0))
                        counts[key] = (n + 1, k + hit)
        print(f"== {folder} ({len(files)} runs)")
        for g, cls, _, name in CHECKS:
            n, k = counts.get((g, cls, ""), (0, 0))
            share = f"{100.0 * k / n:.0f}%" if n else "no steps"
            per = ", ".join(f"{key[2]} {c[1]}/{c[0]}" for key, c in sorted(counts.items())
                            if key[0] == g and key[1] == cls and key[2])
            print(f"{g} {cls} at {name}: {k} of {n} ({share})  [{per}]")
    return 0


if __name__ == "__main__":
    sys.exit(main())
