"""The turntable rig (simulated, replayed or USB): captures into sessions, live comparisons with the simulation, sessions as arrays."""

import os
import pathlib
from typing import Callable, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, os.PathLike[str]]
_Progress = Optional[Callable[[str, int, int], object]]

class Rig:
    """A rig as asked for; each capture or comparison opens it afresh."""

    @property
    def kind(self) -> str:
        """'simulated', 'replay' or 'usb'."""
    @property
    def tool(self) -> Optional[str]: ...
    @property
    def surface(self) -> Optional[str]: ...
    @property
    def load_N(self) -> float: ...
    @property
    def seed(self) -> int: ...
    @property
    def speedup(self) -> float:
        """1 = real time, k = k times faster, 0 = as fast as it computes."""
    @property
    def path(self) -> Optional[pathlib.Path]: ...
    @property
    def serial(self) -> Optional[str]: ...

def simulated(
    tool: str,
    surface: str,
    *,
    load: float = 2.2,
    seed: int = 1,
    speedup: float = 0.0,
    catalog: Optional[_Path] = None,
    stylus: Optional[_Path] = None,
    forcing: Optional[_Path] = None,
) -> Rig:
    """The simulated rig: a tool (catalog id or design point) on a surface, pressed with `load` N."""

def replay(path: _Path, *, speedup: float = 0.0) -> Rig:
    """A session folder (or a paper arm_*.csv recording) replayed as if live."""

def usb(
    *,
    serial: Optional[str] = None,
    input_api: Optional[str] = None,
    input_device: Optional[str] = None,
    input_channel: int = 1,
    accelerometer: float = 49.05,
    tool: Optional[str] = None,
    surface: Optional[str] = None,
    load: float = 2.2,
) -> Rig:
    """The USB rig controller; accelerometer in m/s^2 at full scale. A missing one is an OSError when opened."""

class RigSession:
    """A rig session: its streams (read-only views, float32) and what it says about them."""

    @property
    def folder(self) -> pathlib.Path: ...
    @property
    def complete(self) -> bool:
        """False for a .partial folder a killed capture left."""
    @property
    def warnings(self) -> list[str]: ...
    @property
    def tool(self) -> str: ...
    @property
    def surface(self) -> str: ...
    @property
    def normal_load_N(self) -> float: ...
    @property
    def acceleration_rate_hz(self) -> float: ...
    @property
    def speed_rate_hz(self) -> float: ...
    @property
    def force_rate_hz(self) -> float: ...
    @property
    def units(self) -> dict[str, str]: ...
    @property
    def accelerometer_m_s2_per_unit(self) -> float: ...
    @property
    def force_counts_per_N(self) -> float: ...
    @property
    def lever_factor(self) -> float: ...
    @property
    def speed_profile(self) -> str: ...
    @property
    def profile_time_s(self) -> npt.NDArray[np.float64]: ...
    @property
    def profile_speed_m_s(self) -> npt.NDArray[np.float64]: ...
    @property
    def notes(self) -> str: ...
    @property
    def created_utc(self) -> str: ...
    @property
    def capture(self) -> Optional[dict[str, Union[str, int, float]]]:
        """rig, seconds, frames, dropped_frames, saturated_frames, fault_frames, alignment_error_ms, ended_because."""
    @property
    def acceleration(self) -> npt.NDArray[np.float32]:
        """As recorded, in units['acceleration'] (a view)."""
    @property
    def acceleration_m_s2(self) -> npt.NDArray[np.float64]:
        """m/s^2 (a copy)."""
    @property
    def speed_m_s(self) -> npt.NDArray[np.float32]: ...
    @property
    def normal_force_N(self) -> npt.NDArray[np.float32]: ...
    @property
    def tangential_force_N(self) -> npt.NDArray[np.float32]: ...
    @property
    def frame_times_s(self) -> npt.NDArray[np.float64]:
        """Speed and force sample k at k / speed_rate_hz, s."""

def session(folder: _Path) -> RigSession:
    """Reads a session folder, or a .partial one up to its last block."""

class Comparison:
    """A capture compared per speed bin with the simulation driven by its measured speed."""

    @property
    def tool(self) -> str: ...
    @property
    def surface(self) -> str: ...
    @property
    def simulated(self) -> str: ...
    @property
    def simulated_modes(self) -> str: ...
    @property
    def session(self) -> RigSession: ...
    @property
    def bins(self) -> list[dict[str, float]]:
        """comparison.json's bins: speeds in m/s, lsd_db in dB, NaN where a bin has no rows."""
    @property
    def min_speed_m_s(self) -> npt.NDArray[np.float64]: ...
    @property
    def max_speed_m_s(self) -> npt.NDArray[np.float64]: ...
    @property
    def mean_speed_m_s(self) -> npt.NDArray[np.float64]: ...
    @property
    def rows(self) -> npt.NDArray[np.uint64]:
        """Spectrogram rows in each bin."""
    @property
    def lsd_db(self) -> npt.NDArray[np.float64]: ...
    @property
    def measured_weighted_mean(self) -> npt.NDArray[np.float64]: ...
    @property
    def simulated_weighted_mean(self) -> npt.NDArray[np.float64]: ...
    @property
    def weighted_mean_log10_difference(self) -> npt.NDArray[np.float64]: ...
    @property
    def mean_lsd_db(self) -> float: ...
    @property
    def mean_weighted_mean_log10_difference(self) -> float: ...
    @property
    def bins_with_rows(self) -> int: ...
    @property
    def rows_analysed(self) -> int: ...
    @property
    def rows_outside_speed_range(self) -> int: ...
    @property
    def rows_without_speed(self) -> int: ...
    @property
    def blocks_dropped(self) -> int: ...
    @property
    def band_hz(self) -> Tuple[float, float]: ...
    @property
    def frequencies_hz(self) -> npt.NDArray[np.float64]: ...
    @property
    def measured_mean(self) -> npt.NDArray[np.float64]:
        """bins x frequencies, m/s^2."""
    @property
    def simulated_mean(self) -> npt.NDArray[np.float64]: ...
    @property
    def waterfall_times_s(self) -> npt.NDArray[np.float64]: ...
    @property
    def waterfall_speeds_m_s(self) -> npt.NDArray[np.float64]: ...
    @property
    def measured_db(self) -> npt.NDArray[np.float32]:
        """rows x frequencies, dB re 1 m/s^2 (a view)."""
    @property
    def simulated_db(self) -> npt.NDArray[np.float32]: ...
    def save(self, path: _Path) -> None:
        """Writes comparison.json atomically."""

def capture(
    rig: Rig,
    folder: _Path,
    *,
    profile: Optional[_Path] = None,
    seconds: Optional[float] = None,
    notes: str = "",
    progress: _Progress = None,
) -> RigSession:
    """Records a session into `folder` as `nibrig rig capture`; Ctrl-C finishes it with what it holds."""

def compare(
    rig: Rig,
    tool: Optional[str],
    folder: _Path,
    *,
    surface: Optional[str] = None,
    profile: Optional[_Path] = None,
    seconds: Optional[float] = None,
    seed: int = 1,
    catalog: Optional[_Path] = None,
    stylus: Optional[_Path] = None,
    forcing: Optional[_Path] = None,
    progress: _Progress = None,
) -> Comparison:
    """Captures into `folder` while simulating `tool`, compared per speed bin as `nibrig rig compare`."""
