#!/usr/bin/env python3
"""Side-by-side EM fit time and held-out log-likelihood: scikit-learn's GaussianMixture against
`tactile fit`, on the same generated data and the same settings, in one run.

Usage (from the repository root, after building):
    /usr/bin/python3 bench/analysis/sklearn_compare.py --tactile build/app/tactile [--reps 3]
        [--tactile OTHER_BUILD/app/tactile ...] [--kernel-isa x86-64-v3,x86-64-v4]

Settings shared by both sides: reg_covar = --floor with `--reg add`, tol 1e-3 on the change of
the mean log-likelihood per sample (`--tol-rule absolute`, scikit-learn's rule), max_iter 100,
one initialisation by k-means++ (scikit-learn: init_params='k-means++', seeding only; tactile:
k-means++ seeding then Lloyd iterations, --kmeans-iter), 2 cores each (scikit-learn:
OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=2; tactile: --threads 2). Each repetition uses seed
1, 2, ... on both sides; the script reports medians and ratios.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

# The BLAS/OpenMP thread counts must be fixed before numpy loads.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "2")

import numpy as np  # noqa: E402
import sklearn  # noqa: E402
from sklearn.mixture import GaussianMixture  # noqa: E402
from threadpoolctl import threadpool_info  # noqa: E402


def load_table(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    d = len(header) - 1
    return np.loadtxt(path, delimiter=",", skiprows=1, usecols=range(d), dtype=np.float64)


def run_tactile(binary, isa, train, test, form, order, seed, args):
    cmd = [binary, "fit", "--train", train, "--test", test, "--method", "gmm",
           "--order", str(order), "--cov", form, "--floor", repr(args.floor),
           "--reg", "add", "--init", "kmeans++", "--tol", "1e-3", "--tol-rule", "absolute",
           "--max-iter", "100", "--restarts", "1", "--seed", str(seed),
           "--threads", str(args.threads), "--json"]
    env = dict(os.environ)
    if isa:
        env["TACTILE_KERNEL_ISA"] = isa
    else:
        env.pop("TACTILE_KERNEL_ISA", None)
    out = subprocess.run(cmd, check=True, capture_output=True, text=True, env=env).stdout
    return json.loads(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tactile", required=True, action="append",
                    help="path to a tactile executable; repeat to compare several builds "
                         "against the same scikit-learn fits")
    ap.add_argument("--kernel-isa", default="",
                    help="comma-separated kernel levels to run each build under "
                         "(TACTILE_KERNEL_ISA, e.g. x86-64-v3 to stand in for an AVX2 machine); "
                         "empty = the build's own choice")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--rows", type=int, default=100000)
    ap.add_argument("--test-rows", type=int, default=20000)
    ap.add_argument("--dim", type=int, default=10)
    ap.add_argument("--floor", type=float, default=0.01, help="reg_covar = tactile --floor with --reg add")
    ap.add_argument("--cases", default="nodal-diag:16,nodal-full:16,nodal-diag:64,nodal-full:64")
    ap.add_argument("--threads", type=int, default=2, help="tactile --threads")
    ap.add_argument("--workdir", default=None)
    args = ap.parse_args()

    print("scikit-learn", sklearn.__version__, "numpy", np.__version__)
    print("OPENBLAS_NUM_THREADS=%s OMP_NUM_THREADS=%s" % (os.environ["OPENBLAS_NUM_THREADS"],
                                                          os.environ["OMP_NUM_THREADS"]))
    print("threadpoolctl threadpool_info():")
    for info in threadpool_info():
        print("   ", info)
    sys.stdout.flush()

    workdir = args.workdir or tempfile.mkdtemp(prefix="tactile-sk-")
    train = os.path.join(workdir, "train.csv")
    test = os.path.join(workdir, "test.csv")
    subprocess.run([args.tactile[0], "bench", "learn", "--classes", "1", "--rows", str(args.rows),
                    "--test-rows", str(args.test_rows), "--dim", str(args.dim),
                    "--write-train", train, "--write-test", test], check=True)
    xtrain = load_table(train)
    xtest = load_table(test)
    print("data: %d training rows, %d test rows, D = %d (one class, 8 correlated clusters)"
          % (xtrain.shape[0], xtest.shape[0], xtrain.shape[1]))

    isas = [i for i in args.kernel_isa.split(",") if i] or [""]
    variants = [(b, i) for b in args.tactile for i in isas]  # (binary, level)
    rows = []
    for case in args.cases.split(","):
        form, order = case.split(":")
        order = int(order)
        sk_type = {"nodal-diag": "diag", "nodal-full": "full", "grand-full": "tied",
                   "grand-diag": None}[form]
        sk_t, sk_ll, sk_it = [], [], []
        tw = {v: ([], [], [], "?") for v in variants}
        for rep in range(args.reps):
            seed = rep + 1
            g = GaussianMixture(n_components=order, covariance_type=sk_type, reg_covar=args.floor,
                                tol=1e-3, max_iter=100, n_init=1, init_params="k-means++",
                                random_state=seed)
            t0 = time.perf_counter()
            g.fit(xtrain)
            sk_t.append(time.perf_counter() - t0)
            sk_ll.append(float(g.score(xtest)))
            sk_it.append(int(g.n_iter_))
            line = "  %s K=%d seed %d: sklearn %.3f s (%d it, ll %.4f)" % (
                form, order, seed, sk_t[-1], sk_it[-1], sk_ll[-1])
            for v in variants:
                j = run_tactile(v[0], v[1], train, test, form, order, seed, args)
                t, ll, it, _ = tw[v]
                t.append(j["fit_s"])
                ll.append(j["mean_loglik"])
                it.append(j["iterations"])
                tw[v] = (t, ll, it, j.get("kernel_isa", "?"))
                line += " | %s: %.3f s (%d it, ll %.4f)" % (tw[v][3], t[-1], it[-1], ll[-1])
            print(line)
            sys.stdout.flush()
        for v in variants:
            t, ll, it, isa = tw[v]
            rows.append((v[0], isa, form, order, statistics.median(sk_t), statistics.median(t),
                         statistics.median(sk_ll), statistics.median(ll),
                         statistics.median(sk_it), statistics.median(it)))

    print()
    print("medians over %d repetitions (seeds 1..%d)" % (args.reps, args.reps))
    print("%-28s %-10s %-11s %5s %10s %10s %7s %11s %11s %8s %6s %6s" % (
        "tactile", "kernels", "form", "order", "sklearn_s", "tactile_s", "speedup", "sklearn_ll",
        "tactile_ll", "ll_diff", "sk_it", "tw_it"))
    ok = True
    for binary, isa, form, order, st, tt, sl, tl, si, ti in rows:
        speedup = st / tt if tt > 0 else float("inf")
        good = speedup >= 10 and tl >= sl - 0.02
        ok = ok and good
        print("%-28s %-10s %-11s %5d %10.3f %10.3f %6.1fx %11.4f %11.4f %+8.4f %6g %6g %s" % (
            binary[-28:], isa, form, order, st, tt, speedup, sl, tl, tl - sl, si, ti,
            "" if good else "  <-- target missed"))
    print("target (>= 10x faster, held-out ll >= sklearn - 0.02):", "met" if ok else "NOT met")


if __name__ == "__main__":
    main()
