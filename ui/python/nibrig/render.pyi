import os
from typing import Callable, Optional, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, os.PathLike[str]]

class Rendering:
    @property
    def samples(self) -> npt.NDArray[np.float32]: ...
    @property
    def rate_hz(self) -> float: ...
    @property
    def tool(self) -> str: ...
    @property
    def stroke(self) -> str: ...
    def __len__(self) -> int: ...

def tool(
    tool: str,
    surface: str,
    *,
    speed: Optional[float] = None,
    trajectory: Optional[_Path] = None,
    force: Optional[float] = None,
    seconds: Optional[float] = None,
    rate_hz: float = 48000.0,
    period: int = 64,
    seed: int = 1,
    catalog: Optional[_Path] = None,
    stylus: Optional[_Path] = None,
    forcing: Optional[_Path] = None,
    progress: Optional[Callable[[str, int, int], object]] = None,
) -> Rendering: ...
