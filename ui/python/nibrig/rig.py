"""The turntable rig (simulated, replayed or USB): captures into sessions, live comparisons with the simulation, sessions as arrays."""

from ._core import rig as _rig

Rig = _rig.Rig
RigSession = _rig.RigSession
Comparison = _rig.Comparison
simulated = _rig.simulated
replay = _rig.replay
usb = _rig.usb
capture = _rig.capture
compare = _rig.compare
session = _rig.session

__all__ = ["Rig", "RigSession", "Comparison", "simulated", "replay", "usb", "capture", "compare", "session"]
