"""nibrig from Python: the library calls of the command line and the panel, for scripts and notebooks.

Each area is a submodule: ``nibrig.measure`` measures recordings and builds catalogs,
``nibrig.space`` fits perceptual spaces from triplet judgments, predicts judgments and places
tools, ``nibrig.design`` predicts designs and searches for the nearest one, ``nibrig.render``
renders a tool through the real-time engine into an array, ``nibrig.audition`` plays
one to three tools live on an audio device, ``nibrig.rig`` captures sessions on the
turntable rig (simulated, replayed or USB) and compares them with the simulation,
``nibrig.study`` reads a triplet study's answers and reports it. Arrays are numpy's;
where the library can lend its memory, they are views of it, read-only. The library's log goes
to Python's ``logging``, logger ``"nibrig"``.
"""

from . import audition, design, measure, render, rig, space, study
from ._core import __version__

__all__ = ["audition", "design", "measure", "render", "rig", "space", "study", "__version__"]
