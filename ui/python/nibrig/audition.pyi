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
    ) -> None: ...
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
    ) -> None: ...
    @property
    def speed(self) -> Optional[float]: ...
    @speed.setter
    def speed(self, value: float) -> None: ...
    @property
    def force(self) -> float: ...
    @force.setter
    def force(self, value: float) -> None: ...
    @property
    def stroke(self) -> str: ...
    @overload
    def select(self, slot: str) -> None: ...
    @overload
    def select(self, slot: int) -> None: ...
    @property
    def selected(self) -> str: ...
    @property
    def names(self) -> List[str]: ...
    def stop(self) -> None: ...
    def close(self) -> None: ...
    @property
    def pending(self) -> int: ...
    @property
    def status(self) -> str: ...
    @property
    def problem(self) -> str: ...
    @property
    def stream(self) -> Dict[str, Any]: ...
    @property
    def stats(self) -> Dict[str, Any]: ...
    def __enter__(self) -> "Player": ...
    def __exit__(
        self,
        exc_type: Optional[Type[BaseException]],
        exc: Optional[BaseException],
        tb: Optional[TracebackType],
    ) -> None: ...

def devices(api: Optional[str] = None) -> List[Dict[str, Any]]: ...
