"""Triplet studies with people (Sec. 4.2, 6.1): a study folder's answers and its report."""

from ._core import study as _study

Answers = _study.Answers
Report = _study.Report
answers = _study.answers
report = _study.report

__all__ = ["Answers", "Report", "answers", "report"]
