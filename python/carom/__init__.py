"""carom: exact continuous collision of moving balls in 2D.

The C++ library as a Python package: the time-of-impact queries (one pair, or NumPy arrays of
pairs), the World with its state as NumPy arrays, scenes, and the hard-disk science. Errors are
carom.InvalidArgument and carom.SceneError, both ValueErrors. docs/python.md is the guide.
"""

from ._carom import *  # noqa: F401,F403 (the module's names are the package's)
from ._carom import IMMOVABLE, InvalidArgument, SceneError, World  # noqa: F401

__all__ = [name for name in dir() if not name.startswith("_")]
