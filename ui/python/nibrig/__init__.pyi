from . import audition as audition
from . import design as design
from . import measure as measure
from . import render as render
from . import rig as rig
from . import space as space
from . import study as study

__version__: str
