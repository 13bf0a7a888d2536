from . import space as space
