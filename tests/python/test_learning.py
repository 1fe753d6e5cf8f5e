"""Learning with the product's core: train, classify, features, data sets, sweeps, model files,
each against what the CLI gives for the same database and seed."""
import json

import numpy as np
import pandas as pd
import pytest

import tactile
from conftest import run_cli


def without_times(report):
    for g in report["groups"]:
        g.pop("fit_s", None)
    return report


@pytest.fixture(scope="module")
def trained(cli, demo, tmp_path_factory):
    """The same database trained twice with seed 1: by the CLI and by tactile.train."""
    root = tmp_path_factory.mktemp("trained")
    for name in ("cli.db", "py.db"):
        (root / name).write_bytes((demo / "demo.db").read_bytes())
    cli_report = json.loads(run_cli(cli, "train", "--db", str(root / "cli.db"), "--set", "truth",
                                    "--name", "m", "--seed", "1", "--json"))
    db = tactile.open(root / "py.db")
    result = tactile.train(db, set="truth", name="m", random_state=1)
    return root, cli_report, db, result


def test_train_equals_the_cli(trained):
    _, cli_report, _, result = trained
    assert result.report["model"] == "m"
    assert any(g["trained"] for g in result.report["groups"])
    assert without_times(result.report) == without_times(cli_report)


def test_classify_equals_the_cli(cli, trained):
    root, _, db, result = trained
    test_run = result.report["test_runs"][0]
    out = root / "classes.csv"
    run_cli(cli, "classify", "--db", str(root / "cli.db"), "--model", "m", "--run", test_run,
            "--out", str(out))
    table = pd.read_csv(out, keep_default_na=False)
    run = db.run(test_run)
    for model in (result.model, db.model("m")):
        classes = model.classify(run)
        for group in tactile.GROUPS:
            expected = table[table["group"] == group].sort_values("step")["class"].to_numpy()
            assert len(expected) == run.steps
            np.testing.assert_array_equal(classes[group], expected.astype(str))
    # Some group said something other than NoContact.
    assert any((classes[g] != "NoContact").any() for g in tactile.GROUPS)


def test_estimator_predicts_as_the_trained_model(trained):
    """GmmClassifier fitted on the rows training fitted gives the stored model's step decisions."""
    _, _, db, _ = trained
    # Mixtures in every group (the defaults train trees in most groups).
    result = tactile.train(db, set="truth", name="g", method="gmm", random_state=1, store=False)
    model = result.model
    group = next(g for g in model.groups if len(g["classes"]) >= 2 and g["method"] == "gmm")
    name = group["group"]
    X, y, _, _ = tactile.dataset(db, "truth", result.report["train_runs"], name,
                                 group["features"])
    codes = [tactile.CLASSES.index(c) for c in group["classes"]]
    keep = np.isin(y, codes)
    clf = tactile.GmmClassifier(n_components=group["components"],
                                covariance_type=group["covariance"],
                                variance_floor=group["variance_floor"], n_init=3,
                                random_state=1).fit(X[keep], y[keep])
    assert list(clf.classes_) == sorted(codes)
    run = db.run(result.report["test_runs"][0])
    touching = tactile.contact(run, name)
    assert touching.any()
    rows = tactile.features(run, name, group["features"])[touching]
    predicted = np.array(tactile.CLASSES)[clf.predict(rows)]
    expected = model.classify(run, decision="step")[name][touching]
    np.testing.assert_array_equal(predicted, expected)


def test_features_are_the_groups_values(demo):
    run = tactile.open(demo / "demo.db").run("room1_0000")
    right = tactile.features(run, "R", "normal")
    assert right.shape == (run.steps, 10)
    np.testing.assert_array_equal(right, run.normal[:, 32:42])
    both = tactile.features(run, "right side", "normal+shear")
    np.testing.assert_array_equal(both[:, 1::2], run.shear[:, 32:42])
    touching = tactile.contact(run, "R")
    np.testing.assert_array_equal(touching, (run.sensors[:, 64:84] != 0).any(axis=1))
    with pytest.raises(ValueError, match="unknown group"):
        tactile.features(run, "X")


def test_model_saves_and_loads(trained, tmp_path):
    _, _, db, result = trained
    path = tmp_path / "model.json"
    result.model.save(path)
    loaded = tactile.load_model(path)
    assert loaded.groups == result.model.groups
    run = db.run("room1_0000")
    a, b = loaded.classify(run), result.model.classify(run)
    for g in tactile.GROUPS:
        np.testing.assert_array_equal(a[g], b[g])


def test_sweep_is_a_dataframe_of_stored_cells(db_copy):
    db = tactile.open(db_copy())
    before = len(db.sweeps())
    cells = tactile.sweep(db, "truth", train_runs=["room1_0000", "room1_0001", "ch5_0000"],
                          test_runs=["room1_0002", "ch5_0001"], groups=["R", "F"],
                          orders=[1, 2], covariance_types=["diag", "tied"],
                          variance_floors=[0.01], n_jobs=1)
    assert isinstance(cells, pd.DataFrame)
    assert len(cells) == 8
    assert set(cells["covariance"]) == {"nodal-diag", "grand-full"}
    assert set(cells["order"]) == {1, 2}
    scored = cells[cells["ok"]]
    assert len(scored) > 0
    assert ((scored["balanced_accuracy"] >= 0) & (scored["balanced_accuracy"] <= 1)).all()
    sweeps = db.sweeps()
    assert len(sweeps) == before + 1
    assert int(sweeps["cells"].iloc[-1]) == 8
    assert cells.attrs["sweep"] == int(sweeps["id"].iloc[-1])


def test_trees_take_their_own_features_as_the_cli(cli, demo, tmp_path):
    """method="gbt" trains each group's trees with the trees' own default features (F: the
    neighbours, its mixtures: context), rounds, depth and evidence weight, as `tactile train
    --method gbt` does for the same database and seed."""
    for name in ("cli.db", "py.db"):
        (tmp_path / name).write_bytes((demo / "demo.db").read_bytes())
    cli_report = json.loads(run_cli(cli, "train", "--db", str(tmp_path / "cli.db"), "--set",
                                    "truth", "--name", "t", "--method", "gbt", "--groups", "F",
                                    "--seed", "1", "--json"))
    result = tactile.train(tactile.open(tmp_path / "py.db"), set="truth", name="t",
                           method="gbt", groups=["F"], random_state=1)
    assert without_times(result.report) == without_times(cli_report)
    group = next(g for g in result.model.groups if g["group"] == "F")
    assert group["method"] == "gbt"
    assert group["features"] == "normal+shear+touch+context+neighbours"
    mixtures = tactile.train(tactile.open(tmp_path / "py.db"), set="truth", name="m",
                             method="gmm", groups=["F"], random_state=1, store=False)
    assert next(g for g in mixtures.model.groups
                if g["group"] == "F")["features"] == "normal+shear+touch+context"
