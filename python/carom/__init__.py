"""carom: exact continuous collision of moving balls in 2D.

The C++ library as a Python package: the time-of-impact queries (one pair, or NumPy arrays of
pairs), the World with its state as NumPy arrays, scenes, the hard-disk science (gas, eos) and
GSD trajectories (carom.gsd). Errors are carom.InvalidArgument and carom.SceneError, both
ValueErrors. docs/python.md is the guide.
"""

from ._carom import *  # noqa: F401,F403 (the module's names are the package's)
from ._carom import IMMOVABLE, InvalidArgument, Scene, SceneError, World  # noqa: F401
from . import gsd  # noqa: F401 (GSD trajectories; gsd.hoomd is imported when used)

__all__ = [name for name in dir() if not name.startswith("_")]
