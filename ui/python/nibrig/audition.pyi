"""Tools played live on an audio device (as `nibrig audition`): speed and force set as they play."""

import os
from types import TracebackType
from typing import Any, Callable, Dict, List, Optional, Sequence, Type, Union, overload

_Path = Union[str, os.PathLike[str]]

class Player:
    def __init__(
        self,
        api: Optional[str] = None,
        device: Optional[str] = None,
        *,
        channel: int = 1,
        rate: int = 0,
        period: int = 256,
        name: str = "nibrig-python",
        actuator: Optional[str] = None,
    ) -> None:
        """Opens a device by API ('jack', 'alsa', 'pulse') and name; rate in Hz (0: the device's)."""
    def play(
        self,
        tools: Sequence[str],
        surface: str,
        *,
        speed: Optional[float] = None,
        force: Optional[float] = None,
        trajectory: Optional[_Path] = None,
        sweep: bool = False,
        seed: int = 1,
        catalog: Optional[_Path] = None,
        stylus: Optional[_Path] = None,
        forcing: Optional[_Path] = None,
        progress: Optional[Callable[[str, int, int], object]] = None,
    ) -> None:
        """One to three tools into A, B, C; plays A. speed in m/s (default 0.1), force in N (default 2.2)."""
    @property
    def speed(self) -> Optional[float]:
        """The live contact's speed, m/s."""
    @speed.setter
    def speed(self, value: float) -> None: ...
    @property
    def force(self) -> float:
        """The live contact's normal force, N."""
    @force.setter
    def force(self, value: float) -> None: ...
    @property
    def stroke(self) -> str: ...
    @overload
    def select(self, slot: str) -> None:
        """'A', 'B' or 'C'."""
    @overload
    def select(self, slot: int) -> None:
        """0, 1 or 2."""
    @property
    def selected(self) -> str: ...
    @property
    def names(self) -> List[str]: ...
    def stop(self) -> None:
        """Silence: contact speed and force 0; the device stays open."""
    def close(self) -> None: ...
    @property
    def pending(self) -> int:
        """Commands held until the engine's queue takes them."""
    @property
    def status(self) -> str:
        """'running', 'lost' or 'closed'."""
    @property
    def problem(self) -> str: ...
    @property
    def stream(self) -> Dict[str, Any]:
        """api, device, rate_hz, period_frames, output_channels, latency_frames, actuator."""
    @property
    def stats(self) -> Dict[str, Any]:
        """callbacks, frames, underflows, losses, reconnects, engine_overruns, peak_output, ..."""
    def __enter__(self) -> "Player": ...
    def __exit__(
        self,
        exc_type: Optional[Type[BaseException]],
        exc: Optional[BaseException],
        tb: Optional[TracebackType],
    ) -> None: ...

def devices(api: Optional[str] = None) -> List[Dict[str, Any]]:
    """Every audio API compiled in with its devices: api, name, available, unavailable_reason, devices."""
