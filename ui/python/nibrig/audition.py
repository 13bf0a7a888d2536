"""Tools played live on an audio device (as `nibrig audition`): speed and force set as they play."""

from ._core import audition as _audition

Player = _audition.Player
devices = _audition.devices

__all__ = ["Player", "devices"]
