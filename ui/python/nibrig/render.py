"""Tools rendered offline through the real-time engine into numpy arrays (as `nibrig render`)."""

from ._core import render as _render

Rendering = _render.Rendering
tool = _render.tool

__all__ = ["Rendering", "tool"]
