"""`cmake --install` puts the package into the prefix's Python path, where it imports from."""
import os
import subprocess
import sys

import pytest


def test_installed_module_imports_from_the_prefix(tmp_path):
    build = os.environ["TACTILE_BUILD_DIR"]
    cmake = os.environ.get("CMAKE_COMMAND", "cmake")
    prefix = tmp_path / "prefix"
    # The module's own component: the same files a whole `cmake --install` puts there.
    done = subprocess.run([cmake, "--install", build, "--prefix", str(prefix), "--component",
                           "python"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    site = prefix / "lib" / ("python%d.%d" % sys.version_info[:2]) / "site-packages"
    assert (site / "tactile" / "__init__.py").is_file()
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(site)
    code = ("import tactile, numpy as np\n"
            "print(tactile.__file__)\n"
            "from sklearn.datasets import load_iris\n"
            "X, y = load_iris(return_X_y=True)\n"
            "print(tactile.GmmClassifier(n_components=2).fit(X, y).score(X, y))\n")
    ran = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=env,
                         capture_output=True, text=True)
    assert ran.returncode == 0, ran.stderr
    where, score = ran.stdout.split()
    assert where.startswith(str(site)), where
    assert float(score) > 0.9
