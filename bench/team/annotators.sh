#!/bin/sh
# Annotators side by side: PROCS processes, each making EDITS label edits on the same runs of one
# database the way a person does (read the run's newest revision, then an edit based on it), then
# checks that no edit was lost: every edit reported stored is in the history with its revision,
# every refused one was reported as refused, nothing else failed, and the stored labels are
# exactly what replaying the history gives.
#   bench/team/annotators.sh TACTILE DB PROCS EDITS WORKDIR
# THINK (seconds, default 0.05) is the pause between reading the revision and the edit.
# DB is a file or a PostgreSQL address holding runs run_0000 and run_0001; the script labels them
# in the label set $SET (default "crowd"), which should not exist yet. Prints one JSON line:
# {"procs","edits","stored","refused","failed","history","lost","mismatched_steps","seconds"};
# exits 1 when anything was lost.
set -eu
T=$1 DB=$2 PROCS=$3 EDITS=$4 W=$5
SET=${SET:-crowd}
mkdir -p "$W"
rm -f "$W"/annotator*.log
"$T" labels set --db "$DB" --set "$SET" --run run_0000 --groups F --steps 0 --class NoContact \
  --annotator setup > /dev/null
start=$(date +%s.%N)
p=0
while [ "$p" -lt "$PROCS" ]; do
  (
    i=0
    log="$W/annotator$p.log"
    while [ "$i" -lt "$EDITS" ]; do
      run=run_000$(( (p + i) % 2 ))
      groups=$(echo "F L R FLC" | cut -d' ' -f$(( (i % 4) + 1 )))
      first=$(( ($(od -An -N2 -tu2 /dev/urandom) % 60) ))
      last=$(( first + ($(od -An -N1 -tu1 /dev/urandom) % 10) ))
      cls=$(echo "Wall Corner LeavingWall DeadPath NoContact" | cut -d' ' -f$(( (i % 5) + 1 )))
      rev=$("$T" labels history --db "$DB" --set "$SET" --run "$run" --json |
        sed -n 's/.*"revision":\([0-9]*\),"revisions".*/\1/p')
      # A person looks at the run before editing it; others edit meanwhile.
      sleep "${THINK:-0.05}"
      if out=$("$T" labels set --db "$DB" --set "$SET" --run "$run" --groups "$groups" \
        --steps "$first-$last" --class "$cls" --annotator "a$p" --expect-revision "${rev:-0}" \
        --json 2> "$W/err$p.txt"); then
        echo "stored $(echo "$out" | sed -n 's/.*"revision":\([0-9]*\).*/\1/p')" >> "$log"
      elif grep -q "not stored: steps" "$W/err$p.txt"; then
        echo "refused" >> "$log"
      else
        echo "failed $(tr '\n' ' ' < "$W/err$p.txt")" >> "$log"
      fi
      i=$((i + 1))
    done
  ) &
  p=$((p + 1))
done
wait
end=$(date +%s.%N)
for run in run_0000 run_0001; do
  "$T" labels history --db "$DB" --set "$SET" --run "$run" --json > "$W/history_$run.json"
done
"$T" labels export --db "$DB" --set "$SET" "$W/labels.csv" > /dev/null
/usr/bin/python3 - "$W" "$PROCS" "$EDITS" "$start" "$end" <<'PY'
import csv, glob, json, sys
w, procs, edits, start, end = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
stored, refused, failed = set(), 0, []
for log in glob.glob(w + "/annotator*.log"):
    for line in open(log):
        word, _, rest = line.strip().partition(" ")
        if word == "stored": stored.add(int(rest))
        elif word == "refused": refused += 1
        else: failed.append(rest)
history, state = {}, {}
for run in ("run_0000", "run_0001"):
    for r in json.load(open(f"{w}/history_{run}.json"))["revisions"]:
        history[r["revision"]] = r
        cells = state.setdefault((run, r["group"]), {})
        for s in range(r["first_step"], r["last_step"] + 1):
            if r["class"] is None: cells.pop(s, None)
            else: cells[s] = r["class"]
exported = {}
for row in csv.reader(line for line in open(w + "/labels.csv") if not line.startswith("#")):
    if row[0] == "run": continue
    cells = exported.setdefault((row[0], row[1]), {})
    for s in range(int(row[2]), int(row[3]) + 1): cells[s] = row[4]
mismatched = sum(1 for key in set(state) | set(exported)
                 for s in set(state.get(key, {})) | set(exported.get(key, {}))
                 if state.get(key, {}).get(s) != exported.get(key, {}).get(s))
sets = {k for k, r in history.items() if r["annotator"] != "setup"}
# A stored edit of several groups made one revision per group; the last is reported.
lost = len([r for r in stored if r not in history])
out = {"procs": procs, "edits": procs * edits, "stored": len(stored), "refused": refused,
       "failed": len(failed), "history": len(sets), "lost": lost,
       "mismatched_steps": mismatched, "seconds": round(end - start, 2)}
print(json.dumps(out))
if failed: print("failures: " + "; ".join(failed[:3]), file=sys.stderr)
sys.exit(0 if lost == 0 and not failed and mismatched == 0 and
         len(stored) + refused == procs * edits and len(sets) == len(stored) else 1)
PY
