"""Recordings to friction, velocity-binned spectra and perceptual descriptors (Sec. 3, 4.4); catalogs."""

import os
from typing import Callable, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, os.PathLike[str]]

class Measurement:
    """One recording's physical descriptors; the parts its kind has (others raise ValueError)."""

    @property
    def kind(self) -> str: ...
    @property
    def tool(self) -> str: ...
    @property
    def surface(self) -> str: ...
    @property
    def warnings(self) -> list[str]: ...
    @property
    def mu(self) -> float:
        """Coulomb coefficient (dimensionless)."""
    @property
    def mu_interval(self) -> Tuple[float, float]:
        """mu's 95 % confidence interval."""
    @property
    def normal_load_N(self) -> float: ...
    @property
    def frequencies_hz(self) -> npt.NDArray[np.float64]: ...
    @property
    def speeds_m_s(self) -> npt.NDArray[np.float64]: ...
    @property
    def amplitude(self) -> npt.NDArray[np.float64]:
        """speeds x frequencies, m/s^2."""
    @property
    def weighted_mean(self) -> float:
        """Mean of the threshold-weighted spectrum (dimensionless)."""
    @property
    def weighted_power(self) -> float:
        """Hz."""
    @property
    def band_energies(self) -> dict[int, list[float]]: ...
    def to_json(self) -> str:
        """What `nibrig measure` writes."""

class Catalog:
    @property
    def tools(self) -> list[str]: ...
    @property
    def surfaces(self) -> list[str]: ...
    @property
    def pairings(self) -> list[dict[str, Optional[Union[str, float]]]]: ...
    @property
    def skipped(self) -> list[str]: ...
    def save(self, path: _Path) -> None: ...

def recording(
    path: _Path,
    *,
    tool: Optional[str] = None,
    surface: Optional[str] = None,
    load: Optional[float] = None,
    lever: Optional[float] = None,
    threshold: Optional[_Path] = None,
) -> Measurement:
    """Measures one recording as `nibrig measure` does (load in N)."""

def catalog(
    folder: _Path,
    *,
    threshold: Optional[_Path] = None,
    threads: int = 0,
    progress: Optional[Callable[[str, int, int], object]] = None,
) -> Catalog:
    """Every recording under a folder measured into one catalog; Ctrl-C stops it."""

def load_catalog(path: _Path) -> Catalog: ...
def bundled_catalog() -> str: ...
