"""The scikit-learn estimators: scikit-learn's own checks, model selection and pipelines."""
import warnings

import numpy as np
import pytest
from sklearn.datasets import load_iris, make_blobs
from sklearn.model_selection import GridSearchCV, cross_val_score
from sklearn.pipeline import make_pipeline
from sklearn.preprocessing import StandardScaler
from sklearn.utils.estimator_checks import check_estimator

import tactile


@pytest.mark.parametrize("estimator", [tactile.GmmClassifier(), tactile.GaussianClassifier()],
                         ids=["gmm", "gaussian"])
def test_check_estimator_passes(estimator):
    assert not estimator._get_tags().get("_xfail_checks")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        check_estimator(estimator)
    # Every check ran: none was skipped or declared as expected to fail.
    skipped = [str(w.message) for w in caught if type(w.message).__name__ == "SkipTestWarning"]
    assert skipped == []


@pytest.mark.parametrize("make", [tactile.GmmClassifier, tactile.GaussianClassifier],
                         ids=["gmm", "gaussian"])
def test_classes_with_fewer_samples_than_features_fit_on_the_floor(make):
    # 3 samples of a class over 10 features: fitted, its covariance held up by the variance
    # floor; every probability finite and the few samples predicted as their own class.
    rng = np.random.RandomState(4)
    X = np.vstack([rng.randn(60, 10), rng.randn(3, 10) + 4.0])
    y = np.array(["wall"] * 60 + ["corner"] * 3)
    clf = make().fit(X, y)
    proba = clf.predict_proba(X)
    assert np.isfinite(proba).all() and np.isfinite(clf.predict_log_proba(X)).all()
    np.testing.assert_allclose(proba.sum(axis=1), 1.0)
    assert list(clf.predict(X[60:])) == ["corner"] * 3
    # Without a floor the covariance would be singular: a clear error, not a NaN model.
    with pytest.raises(ValueError, match="variance floor"):
        make(variance_floor=0.0).fit(X, y)


def test_target_checks_keep_scikit_learns_errors():
    X = np.random.RandomState(0).randn(20, 3)
    with pytest.raises(ValueError, match="Unknown label type"):
        tactile.GmmClassifier().fit(X, np.linspace(0.0, 1.0, 20))
    with pytest.raises(ValueError, match="missing label"):
        tactile.GmmClassifier().fit(X, np.array(["a", None] * 10, dtype=object))


def _labels(values, dtype=None):
    """100 labels cycling through values, shuffled: none of them first in sorted order."""
    y = np.array(list(values) * (100 // len(values) + 1), dtype=dtype)[:100]
    return y[np.random.RandomState(3).permutation(100)]


@pytest.mark.parametrize("y", [
    _labels(["wall", "corner", "none", "dead"], dtype=object),
    np.array([str(v) for v in _labels(["wall", "corner", "none"])], dtype=object),  # new objects
    _labels(["wall", "corner", "none"]),  # fixed-width text
    _labels([b"wall", b"corner"]),
    _labels([7, -2, 11, 3]),
    _labels([200, 3, 17], dtype=np.uint8),
    _labels([True, False]),
    _labels([2.0, -1.0, 0.0]),
    np.repeat(_labels(["b", "c", "a"]), 2)[::2],  # strided
    _labels(["c%d" % (29 - i) for i in range(30)], dtype=object),  # more than the core caches
    _labels(["c%d" % (29 - i) for i in range(30)]),
], ids=["str", "new-str-objects", "unicode", "bytes", "int", "uint8", "bool", "float",
        "strided", "30-str", "30-unicode"])
def test_labels_are_numbered_in_scikit_learns_classes_order(y):
    # The core numbers the labels in the order they first appear; classes_ is numpy's sorted
    # unique (scikit-learn's), and each row's class index points at its own label: the training
    # rows, one well separated cluster per class, are predicted as their own labels.
    classes, codes = np.unique(y, return_inverse=True)
    X = np.random.RandomState(1).randn(len(y), 2) * 0.1 + codes[:, None] * 10.0
    clf = tactile.GaussianClassifier().fit(X, y)
    assert clf.classes_.dtype == classes.dtype
    np.testing.assert_array_equal(clf.classes_, classes)
    np.testing.assert_array_equal(clf.predict(X), y)


def test_nan_labels_are_refused():
    X = np.random.RandomState(0).randn(20, 3)
    with pytest.raises(ValueError, match="missing label"):
        tactile.GmmClassifier().fit(X, np.array(["a", float("nan")] * 10, dtype=object))
    with pytest.raises(ValueError, match="NaN"):
        tactile.GmmClassifier().fit(X, np.array([1.0, np.nan] * 10))


def test_fit_takes_any_layout_of_x():
    X, y = load_iris(return_X_y=True)
    a = tactile.GmmClassifier(n_components=2).fit(np.ascontiguousarray(X), y)
    b = tactile.GmmClassifier(n_components=2).fit(np.asfortranarray(X), y)
    c = tactile.GmmClassifier(n_components=2).fit(np.repeat(X, 2, axis=0)[::2], y)  # strided
    np.testing.assert_array_equal(a.predict_proba(X), b.predict_proba(X))
    np.testing.assert_array_equal(a.predict_proba(X), c.predict_proba(X))


def test_parameters_follow_gaussian_mixture():
    params = tactile.GmmClassifier().get_params()
    for name in ("n_components", "covariance_type", "max_iter", "tol", "random_state",
                 "n_init", "variance_floor"):
        assert name in params
    clf = tactile.GmmClassifier().set_params(n_components=3, covariance_type="tied")
    assert clf.n_components == 3 and clf.covariance_type == "tied"
    X, y = load_iris(return_X_y=True)
    with pytest.raises(ValueError, match="spherical"):
        tactile.GmmClassifier(covariance_type="spherical").fit(X, y)


def test_sklearn_names_are_the_products_forms():
    X, y = load_iris(return_X_y=True)
    for short, long in (("full", "nodal-full"), ("diag", "nodal-diag"), ("tied", "grand-full")):
        a = tactile.GmmClassifier(n_components=2, covariance_type=short).fit(X, y)
        b = tactile.GmmClassifier(n_components=2, covariance_type=long).fit(X, y)
        np.testing.assert_array_equal(a.predict_proba(X), b.predict_proba(X))


def test_model_selection_and_pipelines():
    X, y = load_iris(return_X_y=True)
    scores = cross_val_score(tactile.GmmClassifier(n_components=2), X, y, cv=3)
    assert scores.mean() > 0.85
    search = GridSearchCV(tactile.GmmClassifier(), {"n_components": [1, 2],
                                                    "covariance_type": ["diag", "full"]}, cv=3)
    search.fit(X, y)
    assert search.best_params_["n_components"] in (1, 2)
    assert search.best_score_ > 0.85
    pipe = make_pipeline(StandardScaler(), tactile.GaussianClassifier()).fit(X, y)
    assert pipe.score(X, y) > 0.9


def test_proba_agrees_with_predict_and_labels_keep_their_type():
    X, y = make_blobs(n_samples=600, centers=3, n_features=4, random_state=2)
    names = np.array(["wall", "corner", "dead"])[y]
    clf = tactile.GmmClassifier(n_components=2, covariance_type="full").fit(X, names)
    proba = clf.predict_proba(X)
    np.testing.assert_allclose(proba.sum(axis=1), 1.0)
    np.testing.assert_array_equal(clf.classes_[proba.argmax(axis=1)], clf.predict(X))
    assert clf.score(X, names) > 0.95
    assert clf.n_iter_ >= 1 and clf.fit_seconds_ >= 0
