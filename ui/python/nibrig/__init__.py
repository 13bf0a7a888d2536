"""nibrig from Python: the library calls of the command line and the panel, for scripts and notebooks.

Each area is a submodule: ``nibrig.space`` fits perceptual spaces from triplet judgments, predicts
judgments and places tools. Arrays are numpy's; where the library can lend its memory, they are
views of it, read-only.
"""

from . import space

__all__ = ["space"]
