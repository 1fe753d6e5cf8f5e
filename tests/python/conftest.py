"""Shared fixtures of the Python module's tests: the CLI, and a small database made with it
(simulated runs in two scenes, imported, their truth as the label set `truth`), as the shell
tests under tests/app make theirs."""
import os
import shutil
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("TACTILE_CLI")
    assert path and os.access(path, os.X_OK), "TACTILE_CLI must name the built tactile program"
    return path


def run_cli(cli, *args, cwd=None):
    done = subprocess.run([cli, *args], cwd=cwd, capture_output=True, text=True)
    assert done.returncode == 0, "tactile %s: %s" % (" ".join(args), done.stderr)
    return done.stdout


@pytest.fixture(scope="session")
def demo(cli, tmp_path_factory):
    """A folder with the run files (b1/room1_000N.csv, b2/ch5_000N.csv) and demo.db."""
    root = tmp_path_factory.mktemp("demo")
    run_cli(cli, "simulate", "--scene", "room1", "--runs", "3", "--steps", "400", "--out-dir",
            "b1", "--prefix", "room1", "--quiet", cwd=root)
    run_cli(cli, "simulate", "--scene", "chapter5", "--runs", "2", "--steps", "400",
            "--out-dir", "b2", "--prefix", "ch5", "--quiet", cwd=root)
    run_cli(cli, "import", "--db", "demo.db", "b1", "b2", cwd=root)
    run_cli(cli, "autolabel", "--db", "demo.db", "--all", "--set", "truth", cwd=root)
    return root


@pytest.fixture
def db_copy(demo, tmp_path):
    """A private copy of the demo database (for tests that write)."""
    def copy(name="copy.db"):
        target = tmp_path / name
        shutil.copy(demo / "demo.db", target)
        return target
    return copy
