"""Tactile Workbench in Python: run databases, labels, features, training, sweeps and
scikit-learn estimators over the product's own core (docs/python.md).

    import tactile
    db = tactile.open("work.db")
    db.runs()                      # a pandas DataFrame (a list of dicts without pandas)
    run = db.run("room1_0000")     # numpy arrays: run.normal, run.shear, run.pose, ...
    result = tactile.train(db, set="truth")
    result.report                  # the dict `tactile train --json` prints
    result.model.classify(run)     # class names per group
"""

import json as _json

from . import _core
from ._core import Model, Run, contact, features, load_model
from .estimators import GaussianClassifier, GmmClassifier

__all__ = [
    "CLASSES", "GROUPS", "FEATURE_KINDS", "Database", "GaussianClassifier", "GmmClassifier",
    "Model", "Run", "TrainResult", "contact", "dataset", "features", "load_model", "open",
    "sweep", "train",
]

__version__ = _core.version

#: The contact classes; a class code is an index into this tuple.
CLASSES = ("NoContact", "Wall", "Corner", "LeavingWall", "DeadPath")
#: The sensor groups in group order (the columns of Run.truth).
GROUPS = ("F", "FLC", "L", "RLC", "B", "RRC", "R", "FRC")
#: The feature kinds of tactile.features and training.
FEATURE_KINDS = (
    "normal", "magnitude", "normal+shear", "normal+shear+touch", "normal+shear+touch+context",
    "normal+shear+touch+context+neighbours", "normal+shear+touch+motion",
    "normal+shear+touch+motion+neighbours",
)


def _table(rows, columns=None):
    """A pandas DataFrame of the rows when pandas is installed, else the list of dicts."""
    try:
        import pandas
    except ImportError:
        return rows
    return pandas.DataFrame(rows, columns=columns)


class Database:
    """One open run database (one connection: use it from one thread at a time)."""

    def __init__(self, core):
        self._db = core

    @property
    def path(self):
        return self._db.path

    def runs(self):
        """Every stored run: name, scene, steps, subject, outcome, dt, has_truth, label_sets,
        source_file, imported_at, id."""
        return _table(self._db.runs(), ["name", "scene", "steps", "subject", "outcome", "dt",
                                        "has_truth", "label_sets", "source_file", "imported_at",
                                        "id"])

    def run(self, name):
        """The run as numpy arrays (tactile.Run): normal, shear (steps x 44), pose (steps x 3),
        command (steps x 2), blocked, truth (steps x 8 or None), dt, metadata."""
        return self._db.run(name)

    def label_sets(self):
        return _table(self._db.label_sets(), ["name", "annotator", "segments", "created_at",
                                              "runs"])

    def labels(self, set, run):
        """A run's labels in a label set: {"classes": {group: int8 array of class codes per
        step, -1 where no label}, "segments": the segments (id, group, first_step, last_step,
        class, annotator)}."""
        out = self._db.labels(set, run)
        out["segments"] = _table(out["segments"], ["id", "group", "first_step", "last_step",
                                                   "class", "annotator"])
        return out

    def set_labels(self, set, run, segments=None, *, group=None, first_step=None,
                   last_step=None, cls=None, annotator=None):
        """Adds label segments to a set (created when absent), each one committed edit through
        the workbench's own call: the newest segment wins where it overlaps older ones.

        segments: (group, first_step, last_step, class) tuples, dicts or a DataFrame with those
        columns ("class" a name or a code); or one segment by keywords. annotator: stored with
        each segment (default: the set's annotator). Returns the new segments' ids."""
        if segments is None:
            segments = [(group, first_step, last_step, cls)]
        elif hasattr(segments, "to_dict"):
            segments = segments.to_dict("records")
        rows = []
        for s in segments:
            if isinstance(s, dict):
                s = (s["group"], s["first_step"], s["last_step"],
                     s["class"] if "class" in s else s["cls"])
            g, first, last, c = s
            if not isinstance(c, str):
                c = int(c)
            rows.append((str(g), int(first), int(last), c))
        return self._db.add_segments(set, run, rows, annotator)

    def models(self):
        return _table(self._db.models(), ["name", "id", "created_at", "trained_on", "metrics"])

    def model(self, name):
        """A stored model bundle (tactile.Model)."""
        return _core.stored_model(self._db, name)

    def sweeps(self):
        return _table(self._db.sweeps(), ["id", "name", "created_at", "cells", "configuration"])

    def close(self):
        self._db.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __repr__(self):
        return "<tactile.Database %s>" % self._db.path


def open(path, create=False, read_only=False):
    """Opens a run database: a path or sqlite:///path. A missing file raises OSError
    (FileNotFoundError) unless create=True."""
    return Database(_core.open(str(path), create=create, read_only=read_only))


def _runs_of(db, runs):
    return [r if isinstance(r, Run) else db.run(r) for r in runs]


def dataset(db, set, runs, group, kind="normal"):
    """The labelled contact rows of one group over runs (names or tactile.Run), as training sees
    them: X (rows x D), y (class codes), and each row's run index and step."""
    return _core.dataset(db._db, set, _runs_of(db, runs), group, kind)


class TrainResult:
    """What tactile.train returns: .report, the dict `tactile train --json` prints, and .model,
    the trained bundle (stored in the database under .report["model"] unless store=False)."""

    def __init__(self, report, model):
        self.report = report
        self.model = model

    def __repr__(self):
        return "<tactile.TrainResult model=%r>" % self.report.get("model")


def train(db, set, *, train_runs=None, test_runs=None, split="by-run", groups=None, name=None,
          min_rows=20, method=None, n_components=None, covariance_type=None,
          variance_floor=None, n_init=None, features=None, max_iter=None, tol=None, init=None,
          reg=None, emission_weight=None, decision="online", random_state=1, n_jobs=0,
          store=True, n_estimators=None, max_depth=None, learning_rate=None,
          min_child_weight=None):
    """Trains one model per group on a label set of the database, as `tactile train --db`:
    each group's own default settings unless given (then for every group), scored as `split`
    says, stored under `name` (default SET-N). method="gbt" trains boosted trees, with
    n_estimators, max_depth, learning_rate and min_child_weight as XGBoost names them."""
    a = _core.TrainArgs()
    a.set = set
    a.train_runs = list(train_runs or [])
    a.test_runs = list(test_runs or [])
    a.groups = list(groups or [])
    a.split = split
    a.name = name or ""
    a.min_rows = int(min_rows)
    a.method = method
    a.n_components = n_components
    a.covariance_type = covariance_type
    a.variance_floor = variance_floor
    a.n_init = n_init
    a.features = features
    a.max_iter = max_iter
    a.tol = tol
    a.init = init
    a.reg = reg
    a.emission_weight = emission_weight
    a.decision = decision
    a.seed = int(1 if random_state is None else random_state)
    a.n_jobs = int(n_jobs)
    a.store = bool(store)
    a.n_estimators = n_estimators
    a.max_depth = max_depth
    a.learning_rate = learning_rate
    a.min_child_weight = min_child_weight
    report, model = _core.train(db._db, a)
    return TrainResult(_json.loads(report), model)


def sweep(db, set, *, train_runs, test_runs=None, split="by-run", groups=None,
          methods=("gmm",), orders=(1, 2, 4, 8, 16, 32, 64),
          covariance_types=("nodal-full", "nodal-diag", "grand-full", "grand-diag"),
          variance_floors=(0.01, 0.03, 0.1), features=("normal",), seeds=(1,),
          decisions=("step",), reg="floor", init="kmeans++", n_init=1, max_iter=100, tol=1e-3,
          name=None, n_jobs=0, detail=False, n_estimators=(100,), max_depths=(6,),
          learning_rates=(0.1,), min_child_weights=(1.0,)):
    """Trains and scores a grid of classifiers on stored runs, as `tactile sweep --db`, and
    stores every cell. Returns a DataFrame with one row per cell (settings, balanced accuracy,
    accuracy, macro F1, fit time, ...); detail=True keeps the confusion matrices and patterns.
    The sweep's id is in the frame's attrs["sweep"] (a list of dicts without pandas).
    methods may name "gbt" (boosted trees), whose cells sweep n_estimators x max_depths x
    learning_rates x min_child_weights."""
    a = _core.SweepArgs()
    a.set = set
    a.train_runs = list(train_runs)
    a.test_runs = list(test_runs or [])
    a.split = split
    a.groups = list(groups or [])
    a.methods = list(methods)
    a.orders = [int(k) for k in orders]
    a.covariance_types = list(covariance_types)
    a.variance_floors = [float(f) for f in variance_floors]
    a.n_estimators = [int(k) for k in n_estimators]
    a.max_depths = [int(k) for k in max_depths]
    a.learning_rates = [float(r) for r in learning_rates]
    a.min_child_weights = [float(w) for w in min_child_weights]
    a.features = list(features)
    a.seeds = [int(s) for s in seeds]
    a.decisions = list(decisions)
    a.reg = reg
    a.init = init
    a.n_init = int(n_init)
    a.max_iter = int(max_iter)
    a.tol = float(tol)
    a.name = name or ""
    a.n_jobs = int(n_jobs)
    sweep_id, cells, cancelled, wall = _core.sweep(db._db, a)
    rows = []
    for text in cells:
        cell = _json.loads(text)
        if not detail:
            for key in ("confusion", "patterns", "scenes", "rates", "test_steps"):
                cell.pop(key, None)
        rows.append(cell)
    table = _table(rows)
    if hasattr(table, "attrs"):
        table.attrs["sweep"] = sweep_id
        table.attrs["wall_s"] = wall
        table.attrs["cancelled"] = cancelled
    return table
