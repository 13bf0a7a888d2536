"""Perceptual spaces (Sec. 4 of the paper): fit from triplet judgments, predict, place tools."""

import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, os.PathLike[str]]

class Judgments:
    """Triplet judgments read once, for several fits."""

    @property
    def stimuli(self) -> list[str]: ...
    @property
    def triplets(self) -> int: ...
    @property
    def responses(self) -> int: ...
    @property
    def file(self) -> str: ...

def read_judgments(path: _Path) -> Judgments: ...

class Placement:
    """A tool placed from its descriptors: a Gaussian position in the space."""

    @property
    def mean(self) -> npt.NDArray[np.float64]:
        """Its position, one value per axis, in the space's units (a read-only view)."""
    @property
    def covariance(self) -> npt.NDArray[np.float64]:
        """The position's covariance, axes x axes, in squared units (a read-only view)."""
    def ellipses(self, levels: Sequence[float] = ...) -> list[Tuple[float, float, float]]:
        """(semi_axis_1, semi_axis_2, angle in radians from axis 1) of the region in axes 1-2 per level."""

class Space:
    """A perceptual space fitted from triplet judgments."""

    @property
    def stimuli(self) -> list[str]: ...
    @property
    def dims(self) -> int: ...
    @property
    def coordinates(self) -> npt.NDArray[np.float64]:
        """dims x stimuli positions in the space's units (a read-only view)."""
    @property
    def model(self) -> str:
        """'probit', 'logistic' or 'student-t', with '+lapse' and '+noise'."""
    @property
    def model_description(self) -> str: ...
    @property
    def model_reason(self) -> str: ...
    @property
    def scale(self) -> float:
        """s in P = link(s * (d_b - d_a))."""
    @property
    def lapse(self) -> float: ...
    @property
    def lam(self) -> float: ...
    @property
    def negative_log_likelihood(self) -> float:
        """Of the judgments fitted, in nats."""
    @property
    def responses(self) -> int: ...
    @property
    def descriptor_names(self) -> list[str]: ...
    @property
    def has_descriptor_map(self) -> bool: ...
    @property
    def warnings(self) -> list[str]: ...
    def predict(self, triplets: Sequence[Tuple[str, str, str]]) -> npt.NDArray[np.float64]:
        """P(first candidate judged closer to the reference) for each (reference, first, second)."""
    def place(
        self,
        descriptors: Union[Mapping[str, float], Sequence[float]],
        error: Optional[npt.ArrayLike] = None,
    ) -> Placement:
        """Places a tool from its descriptors through the space's descriptor map."""
    def save(self, path: _Path) -> None:
        """Writes the space file atomically."""
    def evaluate(self, judgments: Union[_Path, Judgments], catalog: Optional[_Path] = None) -> Evaluation:
        """Its predictions of judged triplets scored against their answers (`nibrig space evaluate`)."""

class Evaluation:
    @property
    def triplets(self) -> int: ...
    @property
    def responses(self) -> int: ...
    @property
    def placed_from_descriptors(self) -> int: ...
    @property
    def majority_agreement(self) -> float:
        """Share of untied triplets whose majority answer is predicted."""
    @property
    def majority_trials(self) -> float: ...
    @property
    def majority_z(self) -> float: ...
    @property
    def majority_p_value(self) -> float: ...
    @property
    def individual_agreement(self) -> float: ...
    @property
    def mean_absolute_error(self) -> float:
        """Mean |p_predicted - p_observed| over triplets."""
    @property
    def log_loss(self) -> float:
        """Nats per response."""
    @property
    def pearson(self) -> Optional[Dict[str, float]]: ...
    @property
    def no_correlation_because(self) -> str: ...

class Validation:
    @property
    def triplets(self) -> int: ...
    @property
    def responses(self) -> int: ...
    @property
    def points(self) -> List[Dict[str, Any]]:
        """dims, lambda, model, mean_error, sd_error, majority_agreement, individual_agreement, log_loss."""
    @property
    def rank_correlation_with_names(self) -> Optional[Dict[str, float]]: ...

def validate(
    judgments: Union[_Path, Judgments],
    dims: Sequence[int] = (1, 2, 3),
    *,
    lambdas: Sequence[float] = (0.0,),
    models: Sequence[str] = ("probit",),
    folds: int = 5,
    starts: int = 8,
    seed: int = 1,
    descriptors: Optional[_Path] = None,
    threads: int = 0,
    progress: Optional[Callable[[str, int, int], object]] = None,
) -> Validation:
    """k-fold cross-validation per dims x lambda x model (`nibrig space validate`); Ctrl-C stops it."""

def fit(
    judgments: Union[_Path, Judgments],
    dims: int = 2,
    *,
    descriptors: Optional[_Path] = None,
    lam: float = 0.0,
    model: str = "probit",
    starts: int = 16,
    seed: int = 1,
    bootstrap: int = 0,
    threads: int = 0,
    progress: Optional[Callable[[str, int, int], object]] = None,
) -> Space:
    """Fits a space to triplet judgments as `nibrig space fit` does; Ctrl-C stops it."""

def load(path: _Path) -> Space:
    """Reads a space file (`nibrig space fit -o`)."""

def default(*, bootstrap: int = 200, progress: Optional[Callable[[str, int, int], object]] = None) -> Space:
    """The demo's and the panel's space: a SIMULATED observer's, with a descriptor map; cached."""
