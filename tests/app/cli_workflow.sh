#!/bin/sh
# The database-centred workflow end to end (docs/workflow.md): two simulated batches with the same
# numbering under different prefixes, one import, autolabel, train from the database, list and
# export the model, classify a run file with the exported model and a stored run with the stored
# model, sweep, list the sweep, report it in three formats, delete the model. Also: an unwritable
# --out fails before training and stores no model.
#   tests/app/cli_workflow.sh TACTILE WORKDIR
. "$(dirname "$0")/cli_test_lib.sh"
command -v python3 > /dev/null || fail "python3 is needed to read the JSON output"

"$T" simulate --scene room1 --runs 4 --steps 300 --out-dir b1 --prefix room1 --quiet > /dev/null
"$T" simulate --scene chapter5 --runs 4 --steps 300 --out-dir b2 --prefix ch5 --quiet > /dev/null
[ -f b1/room1_0000.csv ] && [ -f b2/ch5_0003.csv ] || fail "simulated files: $(ls b1 b2)"

# Progress to a file (not a terminal): whole lines, one at each tenth of the way and the last.
"$T" simulate --scene room1 --runs 20 --steps 20 --out-dir b3 > /dev/null 2> progress.err ||
  fail "simulate with progress exited $?"
! grep -q "$(printf '\r')" progress.err || fail "progress to a file has carriage returns"
[ "$(tail -n 1 progress.err)" = "simulate: 20/20 runs" ] || fail "progress: $(cat progress.err)"
[ "$(grep -c '^simulate: [0-9]*/20 runs$' progress.err)" -eq 10 ] || fail "progress: $(cat progress.err)"

"$T" import --db w.db b1 b2 > import.out || fail "import exited $?"
grep -q "8 imported, 0 skipped, 0 failed" import.out || fail "import: $(cat import.out)"
"$T" autolabel --db w.db --all --set truth > autolabel.out || fail "autolabel exited $?"
[ "$(grep -c "labelled run" autolabel.out)" -eq 8 ] || fail "autolabel: $(cat autolabel.out)"

# Train from the database: every fourth run by name is held out.
"$T" train --db w.db --set truth --name wf --json > train.json 2> train.err ||
  fail "train exited $?: $(cat train.err)"
python3 - train.json << 'EOF' || fail "train --json: $(cat train.json)"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["model"] == "wf", d["model"]
assert d["label_set"] == "truth"
assert d["split"] == "by-run"
assert d["evaluated_on"] == "test runs", d["evaluated_on"]
assert d["test_runs"] == ["ch5_0003", "room1_0003"], d["test_runs"]
assert not set(d["train_runs"]) & set(d["test_runs"])
assert len(d["train_runs"]) == 6, d["train_runs"]
assert len(d["groups"]) == 8
trained = 0
for g in d["groups"]:
    for key in ("group", "trained", "samples_train", "samples_test"):
        assert key in g, (key, g)
    if g["trained"]:
        trained += 1
        for key in ("accuracy", "balanced_accuracy"):
            assert key in g, (key, g)
            assert g[key] is None or 0.0 <= g[key] <= 1.0, g
    else:
        assert "labelled contact rows" in g["skipped"] or "classes" in g["skipped"], g
assert trained >= 2, trained
assert any(g["trained"] and g["samples_test"] > 0 and g["accuracy"] is not None
           for g in d["groups"])
EOF

"$T" models list --db w.db --json > models.json || fail "models list exited $?"
python3 -c "
import json, sys
m = json.load(open('models.json'))['models']
assert [x['name'] for x in m] == ['wf'], m
assert m[0]['label_set'] == 'truth', m
assert len(m[0]['train_runs']) == 6, m
" || fail "models list: $(cat models.json)"

# The exported model classifies a run file; the stored one a stored run.
"$T" models export --db w.db wf --out wf.json > /dev/null || fail "models export exited $?"
[ -s wf.json ] || fail "models export wrote nothing"
grep -q '"format": *"tactile-model-bundle"' wf.json || fail "exported model: $(head -3 wf.json)"
"$T" classify --model wf.json --run b1/room1_0001.csv --out file.csv 2> /dev/null ||
  fail "classify with the exported model exited $?"
steps=$(grep -v '^#' b1/room1_0001.csv | tail -n +2 | wc -l)
[ "$(($(wc -l < file.csv) - 1))" -eq $((steps * 8)) ] ||
  fail "classify file: $(wc -l < file.csv) lines for $steps steps"
"$T" classify --db w.db --model wf --run room1_0001 --out db.csv 2> /dev/null ||
  fail "classify --db exited $?"
[ "$(($(wc -l < db.csv) - 1))" -eq $((steps * 8)) ] ||
  fail "classify --db: $(wc -l < db.csv) lines for $steps steps"
head -1 db.csv | grep -q '^step,group,class,no_contact_rule' || fail "classify header"
cmp -s file.csv db.csv || fail "the exported and the stored model classify differently"
# Each contact step's log-likelihoods, in the CSV and in the JSON, are that step's own: with the
# model's log priors their argmax is the step's per-step class.
"$T" classify --model wf.json --run b1/room1_0001.csv --json --out file.json > /dev/null \
  2> /dev/null || fail "classify --json exited $?"
python3 - wf.json file.csv file.json << 'EOF' || fail "classify's log-likelihoods are not their steps'"
import csv, json, sys
models = {m["group"]: m for m in json.load(open(sys.argv[1]))["models"]}
def best(group, values):  # a log-likelihood of -inf is written empty (CSV) or null (JSON)
    values = [float("-inf") if v in ("", None) else float(v) for v in values]
    m = models[group]
    return max(range(len(m["classes"])), key=lambda k: (values[k] + m["priors"][k], -k))
contact = 0
for row in csv.DictReader(open(sys.argv[2])):
    if row["no_contact_rule"] == "1" or row["group"] not in models:
        continue
    m = models[row["group"]]
    values = [row["loglik_" + c] for c in m["classes"]]
    assert m["classes"][best(row["group"], values)] == row["step_class"], row
    contact += 1
doc = json.load(open(sys.argv[3]))
for group, g in doc["groups"].items():
    if not g["model"]:
        continue
    names = models[group]["classes"]
    for t, rule in enumerate(g["no_contact_rule"]):
        values = [g["loglik"][c][t] for c in names]
        if rule:
            assert all(v is None for v in values), (group, t)
            continue
        assert names[best(group, values)] == g["step_class"][t], (group, t)
assert contact > 0, "no contact step"
EOF

# A sweep over stored runs, listed and reported.
"$T" sweep --db w.db --set truth --train-runs room1_0000 room1_0001 ch5_0000 \
  --test-runs room1_0002 ch5_0001 --groups F,R --orders 1,2 --covs nodal-diag --floors 0.01,0.1 \
  --max-iter 20 --json > sweep.json 2> sweep.err || fail "sweep exited $?: $(cat sweep.err)"
id=$(python3 -c "
import json
d = json.load(open('sweep.json'))
assert isinstance(d['sweep'], int) and d['sweep'] > 0, d
assert isinstance(d['cells'], list) and len(d['cells']) == 8, len(d['cells'])
print(d['sweep'])
") || fail "sweep --json: $(head -c 300 sweep.json)"
"$T" sweeps list --db w.db --json > sweeps.json || fail "sweeps list exited $?"
python3 -c "
import json
s = json.load(open('sweeps.json'))['sweeps']
assert [(x['id'], x['cells'], x['state']) for x in s] == [($id, 8, 'finished')], s
" || fail "sweeps list: $(cat sweeps.json)"
for f in md csv html; do
  "$T" report --db w.db --sweep "$id" --format $f --out report.$f || fail "report $f exited $?"
  [ -s report.$f ] || fail "report $f is empty"
done
head -1 report.md | grep -q '^# ' || fail "report md: $(head -1 report.md)"
grep -q '^group,features,method' report.csv || fail "report csv: $(head -3 report.csv)"
head -1 report.html | grep -qi '<!DOCTYPE html>' || fail "report html: $(head -1 report.html)"
# --json: the report goes to --out, stdout gets one summary object naming it.
"$T" report --db w.db --sweep "$id" --format md --out again.md --json > report.json ||
  fail "report --json exited $?"
python3 -c "
import json, sys
d = json.load(open('report.json'))
assert d['sweep'] == $id and d['out'] == 'again.md' and d['format'] == 'md' and d['cells'] > 0, d
" || fail "report --json: $(cat report.json)"
# Markdown figures are written beside the report, in "<stem>_files", and linked from it.
for f in rate_floor rate_order time_error; do
  grep -q "](report_files/$f.svg)" report.md || fail "report.md does not link $f.svg"
  head -c 200 report_files/$f.svg | grep -q "<svg" || fail "report_files/$f.svg is not SVG"
  [ -s again_files/$f.svg ] || fail "again_files/$f.svg missing"
done
sed 's/again_files/report_files/g' again.md | cmp -s - report.md ||
  fail "report --json wrote a different report"
grep -q "<svg" report.html || fail "report.html has no inline figure"

# The model of a sweep cell (the best one that has a model) scores as the cell did.
cell=$(python3 -c "
import json
cells = json.load(open('sweep.json'))['cells']
ok = [i for i, c in enumerate(cells) if c.get('balanced_accuracy') is not None and len(c['classes']) > 1]
assert ok, cells
print(max(ok, key=lambda i: cells[i]['balanced_accuracy']))
") || fail "no sweep cell with a model"
"$T" models from-sweep --db w.db --sweep "$id" --cell "$cell" --name fromcell --out cell.json \
  --json > fromcell.json || fail "models from-sweep exited $?"
python3 -c "
import json
d = json.load(open('fromcell.json'))
c = json.load(open('sweep.json'))['cells'][$cell]
assert d['model'] == 'fromcell' and d['cell'] == $cell and d['group'] == c['group'], (d, c)
assert abs(d['balanced_accuracy'] - c['balanced_accuracy']) < 1e-12, (d, c)
m = json.load(open('cell.json'))
assert m['format'].startswith('tactile-model') and len(m['models']) == 1, m.keys()
" || fail "from-sweep: $(cat fromcell.json)"
if "$T" models from-sweep --db w.db --sweep "$id" --cell 999 2> nocell.err > /dev/null; then
  fail "from-sweep of a missing cell succeeded"
fi
grep -q "no cell 999" nocell.err || fail "from-sweep message: $(cat nocell.err)"
"$T" models delete --db w.db fromcell > /dev/null || fail "models delete fromcell exited $?"

# A run both trained and scored on is refused; no sweep is stored.
if "$T" sweep --db w.db --set truth --train-runs room1_0000,room1_0001 --test-runs room1_0001 \
  --groups F --orders 1 --covs nodal-diag --floors 0.01 2> both.err > /dev/null; then
  fail "a sweep with a run in both lists succeeded"
fi
grep -q "room1_0001" both.err || fail "sweep message: $(cat both.err)"
[ "$("$T" sweeps list --db w.db --json | grep -o "\"id\":" | wc -l)" -eq 1 ] ||
  fail "a refused sweep was stored: $("$T" sweeps list --db w.db --json)"

# An unwritable --out is found before training: nothing is stored.
if "$T" train --db w.db --set truth --name never --out "$W/no/such/dir/m.json" 2> out.err; then
  fail "train with an unwritable --out succeeded"
fi
grep -q "no/such/dir" out.err || fail "unwritable --out message: $(cat out.err)"
"$T" models list --db w.db --json | grep -q '"never"' && fail "a model was stored"

# Deleting the model.
"$T" models delete --db w.db wf > /dev/null || fail "models delete exited $?"
"$T" models list --db w.db --json > after.json || fail "models list exited $?"
grep -q '"models":\[\]' after.json || fail "model still listed: $(cat after.json)"
echo "ok"
