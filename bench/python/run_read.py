#!/usr/bin/env python3
"""db.run(name) of a long run: the time to have its arrays in hand.

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/python/run_read.py DB [RUN] [ROUNDS]
           [CALLS] [--against PYTHONPATH]

DB is a run database holding RUN (default "big": `tactile bench storage --steps 1000 --files 1
--big-steps 1000000 --repeats 1 --dir W --keep --no-compare --json` leaves one in W/bench.db).
Each round is a fresh Python process that opens DB and calls db.run(RUN) CALLS times (default 3),
taking normal, shear, pose, command, blocked and truth each time; the first call of a process
also maps the database file. With --against, every round runs a second process whose PYTHONPATH is
the given folder (another build's python/ folder, e.g. the one before a change), so both are timed
on the same machine state, alternately. Prints every call's seconds and the medians."""
import json
import os
import statistics
import subprocess
import sys

CHILD = r"""
import json, sys, time
import tactile
db = tactile.open(sys.argv[1], read_only=True)
times = []
for _ in range(int(sys.argv[3])):
    started = time.perf_counter()
    run = db.run(sys.argv[2])
    arrays = (run.normal, run.shear, run.pose, run.command, run.blocked, run.truth)
    times.append(time.perf_counter() - started)
    steps = run.steps
    del run, arrays
print(json.dumps({"module": tactile.__file__, "steps": steps, "times": times}))
"""


def main():
    args = sys.argv[1:]
    against = None
    if "--against" in args:
        i = args.index("--against")
        against = args[i + 1]
        del args[i:i + 2]
    db = args[0]
    run = args[1] if len(args) > 1 else "big"
    rounds = int(args[2]) if len(args) > 2 else 5
    calls = int(args[3]) if len(args) > 3 else 3
    paths = {"this": os.environ.get("PYTHONPATH", "")}
    if against:
        paths["against"] = against
    times = {k: [] for k in paths}
    for _ in range(rounds):
        for name, path in paths.items():
            env = dict(os.environ, PYTHONPATH=path)
            out = subprocess.run([sys.executable, "-c", CHILD, db, run, str(calls)], env=env,
                                 check=True, capture_output=True, text=True)
            result = json.loads(out.stdout)
            times[name].extend(result["times"])
            print("%-8s %s: %s" % (name, result["module"],
                                   " ".join("%.3f" % t for t in result["times"])), flush=True)
    for name, values in times.items():
        print("%s: median %.3f s of %d calls (%d steps)"
              % (name, statistics.median(values), len(values), result["steps"]))


if __name__ == "__main__":
    main()
