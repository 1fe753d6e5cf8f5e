"""Ctrl+C during a long fit raises KeyboardInterrupt, and the interpreter keeps working."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import tactile


def test_sigint_during_a_long_fit_raises_keyboardinterrupt():
    rng = np.random.default_rng(1)
    X = rng.normal(size=(60000, 8))
    y = rng.integers(0, 3, size=60000)
    # Order 64, full covariances, 1000 iterations with no tolerance: minutes of work.
    clf = tactile.GmmClassifier(n_components=64, covariance_type="full", max_iter=1000, tol=0.0,
                                n_jobs=1)
    timer = threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT))
    started = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            clf.fit(X, y)
    finally:
        timer.cancel()
    elapsed = time.monotonic() - started
    assert 0.9 < elapsed < 20.0, elapsed
    assert not hasattr(clf, "classes_") or not hasattr(clf, "_model")
    # The module still works after the interruption.
    small = tactile.GmmClassifier(n_components=2).fit(X[:3000], y[:3000])
    assert small.predict(X[:10]).shape == (10,)


def test_the_gil_is_released_during_a_fit():
    rng = np.random.default_rng(2)
    X = rng.normal(size=(40000, 8))
    y = rng.integers(0, 2, size=40000)
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.01)

    thread = threading.Thread(target=tick)
    clf = tactile.GmmClassifier(n_components=32, covariance_type="full", max_iter=30, tol=0.0,
                                n_jobs=1)
    started = time.monotonic()
    thread.start()
    clf.fit(X, y)
    took = time.monotonic() - started
    stop.set()
    thread.join()
    # Python kept running beside the fit: ticks all through it.
    assert took > 0.3, took
    assert len(ticks) > 0.5 * took / 0.01
