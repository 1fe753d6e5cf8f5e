"""scikit-learn estimators over the product's classifier engine: one Gaussian mixture (or one
Gaussian) per class, fitted by the same core call as `tactile fit`, predicting the class with the
largest log-likelihood plus log prior. They work in pipelines, cross_val_score and GridSearchCV.
"""

import numbers

import numpy as np
from sklearn.base import BaseEstimator, ClassifierMixin
from sklearn.utils.multiclass import check_classification_targets
from sklearn.utils import assert_all_finite, check_consistent_length, column_or_1d
from sklearn.utils.validation import check_is_fitted

from . import _core

__all__ = ["GmmClassifier", "GaussianClassifier"]


def _seed(random_state):
    """The core's seed: an int as it is, None as the product's default seed 1, a RandomState's
    next draw."""
    if random_state is None:
        return 1
    if isinstance(random_state, numbers.Integral):
        if random_state < 0:
            raise ValueError("random_state must be >= 0, got %d" % random_state)
        return int(random_state)
    if isinstance(random_state, np.random.RandomState):
        return int(random_state.randint(np.iinfo(np.int32).max))
    raise ValueError("random_state must be None, an int or a numpy RandomState, got %r"
                     % (random_state,))


def _jobs(n_jobs):
    if n_jobs is None:
        return 1
    n_jobs = int(n_jobs)
    return 0 if n_jobs < 0 else n_jobs  # -1: all cores (the core's 0)


def _classes(y):
    """The sorted classes of y (scikit-learn's classes_, numpy's unique) and each row's index
    into them. The core numbers the labels in one pass (by hash for objects, by value otherwise),
    and only the distinct ones are sorted; floating-point labels are sorted whole by numpy."""
    found = _core.label_codes(y)
    if found is None:
        return np.unique(y, return_inverse=True)
    first, codes = found
    classes, order = np.unique(y[first], return_inverse=True)
    return classes, order[codes]


class _CoreClassifier(ClassifierMixin, BaseEstimator):
    """Shared fit and predict; subclasses give the core's options."""

    def _options(self):  # pragma: no cover - abstract
        raise NotImplementedError

    def fit(self, X, y):
        """Fits one model per class of y on that class's rows of X."""
        if y is None:
            self._validate_data(X, y)  # scikit-learn's error for an estimator that needs y
        # X as given when it is float64 already (C or Fortran order): the core splits its rows by
        # class in one pass, as `tactile fit` does.
        X = self._validate_data(X, dtype=np.float64)
        # y as scikit-learn's check_X_y takes it, but without its pass over object labels looking
        # for NaN: the core's numbering of the labels refuses None and NaN.
        y = column_or_1d(y, warn=True)
        check_consistent_length(X, y)
        if y.dtype.kind == "c":
            raise ValueError("Complex data not supported\n{}\n".format(y))
        if y.dtype.kind == "f":
            assert_all_finite(y, input_name="y")
        self.classes_, codes = _classes(y)
        # scikit-learn's target check on the distinct labels: the same verdict (and error) as on
        # every label, without sorting them all again.
        check_classification_targets(self.classes_)
        n_samples, n_features = X.shape
        if n_samples < 2:
            raise ValueError("n_samples=%d: at least 2 samples are needed to fit" % n_samples)
        names = [str(c) for c in self.classes_]
        try:
            self._model = _core.fit_classifier(X, codes, names, self._options())
        except ValueError as e:
            raise ValueError("%s (n_samples=%d, n_features=%d, %d class(es))"
                             % (e, n_samples, n_features, len(self.classes_))) from None
        self.n_iter_ = max(self._model.iterations)
        self.converged_ = bool(all(self._model.converged))
        self.fit_seconds_ = self._model.fit_seconds
        return self

    def _checked(self, X):
        check_is_fitted(self, "classes_")
        return self._validate_data(X, dtype=np.float64, order="F", reset=False)

    def log_likelihoods(self, X):
        """log p(x | class) for every row and class: n_samples x n_classes."""
        X = self._checked(X)
        return np.asarray(self._model.log_likelihoods(X))

    def predict(self, X):
        """The class with the largest log-likelihood plus log prior (the core's argmax)."""
        X = self._checked(X)
        codes = np.asarray(self._model.predict(X))
        return self.classes_[codes]

    def predict_log_proba(self, X):
        joint = self.log_likelihoods(X) + np.asarray(self._model.log_priors)[None, :]
        top = np.max(joint, axis=1, keepdims=True)
        # Rows where no class has any density: no class is preferred.
        nowhere = ~np.isfinite(top[:, 0])
        top[nowhere] = 0.0
        joint[nowhere] = 0.0
        shifted = joint - top
        return shifted - np.log(np.sum(np.exp(shifted), axis=1, keepdims=True))

    def predict_proba(self, X):
        """P(class | x) from the log-likelihoods and the class priors."""
        return np.exp(self.predict_log_proba(X))

    def _more_tags(self):
        return {"requires_y": True}


class GmmClassifier(_CoreClassifier):
    """One Gaussian mixture per class (the product's GMM classifier, `tactile fit --method gmm`).

    Parameters as scikit-learn's GaussianMixture where they mean the same:
    n_components (the model order), covariance_type ("nodal-full" or "full", "nodal-diag" or
    "diag", "grand-full" or "tied", "grand-diag"), max_iter, tol, random_state, n_init
    (restarts, best kept), init_params ("kmeans++" or "random-from-data"); and the product's own:
    variance_floor (a clamp on variances, or added to the diagonal with reg="add", as
    scikit-learn's reg_covar), tol_rule ("relative" or "absolute", scikit-learn's), priors
    ("equal" or "empirical"), kmeans_iter, n_jobs (threads; results do not depend on it)."""

    def __init__(self, n_components=16, covariance_type="nodal-diag", max_iter=100, tol=1e-3,
                 random_state=None, n_init=1, init_params="kmeans++", variance_floor=0.01,
                 reg="floor", tol_rule="relative", priors="equal", kmeans_iter=10, n_jobs=None):
        self.n_components = n_components
        self.covariance_type = covariance_type
        self.max_iter = max_iter
        self.tol = tol
        self.random_state = random_state
        self.n_init = n_init
        self.init_params = init_params
        self.variance_floor = variance_floor
        self.reg = reg
        self.tol_rule = tol_rule
        self.priors = priors
        self.kmeans_iter = kmeans_iter
        self.n_jobs = n_jobs

    def _options(self):
        return _core.classifier_options(
            "gmm", int(self.n_components), str(self.covariance_type),
            float(self.variance_floor), str(self.reg), str(self.init_params),
            _seed(self.random_state), int(self.n_init), int(self.max_iter), float(self.tol),
            str(self.tol_rule), int(self.kmeans_iter), str(self.priors), _jobs(self.n_jobs))


class GaussianClassifier(_CoreClassifier):
    """One Gaussian per class with the unbiased covariance (the product's Gaussian classifier,
    `tactile fit --method gaussian`). variance_floor clamps the covariance's eigenvalues (or is
    added to its diagonal with reg="add"); 0 leaves it as estimated."""

    def __init__(self, variance_floor=0.01, reg="floor", priors="equal"):
        self.variance_floor = variance_floor
        self.reg = reg
        self.priors = priors

    def _options(self):
        return _core.classifier_options(
            "gaussian", 1, "nodal-full", float(self.variance_floor), str(self.reg), "kmeans++",
            1, 1, 100, 1e-3, "relative", 10, str(self.priors), 1)
