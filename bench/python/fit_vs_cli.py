#!/usr/bin/env python3
"""GmmClassifier.fit against `tactile fit` on the same feature table and settings, one core.

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/python/fit_vs_cli.py build/app/tactile
       [ROUNDS] [ROWS]

Writes the data set of `tactile bench learn` (D = 10, 3 classes) to a temporary folder, then
alternates, ROUNDS times: `tactile fit --threads 1 --json` (its fit_s, the fits alone; its train_s,
from the table in memory to the classifier: the rows split by class, the fits and the checks after
them, the same work as the Python call; and the whole process's wall time) and GmmClassifier(n_jobs=1).fit in this process (wall time of the call,
and the core's own fit time). Prints the medians, and checks that both give the same test
confusion matrix."""
import json
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np
import pandas as pd

import tactile

cli = sys.argv[1]
rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 5
rows = int(sys.argv[3]) if len(sys.argv) > 3 else 100000
settings = dict(order=16, cov="nodal-diag", floor=0.01, seed=1, max_iter=100, tol=1e-3)

with tempfile.TemporaryDirectory() as work:
    train, test = work + "/train.csv", work + "/test.csv"
    subprocess.run([cli, "bench", "learn", "--rows", str(rows), "--write-train", train,
                    "--write-test", test], check=True, capture_output=True)
    read = dict(float_precision="round_trip")
    t, u = pd.read_csv(train, **read), pd.read_csv(test, **read)
    X, y = t.drop(columns="label").to_numpy(), t["label"].astype(str).to_numpy()
    Xt, yt = u.drop(columns="label").to_numpy(), u["label"].astype(str).to_numpy()
    cli_fit, cli_train, cli_wall, py_wall, py_core = [], [], [], [], []
    for _ in range(rounds):
        started = time.perf_counter()
        out = subprocess.run([cli, "fit", "--train", train, "--test", test, "--threads", "1",
                              "--order", str(settings["order"]), "--cov", settings["cov"],
                              "--floor", str(settings["floor"]), "--seed", str(settings["seed"]),
                              "--max-iter", str(settings["max_iter"]),
                              "--tol", str(settings["tol"]), "--json"],
                             check=True, capture_output=True, text=True)
        cli_wall.append(time.perf_counter() - started)
        report = json.loads(out.stdout)
        cli_fit.append(report["fit_s"])
        cli_train.append(report["train_s"])
        clf = tactile.GmmClassifier(n_components=settings["order"],
                                    covariance_type=settings["cov"],
                                    variance_floor=settings["floor"],
                                    random_state=settings["seed"], max_iter=settings["max_iter"],
                                    tol=settings["tol"], n_jobs=1)
        started = time.perf_counter()
        clf.fit(X, y)
        py_wall.append(time.perf_counter() - started)
        py_core.append(clf.fit_seconds_)
    predicted = clf.predict(Xt)
    classes = report["classes"]
    confusion = [[int(np.sum((yt == a) & (predicted == b))) for b in classes] for a in classes]
    same = confusion == report["confusion"]
    med = statistics.median
    print("rows %d, D 10, 3 classes, order %d %s, floor %g, one thread, %d rounds"
          % (rows, settings["order"], settings["cov"], settings["floor"], rounds))
    print("tactile fit: fit_s median %.3f s %s; train_s (rows split by class, fits, checks) "
          "median %.3f s %s; process wall median %.3f s"
          % (med(cli_fit), [round(v, 3) for v in cli_fit], med(cli_train),
             [round(v, 3) for v in cli_train], med(cli_wall)))
    print("GmmClassifier.fit: wall median %.3f s %s; core fit time median %.3f s"
          % (med(py_wall), [round(v, 3) for v in py_wall], med(py_core)))
    print("ratio (GmmClassifier.fit wall / tactile fit fit_s): %.3f" % (med(py_wall) / med(cli_fit)))
    print("ratio (GmmClassifier.fit wall / tactile fit train_s, the same work from a table in "
          "memory): %.3f" % (med(py_wall) / med(cli_train)))
    print("same test confusion as tactile fit: %s" % same)
    sys.exit(0 if same else 1)
