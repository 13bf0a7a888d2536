"""Perceptual spaces (Sec. 4 of the paper): fit from triplet judgments, predict, evaluate,
validate, place tools."""

from ._core import space as _space

Judgments = _space.Judgments
read_judgments = _space.read_judgments
Space = _space.Space
Placement = _space.Placement
fit = _space.fit
load = _space.load
default = _space.default
Evaluation = _space.Evaluation
Validation = _space.Validation
validate = _space.validate

__all__ = [
    "Judgments", "read_judgments", "Space", "Placement", "fit", "load", "default", "Evaluation", "Validation",
    "validate",
]
