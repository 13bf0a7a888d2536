"""Perceptual spaces (Sec. 4 of the paper): fit from triplet judgments, predict, evaluate,
validate, place tools; and SpaceEstimator, the same fit as a scikit-learn estimator."""

import numpy as np

from ._core import space as _space

Judgments = _space.Judgments
read_judgments = _space.read_judgments
Space = _space.Space
Placement = _space.Placement
fit = _space.fit
load = _space.load
default = _space.default
Evaluation = _space.Evaluation
Validation = _space.Validation
validate = _space.validate
#: The judgment models fit's model= takes (with "auto", which picks among them).
MODELS = _space.MODELS


class SpaceEstimator:
    """A perceptual space fitted as a scikit-learn classifier of triplets.

    X is an (n, 3) integer array of stimulus indices, (reference, first candidate, second
    candidate); y holds 1 where the first candidate was judged closer to the reference and 0 where
    the second was (without y, each row is already (reference, the closer, the farther)). fit
    calls nibrig.space.fit with the parameters below; predict_proba gives the space's
    P(second), P(first) per triplet, the classes being 0 and 1; score is the share of answers
    predicted, as scikit-learn's classifiers score. So cross_val_score and GridSearchCV work on
    it, and it pickles with its fitted space.

    n_stimuli: how many stimuli the indices count (default: the largest index in X plus one); a
    stimulus that no training triplet holds has nothing to place it by.
    """

    _estimator_type = "classifier"
    _PARAMETERS = ("dims", "model", "lam", "starts", "seed", "n_stimuli", "threads")

    def __init__(self, dims=2, *, model="probit", lam=0.0, starts=16, seed=1, n_stimuli=None, threads=0):
        self.dims = dims
        self.model = model
        self.lam = lam
        self.starts = starts
        self.seed = seed
        self.n_stimuli = n_stimuli
        self.threads = threads

    def get_params(self, deep=True):
        """The constructor's parameters by name (scikit-learn's protocol)."""
        return {name: getattr(self, name) for name in self._PARAMETERS}

    def set_params(self, **params):
        """Sets constructor parameters by name; an unknown name raises ValueError naming it."""
        for name, value in params.items():
            if name not in self._PARAMETERS:
                raise ValueError(f"{name}: not a parameter of SpaceEstimator (it has {', '.join(self._PARAMETERS)})")
            setattr(self, name, value)
        return self

    def _judgments(self, X, y):
        triplets = np.asarray(X)
        if triplets.ndim != 2 or triplets.shape[1] != 3:
            raise ValueError(f"X: expected an (n, 3) array of stimulus indices, found shape {triplets.shape}")
        count = self.n_stimuli if self.n_stimuli is not None else int(triplets.max()) + 1
        stimuli = [str(k) for k in range(count)]
        if y is None:
            return Judgments(triplets, stimuli)
        return Judgments(triplets, stimuli, answers=np.asarray(y).astype(np.int64))

    def fit(self, X, y=None):
        """Fits the space to the triplets X and their answers y; returns self."""
        self.space_ = fit(self._judgments(X, y), self.dims, model=self.model, lam=self.lam, starts=self.starts,
                          seed=self.seed, threads=self.threads)
        self.embedding_ = np.array(self.space_.coordinates)
        self.classes_ = np.array([0, 1])
        self.n_features_in_ = 3
        return self

    def _fitted(self):
        if not hasattr(self, "space_"):
            raise AttributeError("this SpaceEstimator is not fitted yet: call fit(X, y) first")
        return self.space_

    def predict_proba(self, X):
        """(n, 2): P(the second candidate is judged closer), P(the first is), per triplet of X."""
        first = self._fitted().predict(np.asarray(X, dtype=np.int64))
        return np.column_stack([1.0 - first, first])

    def predict(self, X):
        """The answer the space makes likelier per triplet: 1 for the first candidate, 0 for the second."""
        return (self.predict_proba(X)[:, 1] >= 0.5).astype(np.int64)

    def score(self, X, y):
        """The share of the answers y that the space predicts (accuracy)."""
        return float(np.mean(self.predict(X) == np.asarray(y)))

    def __repr__(self):
        given = ", ".join(f"{k}={v!r}" for k, v in self.get_params().items())
        return f"SpaceEstimator({given})"


__all__ = [
    "Judgments", "read_judgments", "Space", "Placement", "fit", "load", "default", "Evaluation", "Validation",
    "validate", "MODELS", "SpaceEstimator",
]
