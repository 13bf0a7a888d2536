"""Perceptual spaces (Sec. 4 of the paper): fit from triplet judgments, predict, place tools."""

from ._core import space as _space

Space = _space.Space
Placement = _space.Placement
fit = _space.fit
load = _space.load
default = _space.default

__all__ = ["Space", "Placement", "fit", "load", "default"]
