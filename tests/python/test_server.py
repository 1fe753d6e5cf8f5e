"""A PostgreSQL database opens in Python as a file does (the test server that ctest starts)."""
import os
import random
import subprocess

import numpy as np
import pytest

import tactile
from conftest import run_cli


@pytest.fixture
def server_copy(cli, demo):
    """The demo database copied into a fresh schema of the test server, and its address."""
    state = os.environ.get("TACTILE_TEST_PG_FILE")
    if not state or not os.path.exists(state):
        pytest.skip("no PostgreSQL test server (ctest starts one)")
    with open(state) as f:
        server = f.readline().strip()
    schema = "py%d_%d" % (os.getpid(), random.randrange(1 << 30))
    subprocess.run(["psql", "-q", "-v", "ON_ERROR_STOP=1", server, "-c", "CREATE SCHEMA " + schema],
                   check=True, capture_output=True)
    address = server + "&options=-csearch_path%3D" + schema
    run_cli(cli, "db", "create", "--db", address)
    run_cli(cli, "db", "copy", "--from", str(demo / "demo.db"), "--to", address)
    return address


def test_a_server_database_gives_the_same_runs_arrays_and_labels(demo, server_copy):
    on_file = tactile.open(str(demo / "demo.db"), read_only=True)
    on_server = tactile.open(server_copy, read_only=True)
    assert list(on_server.runs()["name"]) == list(on_file.runs()["name"])
    for name in on_file.runs()["name"]:
        a, b = on_file.run(name), on_server.run(name)
        np.testing.assert_array_equal(a.normal, b.normal)
        np.testing.assert_array_equal(a.shear, b.shear)
        np.testing.assert_array_equal(a.pose, b.pose)
        np.testing.assert_array_equal(a.truth, b.truth)
        la, lb = on_file.labels("truth", name), on_server.labels("truth", name)
        for group in tactile.GROUPS:
            np.testing.assert_array_equal(la["classes"][group], lb["classes"][group])


def test_a_password_in_an_address_never_shows(server_copy):
    with open(os.environ["TACTILE_TEST_PG_FILE"]) as f:
        f.readline()
        folder = f.readline().strip()
    with pytest.raises(OSError) as failed:
        tactile.open("postgresql://nobody:s3cret@/nodb?host=" + folder)
    assert "s3cret" not in str(failed.value)
    assert "***" in str(failed.value.filename)
