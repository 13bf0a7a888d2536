"""Triplet studies with people (Sec. 4.2, 6.1): a study folder's answers and its report."""

import os
import pathlib
from typing import Any, Callable, Optional, Union

import numpy as np
import numpy.typing as npt

from .space import Space

_Path = Union[str, os.PathLike[str]]

class Answers:
    """A study's answers: every participant's log, practice included (copies)."""

    @property
    def folder(self) -> pathlib.Path: ...
    @property
    def stimuli(self) -> list[str]: ...
    @property
    def mode(self) -> str: ...
    @property
    def plan(self) -> str: ...
    @property
    def dims(self) -> int: ...
    @property
    def warnings(self) -> list[str]: ...
    @property
    def participants(self) -> list[dict[str, Any]]: ...
    @property
    def records(self) -> list[dict[str, Any]]:
        """participant, trial, practice, stage, reference, left, right, chosen, chosen_stimulus, response_s (s), plays, answered_utc."""
    @property
    def participant(self) -> list[str]: ...
    @property
    def trial(self) -> npt.NDArray[np.int64]: ...
    @property
    def practice(self) -> npt.NDArray[np.bool_]: ...
    @property
    def stage(self) -> npt.NDArray[np.int64]: ...
    @property
    def reference(self) -> npt.NDArray[np.int64]:
        """Indices into stimuli."""
    @property
    def left(self) -> npt.NDArray[np.int64]: ...
    @property
    def right(self) -> npt.NDArray[np.int64]: ...
    @property
    def chose_left(self) -> npt.NDArray[np.bool_]: ...
    @property
    def response_s(self) -> npt.NDArray[np.float64]:
        """s from each trial's start to its answer."""
    def __len__(self) -> int: ...

def answers(folder: _Path) -> Answers: ...

class Report:
    """A study's report, as `nibrig experiment report` gives and writes it."""

    @property
    def folder(self) -> pathlib.Path: ...
    @property
    def mode(self) -> str: ...
    @property
    def plan(self) -> str: ...
    @property
    def stimuli(self) -> list[str]: ...
    @property
    def selection(self) -> str: ...
    @property
    def triplets(self) -> int: ...
    @property
    def responses(self) -> int: ...
    @property
    def judgments_file(self) -> pathlib.Path: ...
    @property
    def space(self) -> Optional[Space]: ...
    @property
    def with_descriptors(self) -> bool: ...
    @property
    def mean_region_sd(self) -> Optional[float]: ...
    @property
    def participants(self) -> list[dict[str, Any]]:
        """id, respondent, answers, practice, median_response_s, agreement_with_space, agreement_with_others."""
    @property
    def validation(self) -> Optional[dict[str, Any]]: ...
    @property
    def warnings(self) -> list[str]: ...

def report(
    folder: _Path,
    *,
    output: Optional[_Path] = None,
    all_judgments: bool = False,
    space: Optional[_Path] = None,
    catalog: Optional[_Path] = None,
    bootstrap: int = 200,
    starts: int = 16,
    seed: int = 1,
    threads: int = 0,
    progress: Optional[Callable[[str, int, int], object]] = None,
) -> Report:
    """Reports a study as `nibrig experiment report` does, writing into `output` (default <folder>/report)."""
