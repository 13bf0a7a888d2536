"""Predicted designs (Sec. 5.3), their place in a space, and the design searches (Sec. 6.2, 7)."""

from ._core import design as _design

Designer = _design.Designer
Prediction = _design.Prediction
Search = _design.Search
designer = _design.designer

__all__ = ["Designer", "Prediction", "Search", "designer"]
