"""Predicted designs (Sec. 5.3), their place in a space, the design searches (Sec. 6.2, 7), and the loop from a print back to its target."""

import os
import pathlib
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

class Modes:
    @property
    def design(self) -> str: ...
    @property
    def frequencies_hz(self) -> list[float]:
        """Undamped, Hz, ascending."""
    @property
    def damping_ratios(self) -> npt.NDArray[np.float64]: ...
    @property
    def tip(self) -> npt.NDArray[np.float64]:
        """Mode shapes at the tip, kg^-1/2."""
    @property
    def sensor(self) -> npt.NDArray[np.float64]:
        """Mode shapes at the sensor, kg^-1/2."""
    @property
    def response_frequencies_hz(self) -> npt.NDArray[np.float64]: ...
    @property
    def response(self) -> npt.NDArray[np.float64]:
        """|H(f)| from tip force to sensor acceleration, (m/s^2)/N."""

class Forcing:
    @property
    def frequencies_hz(self) -> list[float]: ...
    @property
    def speeds_m_s(self) -> list[float]: ...
    @property
    def knot_frequencies_hz(self) -> list[float]: ...
    @property
    def surfaces(self) -> list[str]: ...
    @property
    def tips_mm(self) -> list[float]: ...
    @property
    def materials(self) -> list[str]: ...
    @property
    def reference(self) -> tuple[float, str]: ...
    def surface_forcing(self, surface: str) -> npt.NDArray[np.float64]:
        """F_S, speeds x frequencies, N."""
    def tip_gain_db(self, tip_mm: float) -> list[float]: ...
    def material_gain_db(self, material: str) -> list[float]: ...
    def predict(self, response: Sequence[float], surface: str, tip_mm: float, material: str) -> npt.NDArray[np.float64]:
        """Speeds x frequencies, m/s^2."""
    @property
    def residual_rms_db(self) -> float: ...
    @property
    def exemplar_fits(self) -> list[dict[str, Any]]: ...
    @property
    def notes(self) -> list[str]: ...

class Designer:
    def modes(self, design: str) -> Modes:
        """A design point's modes and frequency response (its FEM solve)."""
    @property
    def forcing(self) -> Forcing: ...
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

class Calibration:
    @property
    def name(self) -> str: ...
    @property
    def knot_frequencies_hz(self) -> list[float]: ...
    @property
    def gain_db(self) -> list[float]:
        """A material's 20 log10 m(f) at the knots (empty for a surface)."""
    @property
    def gain_se_db(self) -> list[float]: ...
    @property
    def rms_se_db(self) -> float: ...
    @property
    def prints(self) -> int: ...
    @property
    def exemplars(self) -> int: ...
    @property
    def degrees_of_freedom(self) -> float: ...
    @property
    def residual_rms_db(self) -> float: ...
    @property
    def fits(self) -> list[dict[str, Any]]: ...
    @property
    def predicted(self) -> list[dict[str, Any]]: ...
    def save(self, path: _Path) -> None: ...
    def keep(self, name: str, *, replace: bool = False) -> pathlib.Path:
        """Keeps the model by name in the lab's store; designer(forcing=name) finds it."""

def calibrate_material(
    material: str,
    *,
    forcing: _Path,
    tips_mm: Optional[Sequence[float]] = None,
    catalog: Optional[_Path] = None,
    modes: int = 0,
    mesh_size: float = 0.0,
    progress: Optional[Callable[[str, int, int], object]] = None,
) -> Calibration:
    """A new material's curve from its prints in the catalog, against a forcing model (a name or file)."""

def calibrate_surface(
    surface: str,
    *,
    forcing: _Path,
    tools: Optional[Sequence[str]] = None,
    catalog: Optional[_Path] = None,
    modes: int = 0,
    mesh_size: float = 0.0,
    progress: Optional[Callable[[str, int, int], object]] = None,
) -> Calibration:
    """A new surface's forcing from the tools measured on it in the catalog, against a forcing model."""

class CalibrationBar:
    """The ring-down bar written for a material on a printer."""
    @property
    def material(self) -> str: ...
    @property
    def printer(self) -> str: ...
    @property
    def length_mm(self) -> float: ...
    @property
    def volume_mm3(self) -> float: ...
    @property
    def three_mf(self) -> pathlib.Path: ...
    @property
    def stl(self) -> pathlib.Path: ...
    @property
    def ini(self) -> Optional[pathlib.Path]: ...
    @property
    def drawing(self) -> pathlib.Path: ...
    @property
    def instructions(self) -> pathlib.Path: ...
    @property
    def record(self) -> pathlib.Path: ...

class RingDownCalibration:
    """A material fitted to its bar's ring-down and saved among the lab's."""
    @property
    def name(self) -> str: ...
    @property
    def youngs_modulus_Pa(self) -> float: ...
    @property
    def youngs_modulus_sd_Pa(self) -> float: ...
    @property
    def rayleigh_stiffness_s(self) -> float: ...
    @property
    def rayleigh_stiffness_sd_s(self) -> float: ...
    @property
    def first_mode_hz(self) -> float: ...
    @property
    def first_mode_damping_ratio(self) -> float: ...
    @property
    def relative_residual(self) -> float: ...
    @property
    def fitted(self) -> npt.NDArray[np.float64]: ...
    @property
    def saved(self) -> pathlib.Path: ...

def calibration_bar(
    material: str,
    *,
    printer: str,
    folder: _Path,
    length_mm: Optional[float] = None,
    materials: Optional[_Path] = None,
) -> CalibrationBar:
    """Writes the ring-down bar of the paper's Sec. 5.1 in a material for a printer."""

def calibrate_ring_down(
    trace: _Path,
    *,
    bar: _Path,
    name: str,
    calibrated: bool = False,
    replace: bool = False,
    materials: Optional[_Path] = None,
) -> RingDownCalibration:
    """Fits the bar's ring-down for Young's modulus and Rayleigh damping and saves the material by name."""

class DesignLoop:
    @property
    def folder(self) -> pathlib.Path: ...
    @property
    def threshold(self) -> float: ...
    @property
    def rounds(self) -> list[dict[str, Any]]: ...
    @property
    def measured_distances(self) -> npt.NDArray[np.float64]: ...
    @property
    def stopped(self) -> Optional[str]: ...
    @property
    def awaiting(self) -> Optional[int]: ...

def loop(
    folder: _Path,
    *,
    target: Optional[str] = None,
    surface: Optional[str] = None,
    space: Optional[_Path] = None,
    resume: bool = False,
    rule: str = "likeliest",
    rounds: Optional[int] = None,
    mix: Tuple[str, str] = ("vero", "DM85"),
    catalog: Optional[_Path] = None,
    forcing: Optional[str] = None,
    printer: Optional[str] = None,
    simulated: bool = False,
    simulated_forcing: Optional[_Path] = None,
    seed: int = 1,
    seconds: Optional[float] = None,
    replay_prints: Optional[_Path] = None,
    progress: Optional[Callable[[str, int, int], object]] = None,
) -> DesignLoop:
    """The design loop of `nibrig design loop` in a folder, run as far as it goes here."""
