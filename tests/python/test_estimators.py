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
