from . import design as design
from . import measure as measure
from . import space as space
