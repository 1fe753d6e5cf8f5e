"""Databases, runs, labels: tactile.open, Database.runs/run/labels/set_labels."""
import errno

import numpy as np
import pandas as pd
import pytest

import tactile
from conftest import run_cli


def read_run_file(path):
    """The steps and metadata of a run CSV file, read with pandas on its own."""
    meta = {}
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            key, value = line[1:].split(":", 1)
            meta[key.strip()] = value.strip()
    # round_trip: the file holds shortest round-trip decimals; pandas' fast parser can miss the
    # last bit.
    return pd.read_csv(path, comment="#", float_precision="round_trip"), meta


def test_run_arrays_equal_the_run_file(demo):
    db = tactile.open(demo / "demo.db")
    run = db.run("room1_0001")
    table, meta = read_run_file(demo / "b1" / "room1_0001.csv")
    assert run.steps == len(table) == 400
    normal = table[["n%d" % i for i in range(44)]].to_numpy()
    shear = table[["s%d" % i for i in range(44)]].to_numpy()
    assert run.normal.shape == (400, 44) and run.shear.shape == (400, 44)
    np.testing.assert_array_equal(run.normal, normal)
    np.testing.assert_array_equal(run.shear, shear)
    np.testing.assert_array_equal(run.pose, table[["x", "y", "theta"]].to_numpy())
    np.testing.assert_array_equal(run.command, table[["v", "omega"]].to_numpy())
    np.testing.assert_array_equal(run.blocked, table["blocked"].to_numpy() != 0)
    truth = table[["truth_" + g for g in tactile.GROUPS]].to_numpy()
    names = np.array(tactile.CLASSES)[run.truth]
    np.testing.assert_array_equal(names, truth)
    assert run.dt == pytest.approx(float(meta["dt"]))
    assert run.metadata["scene"] == "room1"
    # Views into the loaded run, not copies, and read-only.
    assert not run.normal.flags.writeable
    assert run.normal.base is not None


def test_a_long_run_read_on_two_threads_equals_its_file(cli, tmp_path):
    """A run long enough to be read on two connections, each stepping ranges of its steps (from
    50,000 steps), and of a length that is no multiple of those ranges: its arrays equal the run
    file's, through a read-write and a read-only opening."""
    run_cli(cli, "bench", "storage", "--steps", "100", "--files", "1", "--big-steps", "60001",
            "--repeats", "1", "--dir", str(tmp_path), "--keep", "--no-compare", "--json")
    table, _ = read_run_file(tmp_path / "big.csv")
    assert len(table) == 60001
    normal = table[["n%d" % i for i in range(44)]].to_numpy()
    shear = table[["s%d" % i for i in range(44)]].to_numpy()
    truth = table[["truth_" + g for g in tactile.GROUPS]].to_numpy()
    for read_only in (False, True):
        db = tactile.open(tmp_path / "bench.db", read_only=read_only)
        run = db.run("big")
        assert run.steps == 60001
        np.testing.assert_array_equal(run.normal, normal)
        np.testing.assert_array_equal(run.shear, shear)
        np.testing.assert_array_equal(run.pose, table[["x", "y", "theta"]].to_numpy())
        np.testing.assert_array_equal(run.command, table[["v", "omega"]].to_numpy())
        np.testing.assert_array_equal(run.blocked, table["blocked"].to_numpy() != 0)
        np.testing.assert_array_equal(np.array(tactile.CLASSES)[run.truth], truth)
        db.close()


def test_runs_lists_every_run(demo):
    runs = tactile.open(demo / "demo.db").runs()
    assert isinstance(runs, pd.DataFrame)
    assert sorted(runs["name"]) == ["ch5_0000", "ch5_0001", "room1_0000", "room1_0001",
                                    "room1_0002"]
    assert set(runs["scene"]) == {"room1", "chapter5"}
    assert (runs["steps"] == 400).all()
    assert all(sets == ["truth"] for sets in runs["label_sets"])


def test_missing_database_raises_oserror(tmp_path):
    missing = tmp_path / "nowhere" / "missing.db"
    with pytest.raises(OSError) as caught:
        tactile.open(missing)
    assert caught.value.errno == errno.ENOENT
    assert caught.value.filename == str(missing)
    assert not missing.exists()


def test_not_a_database_raises_oserror_with_the_path(tmp_path):
    bogus = tmp_path / "bogus.db"
    bogus.write_text("this is not SQLite\n")
    with pytest.raises(OSError) as caught:
        tactile.open(bogus)
    assert caught.value.filename == str(bogus)
    assert bogus.read_text() == "this is not SQLite\n"


def test_unknown_run_raises_valueerror(demo):
    with pytest.raises(ValueError, match="no_such_run"):
        tactile.open(demo / "demo.db").run("no_such_run")


def test_bad_model_file_raises_valueerror_with_file_and_line(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "tactile-model-bundle",\n "version": 2,\n "models": [ }\n')
    with pytest.raises(ValueError, match=r"bad\.json:3"):
        tactile.load_model(bad)
    with pytest.raises(OSError):
        tactile.load_model(tmp_path / "absent.json")


def test_labels_are_the_truth_after_autolabel(demo):
    db = tactile.open(demo / "demo.db")
    labels = db.labels("truth", "ch5_0000")
    run = db.run("ch5_0000")
    for g, group in enumerate(tactile.GROUPS):
        np.testing.assert_array_equal(labels["classes"][group], run.truth[:, g])
    segments = labels["segments"]
    assert set(segments["annotator"]) == {"truth"}
    assert segments["last_step"].max() == 399


def test_set_labels_writes_through_the_workbench_edits(db_copy):
    path = db_copy()
    db = tactile.open(path)
    ids = db.set_labels("mine", "room1_0000", [("R", 10, 19, "Wall"), ("R", 15, 30, "Corner")],
                        annotator="ann")
    assert len(ids) == 2
    labels = db.labels("mine", "room1_0000")
    r = labels["classes"]["R"]
    assert (r[10:15] == 1).all() and (r[15:31] == 2).all()
    assert r[9] == -1 and r[31] == -1 and (labels["classes"]["F"] == -1).all()
    # Newest wins: the first segment was trimmed to 10-14.
    seg = labels["segments"].sort_values("first_step")
    assert list(seg["first_step"]) == [10, 15] and list(seg["last_step"]) == [14, 30]
    assert set(seg["annotator"]) == {"ann"}
    db.close()
    # Committed: another connection sees it.
    again = tactile.open(path).labels("mine", "room1_0000")
    assert (again["classes"]["R"][15:31] == 2).all()
    with pytest.raises(ValueError, match="Bump"):
        tactile.open(path).set_labels("mine", "room1_0000", group="R", first_step=0,
                                      last_step=1, cls="Bump")
