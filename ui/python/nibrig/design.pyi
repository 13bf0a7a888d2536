"""Predicted designs (Sec. 5.3), their place in a space, and the design searches (Sec. 6.2, 7)."""

import os
from typing import Any, Callable, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from .space import Placement, Space

_Path = Union[str, os.PathLike[str]]
_Target = Union[str, Placement]

class Prediction:
    @property
    def design(self) -> str: ...
    @property
    def surface(self) -> str: ...
    @property
    def mu(self) -> float: ...
    @property
    def first_mode_hz(self) -> float: ...
    @property
    def mode_frequencies_hz(self) -> list[float]: ...
    @property
    def frequencies_hz(self) -> list[float]: ...
    @property
    def speeds_m_s(self) -> list[float]: ...
    @property
    def amplitude(self) -> npt.NDArray[np.float64]:
        """speeds x frequencies, m/s^2."""
    @property
    def weighted_mean(self) -> float: ...
    def place(self, space: Space) -> Placement: ...

class Search:
    @property
    def optimum(self) -> dict[str, Any]: ...
    @property
    def path(self) -> list[dict[str, Any]]: ...
    def runners_up(self, count: int = 4) -> list[dict[str, Any]]: ...

class Designer:
    def predict(self, design: str, surface: str) -> Prediction:
        """A design point such as 'DM85:0.5,vero:0.5,tip=2mm' on a surface."""
    def search(
        self,
        space: Space,
        targets: Union[_Target, Sequence[_Target]],
        surface: str,
        *,
        between: Optional[Tuple[str, str]] = None,
        aim: str = "largest",
        min_tip_mm: Optional[float] = None,
        max_tip_mm: Optional[float] = None,
        allow: Sequence[str] = ...,
        cost: Mapping[str, float] = ...,
        max_cost: Optional[float] = None,
        mix_a: str = "vero",
        mix_b: str = "DM85",
        progress: Optional[Callable[[str, int, int], object]] = None,
    ) -> Search: ...

def designer(
    *,
    catalog: Optional[_Path] = None,
    forcing: Optional[_Path] = None,
    template: Optional[_Path] = None,
    materials: Optional[_Path] = None,
    modes: int = 0,
    mesh_size: float = 0.0,
    progress: Optional[Callable[[str, int, int], object]] = None,
) -> Designer:
    """Reads what predicting needs; mesh_size in m, 0: the template's."""
